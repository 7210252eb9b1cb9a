// The `cbbg` Python module's C++ half (_cbbg); python/cbbg/__init__.py re-exports it.

#include <pybind11/pybind11.h>

#include "bindings.h"
#include "cbbg/config/config.h"
#include "cbbg/framework/simulator.h"
#include "python_block.h"

namespace py = pybind11;

PYBIND11_MODULE(_cbbg, m) {
  m.doc() = "cbbg: a Drake-style systems framework and the cerebellum-basal-ganglia controller";
  // The library's own errors keep their messages; other C++ exceptions map as pybind11's do
  // (std::invalid_argument: ValueError, std::logic_error and std::runtime_error: RuntimeError).
  py::register_exception<cbbg::config::ConfigError>(m, "ConfigError", PyExc_ValueError);
  py::register_exception<cbbg::SimulationError>(m, "SimulationError", PyExc_RuntimeError);
  py::register_exception<cbbg::python::BlockCallbackError>(m, "BlockError", PyExc_RuntimeError);

  cbbg::python::bind_framework(m);
  cbbg::python::bind_python_blocks(m);
  cbbg::python::bind_primitives(m);
  cbbg::python::bind_library_blocks(m);
  cbbg::python::bind_parameters(m);
  cbbg::python::bind_controller(m);
  cbbg::python::bind_protocols(m);
  cbbg::python::bind_environment(m);
  // Where the command line's plotting script and replay page are: the build tree's share/cbbg
  // for the module built there, the installed one for the installed module (cbbg.main).
  m.attr("_build_share_dir") = CBBG_BUILD_SHARE_DIR;
  m.attr("_install_share_dir") = CBBG_INSTALL_SHARE_DIR;
}
