// File names between Python and the library: the bytes the operating system sees, whatever the
// caller passed (str, bytes or os.PathLike; a str that is not valid UTF-8 on the way in comes
// through os.fsencode's surrogateescape), and back as os.fsdecode gives them (so that a name read
// from the disk in any encoding round-trips, never a decoding error).
#pragma once
#include <pybind11/pybind11.h>

#include <string>

namespace asperity::python {

namespace py = pybind11;

// os.fsencode(path) as a std::string; TypeError for anything but str, bytes and os.PathLike,
// ValueError for an embedded NUL (the C library would stop there: another file).
inline std::string to_path(py::handle path, const char* name = "path") {
  if (!(py::isinstance<py::str>(path) || py::isinstance<py::bytes>(path) ||
        py::hasattr(path, "__fspath__")))
    throw py::type_error(std::string(name) + " must be a str, bytes or os.PathLike, not '" +
                         std::string(py::str(py::type::handle_of(path).attr("__name__"))) + "'");
  const py::bytes encoded = py::module_::import("os").attr("fsencode")(path);
  std::string bytes = encoded;
  if (bytes.find('\0') != std::string::npos)
    throw py::value_error(std::string(name) + " holds a NUL character: " + std::string(py::repr(path)));
  return bytes;
}

// A file name (or a text holding one) from the library as Python text: os.fsdecode's
// surrogateescape for bytes that are not UTF-8.
inline py::str path_text(const std::string& bytes) {
  PyObject* text = PyUnicode_DecodeFSDefaultAndSize(bytes.data(), static_cast<Py_ssize_t>(bytes.size()));
  if (!text) throw py::error_already_set();
  return py::reinterpret_steal<py::str>(text);
}

}  // namespace asperity::python
