// The `cbbg` Python module's C++ half (_cbbg); python/cbbg/__init__.py re-exports it.

#include <pybind11/pybind11.h>

#include "bindings.h"
#include "cbbg/config/config.h"
#include "cbbg/framework/interrupt.h"
#include "cbbg/framework/simulator.h"
#include "python_block.h"
#include "python_errors.h"

namespace py = pybind11;

namespace {

// cbbg.BlockError, for the translator (module lifetime: never released).
PyObject* block_error_type = nullptr;

// Tried before register_exception's (pybind11 tries the last registered first): a Python
// exception that crossed C++ as it is, a block's error raised from its cause.
void translate_python_errors(std::exception_ptr thrown) {
  try {
    if (thrown) std::rethrow_exception(thrown);
  } catch (const cbbg::python::PythonInterrupt& interrupt) {
    interrupt.restore();
  } catch (const cbbg::python::BlockCallbackError& error) {
    cbbg::python::raise_block_error(block_error_type, error);
  }
}

}  // namespace

PYBIND11_MODULE(_cbbg, m) {
  m.doc() = "cbbg: a Drake-style systems framework and the cerebellum-basal-ganglia controller";
  // The library's own errors keep their messages; other C++ exceptions map as pybind11's do
  // (std::invalid_argument: ValueError, std::logic_error and std::runtime_error: RuntimeError).
  py::register_exception<cbbg::config::ConfigError>(m, "ConfigError", PyExc_ValueError);
  py::register_exception<cbbg::SimulationError>(m, "SimulationError", PyExc_RuntimeError);
  block_error_type =
      py::register_exception<cbbg::python::BlockCallbackError>(m, "BlockError", PyExc_RuntimeError)
          .ptr();
  py::register_exception_translator(&translate_python_errors);
  // Ctrl-C during long C++ work: signals are handled between event instants.
  cbbg::python::python_main_thread() =
      py::module_::import("threading").attr("main_thread")().attr("ident").cast<unsigned long>();
  cbbg::set_interrupt_check(&cbbg::python::check_python_signals);

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
