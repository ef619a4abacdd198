// What the binding files of asperity.topography share: a long computation run without the GIL, a
// size from Python, file names back as text. The heights, fits and solves run on copies taken
// with the GIL held (the submodule's contract: module.cpp).
#pragma once
#include <pybind11/pybind11.h>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "helpers.hpp"
#include "interrupt.hpp"
#include "paths.hpp"

namespace asperity::python {

// Runs function() without the GIL, stopped by Ctrl-C (interrupt.hpp). What it reads must be its
// own (captured by value when the lambda is made, with the GIL held), never an object another
// Python thread can change.
template <class Function>
auto without_gil(Function&& function) {
  return interruptible(std::forward<Function>(function));
}

// A size from Python: an int (or anything with __index__) from 0 to the largest std::size_t.
inline std::size_t to_size(const py::handle& value, const char* name) {
  const py::object index = py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr()));
  if (!index) throw py::error_already_set();  // TypeError: not an integer
  const std::size_t size = PyLong_AsSize_t(index.ptr());
  if (size == static_cast<std::size_t>(-1) && PyErr_Occurred()) {
    PyErr_Clear();
    throw py::value_error(std::string(name) + " must be a whole number from 0 to " +
                          std::to_string(static_cast<std::size_t>(-1)) + ", not " + std::string(py::repr(value)));
  }
  return size;
}

inline py::list path_texts(const std::vector<std::string>& texts) {
  py::list out;
  for (const std::string& text : texts) out.append(path_text(text));
  return out;
}

}  // namespace asperity::python
