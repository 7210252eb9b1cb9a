#pragma once
// Python objects held by C++: blocks Python made stay Python's, and callables Python gave to
// C++ (slot factories, plant kinds, protocols) are copied freely by C++ in any thread.
//
// A diagram (or a slot, a plant factory) that takes a block Python made shares it through a
// std::shared_ptr that holds the Python object, not the C++ one, so the block lives while
// either needs it and a block written in Python keeps its Python half.

#include <pybind11/pybind11.h>

#include <memory>
#include <string>

namespace cbbg::python {

namespace py = pybind11;

// Lets go of a reference with the GIL held; after the interpreter ends (a registration kept
// in a static table) it is left alone, as there is nothing left to free it into.
inline void release_reference(py::handle object) {
  if (!Py_IsInitialized() || _Py_IsFinalizing() != 0) return;
  py::gil_scoped_acquire gil;
  object.dec_ref();
}

// `object`, a Python object of a T (made in Python or handed to Python), shared with C++.
// Throws std::invalid_argument naming `what` when it is not a T.
template <class T>
std::shared_ptr<T> shared_from_python(py::handle object, const std::string& what) {
  if (object.is_none() || !py::isinstance<T>(object)) {
    throw std::invalid_argument(
        what + ": expected a " + std::string(py::str(py::type::of<T>().attr("__name__"))) +
        ", got " + std::string(py::str(py::type::of(object).attr("__name__"))));
  }
  T* block = object.cast<T*>();
  object.inc_ref();
  // A handle copies without touching the reference count: the deleter runs in any thread.
  return std::shared_ptr<T>(block, [object](T*) { release_reference(object); });
}

// A Python object that C++ copies may share in any thread: copies touch only an atomic count,
// and the last one lets the object go with the GIL held.
class SharedPythonObject {
 public:
  explicit SharedPythonObject(py::object object)
      : handle_(object.release().ptr(), [](PyObject* held) { release_reference(held); }) {}
  // Use with the GIL held.
  py::handle get() const { return handle_.get(); }

 private:
  std::shared_ptr<PyObject> handle_;
};

}  // namespace cbbg::python
