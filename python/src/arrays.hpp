// numpy arrays in and out of the library: any shape, any real dtype (converted to float64 once,
// without copying when it already is contiguous float64), the result shaped like the input; a
// Python number in gives a Python float out. The work runs without the GIL for large arrays,
// so other Python threads go on meanwhile.
#pragma once
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace asperity::python {

namespace py = pybind11;

// Python objects passed through as they are, named in the signatures help() shows (the type
// casters below): a number or an array of numbers in, a float or an array out, a record out.
struct ArrayLike {
  py::object object;
};
struct OptionalOut {
  py::object object;  // None or the array to write into
};
struct FloatOrArray {
  py::object object;
};
struct ContactStateRecord {
  py::object object;
};
struct PhysicalStateRecord {
  py::object object;
};
struct DistributionName {
  py::object object;  // 'weibull', 'gaussian' or an asperity.Distribution
};
struct SideName {
  py::object object;  // 'tail', 'bounded' or an asperity.Side
};
struct PathName {
  py::object object;  // str, bytes or os.PathLike
};
struct Count {
  py::object object;  // an int or anything with __index__ (numpy's integers), checked where used
};
struct OrderName {
  py::object object;  // twice_order 0..5 (an int) or a quantity's name ('load'), checked where used
};

}  // namespace asperity::python

namespace pybind11::detail {
#define ASPERITY_PASS_THROUGH_CASTER(Type, Name)                                                              \
  template <>                                                                                                \
  struct type_caster<asperity::python::Type> {                                                               \
    PYBIND11_TYPE_CASTER(asperity::python::Type, const_name(Name));                                          \
    bool load(handle source, bool) {                                                                         \
      if (!source) return false;                                                                             \
      value.object = reinterpret_borrow<object>(source);                                                     \
      return true;                                                                                           \
    }                                                                                                        \
    static handle cast(const asperity::python::Type& source, return_value_policy, handle) {                  \
      return source.object.inc_ref();                                                                        \
    }                                                                                                        \
  };
ASPERITY_PASS_THROUGH_CASTER(ArrayLike, "float | numpy.typing.ArrayLike")
ASPERITY_PASS_THROUGH_CASTER(OptionalOut, "numpy.ndarray[numpy.float64] | None")
ASPERITY_PASS_THROUGH_CASTER(FloatOrArray, "float | numpy.ndarray[numpy.float64]")
ASPERITY_PASS_THROUGH_CASTER(ContactStateRecord, "asperity.ContactState")
ASPERITY_PASS_THROUGH_CASTER(PhysicalStateRecord, "asperity.PhysicalState")
ASPERITY_PASS_THROUGH_CASTER(DistributionName, "str | asperity.Distribution")
ASPERITY_PASS_THROUGH_CASTER(SideName, "str | asperity.Side")
ASPERITY_PASS_THROUGH_CASTER(PathName, "str | bytes | os.PathLike")
ASPERITY_PASS_THROUGH_CASTER(Count, "int")
ASPERITY_PASS_THROUGH_CASTER(OrderName, "int | str")
#undef ASPERITY_PASS_THROUGH_CASTER
}  // namespace pybind11::detail

namespace asperity::python {

// C-contiguous and aligned (an unaligned buffer, e.g. a view at an odd byte offset, is copied).
constexpr int aligned = py::detail::npy_api::NPY_ARRAY_ALIGNED_;
using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast | aligned>;

// Below this many elements the GIL is kept: releasing and taking it back costs more than the work.
inline constexpr std::size_t release_gil_from = 2048;

inline py::type_error not_numbers(const char* name, const std::string& what) {
  return py::type_error(std::string(name) + " must be a number or an array of numbers, not " + what);
}

// Why a float64 copy of `any` could not be made: ensure() clears numpy's error, so numpy is asked
// again and its own is raised (MemoryError naming the size, for a broadcast of 2^36 elements);
// else a MemoryError naming the size here.
inline py::error_already_set copy_failed(const py::array& any, const char* name) {
  try {
    py::module_::import("numpy").attr("ascontiguousarray")(any, py::arg("dtype") = "float64");
  } catch (py::error_already_set& numpy_error) {
    return std::move(numpy_error);
  }
  const std::string message = std::string(name) + ": no float64 copy of an array of " + std::to_string(any.size()) +
                              " elements (" + std::to_string(any.size() / 131072) + " MiB) could be made";
  PyErr_SetString(PyExc_MemoryError, message.c_str());
  return py::error_already_set();
}

// The argument as a C-contiguous float64 array (a copy only if needed). Numbers only: bool, int,
// unsigned and float arrays and scalars, and objects with __float__ (fractions.Fraction,
// decimal.Decimal), as float() takes them. TypeError for anything else: None (numpy would make
// it NaN), strings (numpy would parse them), complex numbers (numpy would drop the imaginary
// part), dates.
inline DoubleArray as_double_array(py::handle input, const char* name) {
  if (input.is_none()) throw not_numbers(name, "None");
  if (PyUnicode_Check(input.ptr()) || PyBytes_Check(input.ptr()) || PyByteArray_Check(input.ptr()))
    throw not_numbers(name, "a string");
  const py::array any = py::array::ensure(input);
  if (!any) throw not_numbers(name, "'" + std::string(py::str(py::type::handle_of(input).attr("__name__"))) + "'");
  const char kind = any.dtype().kind();
  if (kind == 'b' || kind == 'i' || kind == 'u' || kind == 'f') {
    DoubleArray array = DoubleArray::ensure(any);
    if (!array) throw copy_failed(any, name);
    return array;
  }
  if (kind != 'O') throw not_numbers(name, "an array of dtype " + std::string(py::str(any.dtype())));
  // objects: each converted as float() converts a number (never a string, never None)
  DoubleArray array(std::vector<py::ssize_t>(any.shape(), any.shape() + any.ndim()));
  double* target = array.mutable_data();
  const bool one = any.ndim() == 0;
  for (const py::handle item : py::iter(any.attr("flat"))) {
    const bool text = PyUnicode_Check(item.ptr()) || PyBytes_Check(item.ptr()) || PyByteArray_Check(item.ptr());
    double value = -1.0;
    if (!text && !item.is_none()) value = PyFloat_AsDouble(item.ptr());  // __float__ (or __index__)
    if (text || item.is_none() || (value == -1.0 && PyErr_Occurred())) {
      if (PyErr_Occurred() && !PyErr_ExceptionMatches(PyExc_TypeError)) throw py::error_already_set();
      PyErr_Clear();
      const std::string what =
          item.is_none() ? "None" : "'" + std::string(py::str(py::type::handle_of(item).attr("__name__"))) + "'";
      throw not_numbers(name, one ? what : "an array holding " + what);
    }
    *target++ = value;
  }
  return array;
}

// A plain number, not an ndarray (a Python float or int, a numpy scalar): the answer is a float.
inline bool is_scalar(py::handle input, const DoubleArray& array) {
  return array.ndim() == 0 && !py::isinstance<py::array>(input);
}

inline std::vector<py::ssize_t> shape_of(const DoubleArray& array) {
  return std::vector<py::ssize_t>(array.shape(), array.shape() + array.ndim());
}

// Whether n doubles at a and at b share memory without being the same elements: both are
// contiguous, so numpy's shares_memory is this comparison of the two byte ranges.
inline bool overlap_apart(const double* a, const double* b, std::size_t n) {
  const auto first = reinterpret_cast<std::uintptr_t>(a), second = reinterpret_cast<std::uintptr_t>(b);
  const std::uintptr_t bytes = n * sizeof(double);
  return n > 0 && first != second && first < second + bytes && second < first + bytes;
}

// out[i] = f(in[i]) for a whole array through one call `batch(in, out, n)`, or `scalar(x)` for one
// number; `out`, if given, must be a writeable, aligned, C-contiguous float64 array of the
// input's size and receives the result. out may be the input itself (in place) or overlap it in
// any other way (then the input is copied first, as memmove would).
template <class Batch, class Scalar>
FloatOrArray map_batch(py::handle input, const char* name, py::object out, Batch batch, Scalar scalar) {
  if (out.is_none() && (PyFloat_Check(input.ptr()) || (PyLong_Check(input.ptr()) && !PyBool_Check(input.ptr())))) {
    // One number (a float, an int, numpy.float64): no array made, a float back.
    const double x = PyFloat_AsDouble(input.ptr());
    if (x == -1.0 && PyErr_Occurred()) throw py::error_already_set();
    return {py::float_(scalar(x))};
  }
  DoubleArray in = as_double_array(input, name);
  const std::size_t n = static_cast<std::size_t>(in.size());
  py::array_t<double> result;
  if (out.is_none()) {
    result = py::array_t<double>(shape_of(in));
  } else {
    if (!py::isinstance<py::array_t<double>>(out)) throw py::type_error("out must be a float64 numpy array");
    result = py::reinterpret_borrow<py::array_t<double>>(out);
    if (!(result.flags() & py::array::c_style) || !(result.flags() & aligned) || !result.writeable())
      throw py::value_error("out must be C-contiguous, aligned and writeable");
    if (static_cast<std::size_t>(result.size()) != n)
      throw py::value_error("out has " + std::to_string(result.size()) + " elements, the input " + std::to_string(n));
    if (overlap_apart(in.data(), result.data(), n)) in = DoubleArray(shape_of(in), in.data());  // a copy
  }
  const double* source = in.data();
  double* target = result.mutable_data();
  if (n >= release_gil_from) {
    py::gil_scoped_release unlocked;
    batch(source, target, n);
  } else {
    batch(source, target, n);
  }
  if (out.is_none() && is_scalar(input, in)) return {py::float_(target[0])};
  return {std::move(result)};
}

// Several outputs per element (a record of arrays): `each(in[i], i)` writes element i of every
// output. Returns the arrays, shaped like the input (floats for a number).
template <std::size_t Fields, class Each>
std::vector<py::object> map_records(py::handle input, const char* name, Each each) {
  const DoubleArray in = as_double_array(input, name);
  const std::size_t n = static_cast<std::size_t>(in.size());
  std::vector<py::array_t<double>> arrays;
  double* fields[Fields];
  arrays.reserve(Fields);
  for (std::size_t k = 0; k < Fields; ++k) {
    arrays.emplace_back(shape_of(in));
    fields[k] = arrays.back().mutable_data();
  }
  const double* source = in.data();
  auto run = [&] {
    for (std::size_t i = 0; i < n; ++i) each(source[i], fields, i);
  };
  if (n >= release_gil_from) {
    py::gil_scoped_release unlocked;
    run();
  } else {
    run();
  }
  std::vector<py::object> result;
  const bool scalar = is_scalar(input, in);
  for (std::size_t k = 0; k < Fields; ++k)
    result.push_back(scalar ? py::object(py::float_(fields[k][0])) : py::object(arrays[k]));
  return result;
}

}  // namespace asperity::python
