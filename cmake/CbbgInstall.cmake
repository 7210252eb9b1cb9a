# Install rules and a CMake package: find_package(cbbg) gives every library as a target
# (cbbg::framework, codegen, plant, blocks, config, parameters, diagrams, records, experiments, environment, store,
# realtime, replay, and cli: the command line a user's program runs with its own registrations), the `cbbg`
# command, its plotting script and its replay page; find_package(cbbg COMPONENTS framework)
# gives the framework alone, needing Eigen only. Headers install under include/cbbg/ with
# their tree and are included as <cbbg/framework/...>, <cbbg/diagrams/...>, as the sources
# include them; plant/simbody/ is the plant library's own (its headers include Simbody) and
# stays out. The docs and the examples install under share/doc/cbbg/; the Python module
# (component python) where the Python it was built for finds it (python/CMakeLists.txt).
include(CMakePackageConfigHelpers)

set(CBBG_LIBRARIES cbbg_framework cbbg_codegen cbbg_plant cbbg_blocks cbbg_config cbbg_parameters cbbg_diagrams
                   cbbg_records cbbg_experiments cbbg_environment cbbg_store cbbg_realtime
                   cbbg_replay cbbg_cli)
install(TARGETS ${CBBG_LIBRARIES} EXPORT cbbgTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
foreach(folder ${CBBG_HEADER_FOLDERS})
  install(DIRECTORY ${folder}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/cbbg/${folder}
          FILES_MATCHING PATTERN "*.h" PATTERN "simbody" EXCLUDE PATTERN "node_modules" EXCLUDE)
endforeach()
# The command line's one public header (the rest are its own).
install(FILES apps/cli.h DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/cbbg/apps)
install(TARGETS cbbg RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The command finds its plotting script in share/cbbg/ beside its bin/.
install(PROGRAMS scripts/plot_results.py DESTINATION ${CMAKE_INSTALL_DATADIR}/cbbg)
# The robustness, teacher, ablation and baseline studies and their reports (docs/studies.md),
# what they share, and the variants' configs the teacher and ablation studies run.
install(PROGRAMS scripts/robustness_study.sh scripts/robustness_report.py
                 scripts/teacher_study.sh scripts/teacher_report.py
                 scripts/ablation_study.sh scripts/ablation_report.py
                 scripts/baseline_study.sh scripts/baseline_report.py
                 scripts/disturbance_search.sh scripts/disturbance_front.py
        DESTINATION ${CMAKE_INSTALL_DATADIR}/cbbg)
install(FILES scripts/study_kit.sh scripts/study_stats.py DESTINATION ${CMAKE_INSTALL_DATADIR}/cbbg)
install(DIRECTORY configs/ DESTINATION ${CMAKE_INSTALL_DATADIR}/cbbg/configs)
# The paper's two-wheeler as an MJCF model (plant.kind mujoco), to copy and change.
install(FILES plant/mujoco/two_wheeler.xml DESTINATION ${CMAKE_INSTALL_DATADIR}/cbbg/models)
# The Slurm batch scripts of a sweep (docs/sweeps.md).
install(PROGRAMS scripts/slurm/sweep.sbatch scripts/slurm/merge.sbatch scripts/slurm/submit_sweep.sh
        DESTINATION ${CMAKE_INSTALL_DATADIR}/cbbg/slurm)
# The documentation, and the examples as a user's project to start from.
install(FILES README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs PATTERN "CMakeLists.txt" EXCLUDE)
# The documentation site (guide and API reference), when the build made it (docs/CMakeLists.txt).
if(CBBG_WITH_DOCS)
  install(DIRECTORY ${CBBG_DOCS_HTML}/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/html)
endif()
install(DIRECTORY examples/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/examples)
install(DIRECTORY python/examples/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/examples/python
        PATTERN "__pycache__" EXCLUDE)
install(EXPORT cbbgTargets NAMESPACE cbbg:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/cbbg)

configure_package_config_file(cmake/cbbgConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/cbbgConfig.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/cbbg
  PATH_VARS CMAKE_INSTALL_BINDIR)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/cbbgConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/cbbgConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/cbbgConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/cbbg)
