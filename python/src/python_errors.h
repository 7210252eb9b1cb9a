#pragma once
// Python exceptions crossing C++. An Exception a Python callable raises is an error: the
// library reports it (BlockCallbackError, with the exception as its __cause__) or lets it
// through as it is (a factory's). A BaseException that is not an Exception (KeyboardInterrupt,
// SystemExit) is no error but a request to stop: it crosses C++ as a PythonInterrupt, which no
// `catch (const std::exception&)` stops (the command line's, a protocol's), stops the other
// threads of a parallel run (cbbg::throw_interrupt), and reaches the interpreter as raised.
//
// Ctrl-C during long C++ work: the simulator calls the interrupt check between event instants
// (framework/interrupt.h); check_python_signals, installed when the module loads, runs
// Python's signal handlers there, so KeyboardInterrupt arrives within milliseconds.

#include <pybind11/pybind11.h>

#include <exception>
#include <string>
#include <utility>

#include "cbbg/framework/interrupt.h"

namespace cbbg::python {

namespace py = pybind11;

// A Python exception that must reach the interpreter as it is; deliberately not a
// std::exception. module.cc's translator raises it again.
class PythonInterrupt {
 public:
  explicit PythonInterrupt(py::error_already_set error) : error_(std::move(error)) {}
  // Sets it as Python's current exception; with the GIL held. (Not error_already_set::restore,
  // which may run once only: an exception_ptr may carry copies of this to several threads.)
  void restore() const {
    PyErr_Restore(error_.type().inc_ref().ptr(), error_.value().inc_ref().ptr(),
                  error_.trace().inc_ref().ptr());
  }

 private:
  py::error_already_set error_;
};

// Throws `error` as a PythonInterrupt when it is not an Exception; with the GIL held.
inline void throw_if_interrupt(const py::error_already_set& error) {
  if (!error.matches(PyExc_Exception)) {
    cbbg::throw_interrupt(std::make_exception_ptr(PythonInterrupt(error)));
  }
}

// call() (Python code, with the GIL held), a KeyboardInterrupt or SystemExit it raises leaving
// as a PythonInterrupt; any other exception as it is.
template <class Call>
decltype(auto) calling_python(Call&& call) {
  try {
    return std::forward<Call>(call)();
  } catch (const py::error_already_set& error) {
    throw_if_interrupt(error);
    throw;
  }
}

// "ValueError: the sensor is unplugged": the exception's type and message, for an error's
// one-line message (its traceback stays with the exception, the error's __cause__).
inline std::string python_error_text(const py::error_already_set& error) {
  const py::gil_scoped_acquire gil;
  std::string text = py::str(error.type().attr("__name__"));
  std::string message;
  try {
    message = py::str(error.value());
  } catch (const py::error_already_set&) {
    message = "(its str() raised)";
  }
  return message.empty() ? text : text + ": " + message;
}

// Python's main thread (the one whose signal handlers run), set when the module loads.
inline unsigned long& python_main_thread() {
  static unsigned long ident = 0;
  return ident;
}

// The simulator's interrupt check: in Python's main thread, runs the signal handlers of the
// signals that arrived (KeyboardInterrupt for Ctrl-C) and throws what they raise as a
// PythonInterrupt. Elsewhere it does nothing: Python handles signals in its main thread only.
inline void check_python_signals() {
  if (PyThread_get_thread_ident() != python_main_thread()) return;
  if (!Py_IsInitialized() || _Py_IsFinalizing() != 0) return;
  const py::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() != 0) {
    cbbg::throw_interrupt(std::make_exception_ptr(PythonInterrupt(py::error_already_set())));
  }
}

}  // namespace cbbg::python
