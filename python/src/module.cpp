// The Python module asperity._asperity (imported by python/asperity/__init__.py): a thin
// binding of the C++ API with the same names. Arrays go through the vectorized batch path
// (arrays.hpp); asperity::Error becomes asperity.Error with the library's message.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "paths.hpp"
#include "asperity/contact.hpp"
#include "asperity/contact_curves.hpp"
#include "asperity/contact_model.hpp"
#include "asperity/error.hpp"
#include "asperity/instruction_set.hpp"
#include "asperity/interrupt.hpp"
#include "asperity/inverse.hpp"
#include "asperity/integrals.hpp"
#include "asperity/number_text.hpp"
#include "asperity/persson.hpp"
#include "asperity/plausibility.hpp"
#include "asperity/pressure_overclosure.hpp"
#include "asperity/scene.hpp"
#include "asperity/scene_curves.hpp"
#include "asperity/separation_datum.hpp"
#include "asperity/surface.hpp"
#include "asperity/table.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace asperity::python {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// The record types (collections.namedtuple, made once at import): fields are floats for a
// number in, arrays for an array in.
py::handle contact_state_type, physical_state_type;

Distribution to_distribution(const py::handle& value) {
  if (py::isinstance<Distribution>(value)) return value.cast<Distribution>();
  if (py::isinstance<py::str>(value)) {
    const std::string name = value.cast<std::string>();
    Distribution out;
    if (parse_distribution(name, out)) return out;
    throw py::value_error("unknown distribution '" + name + "': expected 'weibull' or 'gaussian'");
  }
  throw py::type_error("distribution must be 'weibull', 'gaussian' or an asperity.Distribution");
}

Side to_side(const py::handle& value) {
  if (py::isinstance<Side>(value)) return value.cast<Side>();
  if (py::isinstance<py::str>(value)) {
    const std::string name = value.cast<std::string>();
    Side out;
    if (parse_side(name, out)) return out;
    throw py::value_error("unknown side '" + name + "': expected 'tail' or 'bounded'");
  }
  throw py::type_error("side must be 'tail', 'bounded' or an asperity.Side");
}

// twice_order from an int 0..5 or a quantity's name, as scene files name them (quantity_twice_order,
// docs/model.md): 'count', 'stiffness', 'area', 'load', 'F2', 'F5/2', ...
constexpr const char* order_names = "'count', 'stiffness', 'area', 'load' (or 'F0', 'F1/2', 'F1', 'F3/2', 'F2', 'F5/2')";
int twice_order_of(const OrderName& order) {
  const py::handle value = order.object;
  if (py::isinstance<py::str>(value)) {
    const std::string name = value.cast<std::string>();
    const int twice_order = quantity_twice_order(name);
    if (twice_order < 0)
      throw py::value_error("unknown order " + std::string(py::repr(value)) + ": expected " + order_names +
                            " or twice_order 0..5");
    return twice_order;
  }
  if (PyBool_Check(value.ptr()) || !PyIndex_Check(value.ptr()))
    throw py::type_error(std::string("the order must be twice_order 0..5 (an int) or a quantity's name (") +
                         order_names + "), not '" +
                         std::string(py::str(py::type::handle_of(value).attr("__name__"))) + "'");
  const Py_ssize_t twice_order = PyNumber_AsSsize_t(value.ptr(), nullptr);  // clipped, never overflows
  if (twice_order == -1 && PyErr_Occurred()) throw py::error_already_set();
  if (twice_order < 0 || twice_order >= order_count)
    throw py::value_error("twice_order " + std::to_string(twice_order) + " is outside 0..5");
  return static_cast<int>(twice_order);
}

py::array_t<double> to_array(const std::vector<double>& values) {
  py::array_t<double> out(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

py::object make_record(py::handle type, const std::vector<py::object>& fields) {
  py::tuple arguments(fields.size());
  for (std::size_t i = 0; i < fields.size(); ++i) arguments[i] = fields[i];
  return type(*arguments);
}

// asperity.AreaFractionWarning (a UserWarning), made once at import.
PyObject* area_fraction_warning = nullptr;

// As the command warns (asperity contact), a Python warning where the real area passes
// gw_area_fraction_limit of the nominal area; raises if warnings are errors (-W error).
void warn_past_gw(double area_fraction) {
  if (!(area_fraction > gw_area_fraction_limit)) return;
  char text[320];
  std::snprintf(text, sizeof text,
                "the real contact area reaches %.4g of the nominal area (above %.4g): Greenwood-Williamson treats "
                "the asperity contacts as sparse and independent, which no longer holds there%s",
                area_fraction, gw_area_fraction_limit, area_fraction > 1 ? "; above 1 the answer is impossible" : "");
  if (PyErr_WarnEx(area_fraction_warning, text, 1) < 0) throw py::error_already_set();
}

// asperity.OutOfRangeWarning (a UserWarning), made once at import.
PyObject* out_of_range_warning = nullptr;

// Queries outside the range a table serves (a scene table's, contact curves') are answered NaN,
// as the C++ API answers them; where the command refuses them, Python warns once per call,
// naming how many and the range in the query's unit. Raises if warnings are errors.
void warn_out_of_range(std::size_t outside, std::size_t total, const char* what, const std::string& range) {
  if (outside == 0) return;
  const std::string text = std::to_string(outside) + " of " + std::to_string(total) + " " + what +
                           " outside the range the table serves (answered NaN): " + range;
  if (PyErr_WarnEx(out_of_range_warning, text.c_str(), 1) < 0) throw py::error_already_set();
}

std::string g(double value) { return format_double(value); }

// The range a model answers (a scene table's), in the unit of a query of `kind`
std::string model_range(const ContactModel& model, const std::string& kind) {
  const double area = model.surface().nominal_area;
  if (kind == "separation")
    return "separations " + g(model.min_separation()) + " to " + g(model.max_separation()) + " m" +
           (model.surface().side == Side::bounded ? " (and from 0 on: no contact)" : "");
  if (kind == "load") return "loads " + g(model.min_load()) + " to " + g(model.max_load()) + " N";
  if (kind == "pressure") return "nominal pressures " + g(model.min_load() / area) + " to " + g(model.max_load() / area) + " Pa";
  return "real areas " + g(model.min_real_area()) + " to " + g(model.max_real_area()) + " m^2";
}

template <class Answer>
PhysicalStateRecord physical_states(py::handle input, const char* name, const ContactModel& model, Answer answer) {
  double largest_fraction = 0;  // NaN never counts
  std::size_t total = 0, outside = 0;  // queries, and those answered NaN (outside a scene table's range)
  constexpr std::size_t fields = physical_state_field_count;
  PhysicalStateRecord record{make_record(physical_state_type, map_records<fields>(input, name, [&](double x, double** out, std::size_t i) {
    const PhysicalState state = answer(x);
    if (state.area_fraction > largest_fraction) largest_fraction = state.area_fraction;
    ++total;
    outside += std::isnan(state.load) && !std::isnan(x);
    for (std::size_t k = 0; k < fields; ++k) out[k][i] = state.*physical_state_members[k];
  }))};
  const std::string kind = std::strcmp(name, "real_area") == 0 ? "real-area" : name;
  const std::string plural = kind == "real-area" ? "real areas" : std::string(name) + "s";
  if (outside > 0) warn_out_of_range(outside, total, plural.c_str(), model_range(model, kind));
  warn_past_gw(largest_fraction);
  return record;
}

template <class Function>
FloatOrArray map_scalar(py::handle input, const char* name, Function function) {
  return map_batch(
      input, name, py::none(),
      [&](const double* in, double* out, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) out[i] = function(in[i]);
      },
      function);
}

// map_scalar for contact curves: values of x outside [lo, hi] (NaN aside) counted and warned
template <class Function>
FloatOrArray map_served(py::handle input, const char* name, double lo, double hi, const char* unit, Function function) {
  std::size_t total = 0, outside = 0;
  FloatOrArray answer = map_scalar(input, name, [&](double x) {
    ++total;
    outside += !std::isnan(x) && !(x >= lo && x <= hi);
    return function(x);
  });
  if (outside > 0)
    warn_out_of_range(outside, total, (std::string(name) + "s").c_str(),
                      std::string(name) + "s " + g(lo) + " to " + g(hi) + " " + unit);
  return answer;
}

std::string describe(const Curve& curve) {
  std::string text = std::string("<asperity.Curve ") + to_string(curve.distribution()) + " " + to_string(curve.side());
  if (curve.distribution() == Distribution::weibull) text += " shape=" + py::repr(py::float_(curve.shape())).cast<std::string>();
  return text + ">";
}

CardFormat card_format(const std::string& name) {
  CardFormat format;
  if (!parse_card_format(name, format)) throw Error("unknown card format '" + name + "' (calculix, abaqus or csv)");
  return format;
}
CardUnits card_units(const std::string& name) {
  CardUnits units;
  if (!parse_card_units(name, units)) throw Error("unknown card units '" + name + "' (si or mm)");
  return units;
}
}  // namespace

void bind(py::module_& m) {
  m.doc() = "asperity: Greenwood-Williamson asperity integrals from precomputed tables (the C++ library's binding).";
  m.attr("__version__") = ASPERITY_VERSION_STRING;
  m.attr("ORDER_COUNT") = order_count;
  m.attr("ALL_ORDERS") = Curve::all_orders;

  // asperity::Error as asperity.Error with the library's message; a message naming a file whose
  // name is not UTF-8 keeps those bytes as \xNN escapes (pybind11's own translation would fail).
  static PyObject* const error_type = py::exception<Error>(m, "Error", PyExc_RuntimeError).release().ptr();  // kept
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const Interrupted&) {  // a stop asked (interrupt.hpp): the signal handler's exception
      if (!PyErr_Occurred()) PyErr_SetNone(PyExc_KeyboardInterrupt);
    } catch (const Error& error) {
      const char* message = error.what();
      PyObject* text = PyUnicode_DecodeUTF8(message, static_cast<Py_ssize_t>(std::strlen(message)), "backslashreplace");
      if (!text) return;  // the decoding error stands
      PyErr_SetObject(error_type, text);
      Py_DECREF(text);
    }
  });
  area_fraction_warning = PyErr_NewExceptionWithDoc(
      "asperity.AreaFractionWarning",
      "Warned (warnings.warn) where a ContactModel's real contact area passes gw_area_fraction_limit (0.1) of the\n"
      "nominal area, as the command asperity contact warns: Greenwood-Williamson's asperity contacts are\n"
      "sparse and independent only below it. warnings.simplefilter('error', asperity.AreaFractionWarning)\n"
      "makes it an exception; 'ignore' silences it.",
      PyExc_UserWarning, nullptr);
  if (!area_fraction_warning) throw py::error_already_set();
  m.attr("AreaFractionWarning") = py::reinterpret_borrow<py::object>(area_fraction_warning);  // the module keeps it
  out_of_range_warning = PyErr_NewExceptionWithDoc(
      "asperity.OutOfRangeWarning",
      "Warned (warnings.warn) where a query lies outside the range a table serves and is answered NaN: a\n"
      "ContactModel on a scene table (its scene's separations, and the loads, pressures and real areas there) or\n"
      "ContactCurves (a contact-curves table: a law's or a measured surface's). The message names how many and\n"
      "the range, in the query's unit; the command asperity contact refuses such a query.\n"
      "warnings.simplefilter('error', asperity.OutOfRangeWarning) makes it an exception.",
      PyExc_UserWarning, nullptr);
  if (!out_of_range_warning) throw py::error_already_set();
  m.attr("OutOfRangeWarning") = py::reinterpret_borrow<py::object>(out_of_range_warning);
  m.attr("gw_area_fraction_limit") = gw_area_fraction_limit;
  m.attr("Error").attr("__doc__") =
      "An error of the asperity library (a missing or bad table or scene, a shape outside the table, a bad "
      "physical parameter); its message is the library's.";

  auto collections = py::module_::import("collections");
  py::object contact_state = collections.attr("namedtuple")(
      "ContactState", py::make_tuple("count", "area", "load", "stiffness", "stiffness_ratio"), "module"_a = "asperity");
  contact_state.attr("__doc__") =
      "contact_at's answer (floats, or arrays shaped like the separations): count N X_0, area pi N R sigma_s X_1, "
      "load (4/3) N E* R^1/2 sigma_s^3/2 X_3/2, stiffness 2 N E* R^1/2 sigma_s^1/2 X_1/2 and the stiffness/load "
      "ratio (3/2) X_1/2 / X_3/2 (in separation units).";
  m.attr("ContactState") = contact_state;
  contact_state_type = contact_state.release();
  // the fields' names and meanings from their one list (physical_state_fields.hpp)
  py::list physical_state_names;
  std::string physical_state_doc = "ContactModel's answer (floats, or arrays shaped like the input), SI units:";
  for (const PhysicalStateField& field : physical_state_fields) {
    physical_state_names.append(field.name);
    physical_state_doc += std::string(" ") + field.name + " (" + field.meaning + "),";
  }
  physical_state_doc.back() = '.';
  py::object physical_state = collections.attr("namedtuple")("PhysicalState", py::tuple(physical_state_names),
                                                             "module"_a = "asperity");
  physical_state.attr("__doc__") = physical_state_doc;
  m.attr("PhysicalState") = physical_state;
  physical_state_type = physical_state.release();

  // ---- the vocabulary (asperity/model.hpp) ----
  py::enum_<Distribution>(m, "Distribution", "Summit height density: weibull (shape a) or gaussian.")
      .value("weibull", Distribution::weibull)
      .value("gaussian", Distribution::gaussian);
  py::enum_<Side>(m, "Side", "Side of approach: tail (the GW approach, unbounded upper tail) or bounded "
                             "(mirrored heights: worn, polished surfaces; Weibull only).")
      .value("tail", Side::tail)
      .value("bounded", Side::bounded);
  py::enum_<InstructionSet>(m, "InstructionSet", "The batch kernel's instruction set.")
      .value("automatic", InstructionSet::automatic)
      .value("generic", InstructionSet::generic)
      .value("avx2", InstructionSet::avx2)
      .value("avx512", InstructionSet::avx512);
  m.def("best_instruction_set", &best_instruction_set,
        "The widest instruction set this CPU has, which the batch path uses.");

  m.def("order_of", [](const OrderName& order) { return order_of(twice_order_of(order)); }, "twice_order"_a,
        "The order n = twice_order / 2 (twice_order 0..5 or a quantity's name: order_of('load') is 1.5).");
  m.def("weibull_mean", py::vectorize(&weibull_mean), "shape"_a,
        "Mean of the unit Weibull density, mu_a = Gamma(1 + 1/a).");
  m.def("weibull_rms", py::vectorize(&weibull_rms), "shape"_a,
        "Rms about the mean of the unit Weibull density, c_a = sqrt(Gamma(1 + 2/a) - Gamma(1 + 1/a)^2).");
  m.def("weibull_moment", py::vectorize(&weibull_moment), "shape"_a, "power"_a,
        "Raw moment of the unit Weibull density, E z^p = Gamma(1 + p/a).");
  m.def("weibull_log_density", py::vectorize(&weibull_log_density), "shape"_a, "height"_a,
        "ln phi_a(z), phi_a(z) = a z^(a-1) exp(-z^a).");
  m.def("gaussian_log_density", py::vectorize(&gaussian_log_density), "height"_a,
        "ln phi(z), phi(z) = exp(-z^2/2) / sqrt(2 pi).");

  // ---- curves (asperity/curve.hpp) ----
  py::class_<Curve>(m, "Curve",
                    "One resolved curve (distribution, side, shape): the hot handle. Immutable; any number of "
                    "threads may query it at once. Made by Table.curve.")
      .def(
          "value",
          [](const Curve& curve, const OrderName& order, const ArrayLike& separation, const OptionalOut& out) {
            const int twice_order = twice_order_of(order);
            return map_batch(separation.object, "separation", out.object, [&](const double* in, double* result, std::size_t n) {
              curve.value_batch(twice_order, in, result, n);
            }, [&](double x) { return curve.value(twice_order, x); });
          },
          "twice_order"_a, "separation"_a, py::kw_only(), "out"_a = py::none(),
          "X_n(s) for n = twice_order/2 (0 count, 1 stiffness, 2 area, 3 load, 4 F_2, 5 F_5/2) at the\n"
          "separations s (origin convention, units of sigma_s; docs/model.md). The order is twice_order or\n"
          "the quantity's name: 'count', 'stiffness', 'area', 'load', 'F2', 'F5/2' (quantity_twice_order).\n\n"
          "separation: a number (the answer is a float) or an array of any shape (the answer is a float64\n"
          "array of that shape), computed by the vectorized batch path without the GIL. NaN for a NaN or\n"
          "infinite separation; underflows to 0 below ~1e-308 (use log_value there). out: an optional\n"
          "C-contiguous float64 array of the same size to write into (returned).")
      .def(
          "log_value",
          [](const Curve& curve, const OrderName& order, const ArrayLike& separation, const OptionalOut& out) {
            const int twice_order = twice_order_of(order);
            return map_batch(separation.object, "separation", out.object, [&](const double* in, double* result, std::size_t n) {
              curve.log_value_batch(twice_order, in, result, n);
            }, [&](double x) { return curve.log_value(twice_order, x); });
          },
          "twice_order"_a, "separation"_a, py::kw_only(), "out"_a = py::none(),
          "ln X_n(s): finite wherever X_n > 0 (far below 1e-308), -inf where it is exactly 0 (bounded side,\n"
          "s >= 0). Arguments as for value().")
      .def("has_order", [](const Curve& curve, const OrderName& order) { return curve.has_order(twice_order_of(order)); },
           "twice_order"_a, "Whether the curve holds this order (twice_order or a quantity's name; order_mask).")
      .def_property_readonly("distribution", &Curve::distribution)
      .def_property_readonly("side", &Curve::side)
      .def_property_readonly("shape", &Curve::shape, "The Weibull shape a (2 for the Gaussian).")
      .def_property_readonly("order_mask", &Curve::order_mask, "Bit 1 << twice_order for each order held.")
      .def_property_readonly("served_min_separation", &Curve::served_min_separation,
                             "The separations the curve serves start here: -inf for a full table's curves, a scene\n"
                             "table's range for its curves. Outside them value() and log_value() answer NaN\n"
                             "(the bounded side at s >= 0 excepted: exactly 0).")
      .def_property_readonly("served_max_separation", &Curve::served_max_separation,
                             "The separations the curve serves end here: +inf for a full table's curves.")
      .def("serves", py::vectorize(&Curve::serves), "separation"_a,
           "True where the curve answers: inside [served_min_separation, served_max_separation], or the\n"
           "bounded side at s >= 0 (exactly 0); False for NaN.")
      .def_property_readonly("table_min_separation", &Curve::table_min_separation,
                             "Where the knots start (below: the all-touching segment).")
      .def_property_readonly("table_max_separation", &Curve::table_max_separation,
                             "Where the knots end (beyond: the series).")
      .def_property_readonly("memory_bytes", &Curve::memory_bytes, "Bytes of the curve's data (shared by its copies).")
      .def_property_readonly("grid_intervals", &Curve::grid_intervals,
                             "Intervals of the lookup grid per order (CurveOptions.grid_tolerance sets how many).")
      .def_property_readonly("grid_error", &Curve::grid_error,
                             "The largest difference in ln X from the table the grid showed where it was checked.")
      .def("__copy__", [](const Curve& curve) { return curve; }, "A handle sharing the same data (curves are immutable).")
      .def("__deepcopy__", [](const Curve& curve, py::dict) { return curve; }, "memo"_a)
      .def("__repr__", &describe);

  py::class_<CurveOptions>(m, "CurveOptions",
                           "The lookup grid of a curve (Table.curve(..., options=)): the largest error it may add to\n"
                           "the table's own, in ln X (relative in X where X >= 1e-100; 100 times that below), and the\n"
                           "separations it covers (outside, the table's own layout answers). A smaller tolerance costs\n"
                           "memory, never time.")
      .def(py::init([](double grid_tolerance, double grid_min_separation, double grid_max_separation) {
             CurveOptions options;
             options.grid_tolerance = grid_tolerance;
             options.grid_min_separation = grid_min_separation;
             options.grid_max_separation = grid_max_separation;
             return options;
           }),
           "grid_tolerance"_a = CurveOptions{}.grid_tolerance,
           "grid_min_separation"_a = CurveOptions{}.grid_min_separation,
           "grid_max_separation"_a = CurveOptions{}.grid_max_separation)
      .def_readwrite("grid_tolerance", &CurveOptions::grid_tolerance)
      .def_readwrite("grid_min_separation", &CurveOptions::grid_min_separation)
      .def_readwrite("grid_max_separation", &CurveOptions::grid_max_separation)
      .def("__repr__", [](const CurveOptions& o) {
        return py::str("CurveOptions(grid_tolerance={!r}, grid_min_separation={!r}, grid_max_separation={!r})")
            .format(o.grid_tolerance, o.grid_min_separation, o.grid_max_separation);
      });

  // ---- tables (asperity/table.hpp) ----
  py::class_<CurveSet>(m, "CurveSet", "One (distribution, side) group of a table file.")
      .def_readonly("distribution", &CurveSet::distribution)
      .def_readonly("side", &CurveSet::side)
      .def_property_readonly("shapes", [](const CurveSet& set) { return to_array(set.shapes); },
                             "The grid shapes (ascending; a few run past the served range).")
      .def_readonly("shape_min", &CurveSet::shape_min, "The smallest shape served.")
      .def_readonly("shape_max", &CurveSet::shape_max, "The largest shape served.")
      .def_property_readonly(
          "max_rel_error",
          [](const CurveSet& set) {
            py::array_t<double> out = to_array(set.max_rel_error);
            if (!set.max_rel_error.empty()) out.resize({static_cast<py::ssize_t>(set.shapes.size()), py::ssize_t(order_count)});
            return out;
          },
          "The generator's measured error per [shape, twice_order].")
      .def("__repr__", [](const CurveSet& set) {
        return std::string("<asperity.CurveSet ") + to_string(set.distribution) + " " + to_string(set.side) + ", " +
               std::to_string(set.shapes.size()) + " shapes>";
      });

  py::class_<Table>(m, "Table",
                    "A loaded table file: its curve sets, and curves resolved from them. Opening validates "
                    "everything and raises asperity.Error naming the file and the problem.")
      .def_static("open", [](const PathName& path) { return Table::open(to_path(path.object)); }, "path"_a,
                  "Opens and validates a table file (HDF5).")
      .def_static("open_default", &Table::open_default,
                  "The default table: $ASPERITY_TABLE if set, else the one installed with the library\n"
                  "(share/asperity/asperity-default.h5), else the build tree's. The error names every place looked at.")
      .def_static("default_path", [] { return path_text(Table::default_path()); },
                  "The file open_default() would open; raises asperity.Error naming every place looked at.")
      .def_static("default_search_paths", [] {
                    py::list paths;
                    for (const std::string& path : Table::default_search_paths()) paths.append(path_text(path));
                    return paths;
                  },
                  "Where default_path() looks, in order ($ASPERITY_TABLE alone when it is set).")
      .def(
          "curve",
          [](const Table& table, const DistributionName& distribution, const SideName& side, std::optional<double> shape,
             unsigned order_mask, const std::optional<CurveOptions>& options) {
            const Distribution d = to_distribution(distribution.object);
            if (!shape && d == Distribution::weibull) throw py::value_error("a Weibull curve needs its shape");
            if (options) return table.curve(d, to_side(side.object), shape.value_or(2.0), order_mask, *options);
            return table.curve(d, to_side(side.object), shape.value_or(2.0), order_mask);
          },
          "distribution"_a, "side"_a = "tail", "shape"_a = py::none(), "order_mask"_a = Curve::all_orders,
          py::kw_only(), "options"_a = py::none(),
          "The curve of a distribution ('weibull' or 'gaussian'), a side ('tail' or 'bounded') and a Weibull\n"
          "shape (ignored for the Gaussian). A shape between grid nodes is resolved here, once. order_mask\n"
          "(bit 1 << twice_order) keeps only the orders needed (less memory; NaN for the others). options: a\n"
          "CurveOptions for the lookup grid (None: the table's, 1e-13 over the whole range or a scene table's).\n"
          "Raises asperity.Error for a shape outside the table, a missing set or bad options.")
      .def_property_readonly(
          "sets",
          [](const py::object& self) {
            py::list sets;  // views into the table (the knots are not copied), which they keep alive
            for (const CurveSet& set : self.cast<const Table&>().data().sets)
              sets.append(py::cast(&set, py::return_value_policy::reference_internal, self));
            return sets;
          },
          "The (distribution, side) groups of the file.")
      .def_property_readonly("generator", [](const Table& table) { return table.data().generator; })
      .def_property_readonly("generator_options", [](const Table& table) { return table.data().generator_options; })
      .def_property_readonly("exact_shapes", [](const Table& table) { return table.data().exact_shapes; },
                             "True for a scene table: it serves only its own shapes.")
      .def("__repr__", [](const Table& table) {
        return "<asperity.Table " + std::to_string(table.data().sets.size()) + " curve sets>";
      });

  // ---- the physical quantities (asperity/contact.hpp) ----
  py::class_<SurfaceScales>(m, "SurfaceScales",
                            "The four scales contact_at multiplies a curve's integrals by: N summits of radius R, height\n"
                            "scale sigma_s (Gaussian: rms sigma), modulus E*, in any consistent units, with separations\n"
                            "in units of sigma_s (the lower level; Surface is its former name). A physical surface in SI\n"
                            "units, with its distribution, density and nominal area, for ContactModel: RoughSurface.")
      .def(py::init([](double summit_count, double summit_radius, double height_scale, double contact_modulus) {
             return SurfaceScales{summit_count, summit_radius, height_scale, contact_modulus};
           }),
           "summit_count"_a = 1.0, "summit_radius"_a = 1.0, "height_scale"_a = 1.0, "contact_modulus"_a = 1.0)
      .def_readwrite("summit_count", &SurfaceScales::summit_count)
      .def_readwrite("summit_radius", &SurfaceScales::summit_radius)
      .def_readwrite("height_scale", &SurfaceScales::height_scale)
      .def_readwrite("contact_modulus", &SurfaceScales::contact_modulus)
      .def("__repr__", [](const SurfaceScales& s) {
        return py::str("SurfaceScales(summit_count={!r}, summit_radius={!r}, height_scale={!r}, contact_modulus={!r})")
            .format(s.summit_count, s.summit_radius, s.height_scale, s.contact_modulus);
      });

  m.def(
      "contact_at",
      // the surface by value: a copy, read without the GIL while another thread may set its fields
      [](const Curve& curve, SurfaceScales surface, const ArrayLike& separation) -> ContactStateRecord {
        return {make_record(contact_state_type,
                           map_records<5>(separation.object, "separation", [&](double s, double** out, std::size_t i) {
                             ContactState state{nan, nan, nan, nan, nan};
                             contact_at(curve, surface, s, state);
                             out[0][i] = state.count;
                             out[1][i] = state.area;
                             out[2][i] = state.load;
                             out[3][i] = state.stiffness;
                             out[4][i] = state.stiffness_ratio;
                           }))};
      },
      "curve"_a, "surface"_a, "separation"_a,
      "Count, area, load, stiffness and stiffness/load ratio at the separations (a number or an array),\n"
      "as a ContactState of floats or arrays. NaN for a non-physical surface or a NaN/infinite separation.");
  m.def(
      "standardized_from_origin",
      [](const Curve& curve, const ArrayLike& separation) {
        return map_scalar(separation.object, "separation", [&](double s) { return standardized_from_origin(curve, s); });
      },
      "curve"_a, "separation"_a,
      "(s - mu_a)/c_a: the separation from the mean summit height in rms units (the GW/McCool convention).");
  m.def(
      "origin_from_standardized",
      [](const Curve& curve, const ArrayLike& standardized) {
        return map_scalar(standardized.object, "standardized", [&](double t) { return origin_from_standardized(curve, t); });
      },
      "curve"_a, "standardized"_a, "The inverse of standardized_from_origin.");

  // ---- physical surfaces and the contact model (surface.hpp, contact_model.hpp, inverse.hpp) ----
  py::class_<RoughSurface>(m, "RoughSurface",
                              "A physical rough surface in SI units, what ContactModel takes: Weibull summit heights "
                              "of shape a and scale sigma_s, or Gaussian (rms sigma), summit radius and density, "
                              "nominal area, contact modulus (PhysicalSurface is its former name; SurfaceScales, "
                              "formerly Surface, is the lower level's four scales for contact_at).")
      .def(py::init([](const DistributionName& distribution, const SideName& side, std::optional<double> given_shape,
                       std::optional<double> height_scale, double summit_radius, double summit_density,
                       double nominal_area, double contact_modulus, std::optional<double> rms) {
             RoughSurface s;
             s.distribution = to_distribution(distribution.object);
             s.side = to_side(side.object);
             // the Gaussian has no shape: None (or any shape) is taken, as Table.curve takes it
             if (!given_shape && s.distribution == Distribution::weibull)
               throw py::value_error("a Weibull surface needs its shape (shape=None is for the Gaussian)");
             const double shape = given_shape.value_or(2.0);
             s.shape = shape;
             if (height_scale && rms) throw py::value_error("give the height scale once: height_scale or rms");
             s.height_scale = rms ? height_scale_from_rms(s.distribution, shape, *rms) : height_scale.value_or(1e-6);
             s.summit_radius = summit_radius;
             s.summit_density = summit_density;
             s.nominal_area = nominal_area;
             s.contact_modulus = contact_modulus;
             return s;
           }),
           "distribution"_a = "weibull", "side"_a = "tail", "shape"_a = 2.0, "height_scale"_a = py::none(),
           "summit_radius"_a = 1e-4, "summit_density"_a = 1e10, "nominal_area"_a = 1e-4, "contact_modulus"_a = 1e11,
           py::kw_only(), "rms"_a = py::none(),
           "The physical surface a ContactModel takes (PhysicalSurface is its former name). shape: the Weibull\n"
           "shape a (ignored for the Gaussian, which takes None). height_scale sigma_s [m]: the Weibull scale (not\n"
           "its rms), or the Gaussian's rms summit height (default\n"
           "1e-6); or instead rms [m], the rms summit height GW users measure, which sets height_scale through\n"
           "height_scale_from_rms (for a = 1.6, rms = 0.574 sigma_s). summit_radius R [m], summit_density [1/m^2],\n"
           "nominal_area A0 [m^2], contact_modulus E* [Pa] (plane strain).")
      .def_property(
          "distribution", [](const RoughSurface& s) { return s.distribution; },
          [](RoughSurface& s, const DistributionName& value) { s.distribution = to_distribution(value.object); })
      .def_property(
          "side", [](const RoughSurface& s) { return s.side; },
          [](RoughSurface& s, const SideName& value) { s.side = to_side(value.object); })
      .def_readwrite("shape", &RoughSurface::shape)
      .def_readwrite("height_scale", &RoughSurface::height_scale)
      .def_readwrite("summit_radius", &RoughSurface::summit_radius)
      .def_readwrite("summit_density", &RoughSurface::summit_density)
      .def_readwrite("nominal_area", &RoughSurface::nominal_area)
      .def_readwrite("contact_modulus", &RoughSurface::contact_modulus)
      .def_property(
          "rms",
          [](const RoughSurface& s) {
            return s.distribution == Distribution::gaussian ? s.height_scale : s.height_scale * weibull_rms(s.shape);
          },
          [](RoughSurface& s, double rms) { s.height_scale = height_scale_from_rms(s.distribution, s.shape, rms); },
          "The rms summit height [m] (about the mean): height_scale * weibull_rms(shape) for the Weibull, height_scale\n"
          "for the Gaussian. Setting it sets height_scale for the current distribution and shape.")
      .def_property_readonly("summit_count", &RoughSurface::summit_count, "summit_density * nominal_area")
      .def("validate", &RoughSurface::validate, "Raises asperity.Error naming the first bad parameter.")
      .def("__repr__", [](const RoughSurface& s) {
        return py::str("RoughSurface(distribution='{}', side='{}', shape={!r}, height_scale={!r}, summit_radius={!r}, "
                       "summit_density={!r}, nominal_area={!r}, contact_modulus={!r})")
            .format(to_string(s.distribution), to_string(s.side), s.shape, s.height_scale, s.summit_radius,
                    s.summit_density, s.nominal_area, s.contact_modulus);
      });
  m.def("contact_modulus_from", py::vectorize(&contact_modulus_from), "young1"_a, "poisson1"_a, "young2"_a, "poisson2"_a,
        "E* from 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (broadcasts); raises asperity.Error for E <= 0 or nu\n"
        "outside (-1, 0.5].");
  m.def(
      "contact_modulus_given",
      [](std::optional<double> contact_modulus, std::optional<double> young1, std::optional<double> poisson1,
         std::optional<double> young2, std::optional<double> poisson2) -> std::optional<double> {
        const double not_given = std::numeric_limits<double>::quiet_NaN();
        const double modulus =
            contact_modulus_given(contact_modulus.value_or(not_given), young1.value_or(not_given),
                                  poisson1.value_or(not_given), young2.value_or(not_given), poisson2.value_or(not_given));
        if (std::isnan(modulus)) return std::nullopt;
        return modulus;
      },
      "contact_modulus"_a = py::none(), "young1"_a = py::none(), "poisson1"_a = py::none(), "young2"_a = py::none(),
      "poisson2"_a = py::none(),
      "E* [Pa] from what a user gave: contact_modulus itself, or young1, poisson1, young2, poisson2 together\n"
      "(the commands' check); None where none is given. Raises asperity.Error for both, the four\n"
      "incomplete, E* not positive, or a bad E or nu.");
  m.def("nominal_pressure_from_load", &nominal_pressure_from_load, "load"_a, "nominal_area"_a,
        "A total load [N] as the nominal pressure [Pa] over the nominal area [m^2]; asperity.Error for a\n"
        "load or area that is not a positive number.");
  m.def(
      "tabulated_pressure_overclosure_card",
      [](const std::vector<double>& pressures, const std::vector<double>& overclosures, const std::string& format,
         const std::string& units, const std::string& description, const std::string& notes) {
        if (pressures.size() != overclosures.size())
          throw Error("tabulated_pressure_overclosure_card: as many pressures as overclosures");
        std::vector<PressureOverclosurePoint> points(pressures.size());
        for (std::size_t i = 0; i < points.size(); ++i) points[i] = {pressures[i], overclosures[i]};
        std::ostringstream out;
        write_tabulated_pressure_overclosure(out, points, card_format(format), card_units(units), description, notes);
        return out.str();
      },
      "pressures"_a, "overclosures"_a, "format"_a = "calculix", "units"_a = "si", "description"_a = "",
      "notes"_a = "",
      "FE export of a curve given by its points (a tabulated law: the exact contact of a measured map): the\n"
      "pressure-overclosure card of CalculiX or Abaqus (format 'calculix', 'abaqus' or 'csv'; units 'si' for\n"
      "m and Pa, 'mm' for mm and MPa) as text. Points ascending in overclosure [m] (positive where the\n"
      "surfaces overlap), pressures [Pa] never falling. Raises asperity.Error for fewer than two points or\n"
      "points out of order.");
  m.def(
      "height_scale_from_rms",
      [](const DistributionName& distribution, const ArrayLike& shape, const ArrayLike& rms) -> py::object {
        const Distribution d = to_distribution(distribution.object);
        return py::vectorize([d](double a, double r) { return height_scale_from_rms(d, a, r); })(shape.object,
                                                                                                rms.object);
      },
      "distribution"_a, "shape"_a, "rms"_a,
      "The height scale sigma_s that gives an rms summit height rms (about the mean, [m]): rms / c_a for the\n"
      "Weibull, c_a = weibull_rms(shape) (for a = 1.6, rms = 0.574 sigma_s); the rms itself for the Gaussian\n"
      "(shape ignored). Broadcasts over shape and rms. Raises asperity.Error for rms or a Weibull shape <= 0.");
  m.def("gaussian_surface_from_moments", &gaussian_surface_from_moments, "m0"_a, "m2"_a, "m4"_a, "nominal_area"_a,
        "contact_modulus"_a,
        "A Gaussian RoughSurface from its profile's spectral moments (Nayak's bandwidth, McCool's summit\n"
        "statistics; docs/model.md section 6).");
  m.def("bandwidth_alpha", &bandwidth_alpha, "m0"_a, "m2"_a, "m4"_a, "Nayak's bandwidth alpha = m0 m4 / m2^2.");

  py::class_<InverseCurve>(m, "InverseCurve",
                           "The separation where X_n takes a value (n = twice_order/2 > 1/2): a tabulated inverse "
                           "and one Newton step on the curve (iterated where one is not enough: the Weibull tail side near "
                           "s = 0), ln X_n within 1e-13 (1 + |ln X_n|) of the value.")
      .def(py::init([](const Curve& curve, const OrderName& order) { return InverseCurve(curve, twice_order_of(order)); }),
           "curve"_a, "twice_order"_a,
           "The curve must hold twice_order and twice_order - 2 (asperity.Error otherwise); twice_order 2..5 or\n"
           "a quantity's name ('area', 'load', 'F2', 'F5/2'). The inverse holds the curve's data: it may outlive\n"
           "the Curve and the Table.")
      .def(
          "separation_at",
          [](const InverseCurve& inverse, const ArrayLike& value) {
            return map_scalar(value.object, "value", [&](double x) { return inverse.separation_at(x); });
          },
          "value"_a, "s with X_n(s) = value (a number or an array).")
      .def(
          "separation_at_log",
          [](const InverseCurve& inverse, const ArrayLike& log_value) {
            return map_scalar(log_value.object, "log_value", [&](double y) { return inverse.separation_at_log(y); });
          },
          "log_value"_a, "s with ln X_n(s) = log_value.")
      .def_property_readonly("twice_order", &InverseCurve::twice_order)
      .def_property_readonly("curve", &InverseCurve::curve, py::return_value_policy::copy,
                             "The curve it inverts (a handle sharing its data).")
      .def_property_readonly("memory_bytes", &InverseCurve::memory_bytes)
      .def("__copy__", [](const InverseCurve& inverse) { return inverse; })
      .def("__deepcopy__", [](const InverseCurve& inverse, py::dict) { return inverse; }, "memo"_a);

  // Units caught (asperity/plausibility.hpp): a UserWarning subclass, raised where a model is made
  static PyObject* const implausible_warning =
      PyErr_NewExceptionWithDoc("asperity.ImplausibleValueWarning",
                                "A physically implausible surface parameter, most likely a unit slip (a summit radius "
                                "over 1 mm, E* under 1 MPa, ...): the message names the value and the likely slip.",
                                PyExc_UserWarning, nullptr);
  m.attr("ImplausibleValueWarning") = py::reinterpret_borrow<py::object>(implausible_warning);
  m.def("implausible_values", &implausible_values, "surface"_a,
        "Units caught: one line per implausible parameter of the surface (a summit radius outside 1 nm..1 mm,\n"
        "sigma_s outside 0.1 nm..1 mm, a summit density outside 1e4..1e18 per m^2, E* outside 1 MPa..10 TPa, A0\n"
        "over 100 m^2, fewer than one summit, sigma_s >= R), each naming the value and the likely slip;\n"
        "empty for a plausible surface. ContactModel warns them (asperity.ImplausibleValueWarning).");
  py::class_<ContactModel>(m, "ContactModel",
                           "Contact of a flat with a RoughSurface, forward and inverse, SI units. Separations "
                           "are lengths [m] from the model's datum (docs/model.md section 2): 'origin' by default "
                           "(the Weibull origin, the Gaussian's mean), 'mean-summit' or 'mean-plane'. Where the real area "
                           "passes gw_area_fraction_limit (0.1) of the nominal area the answers come with an "
                           "asperity.AreaFractionWarning (warnings.warn), as the command warns.")
      .def(py::init([](const Table& table, const RoughSurface& surface, const std::string& datum,
                       std::optional<double> mean_summit_height) {
             SeparationDatum separation_datum;
             if (!parse_separation_datum(datum, separation_datum))
               throw py::value_error("unknown datum '" + datum + "': expected 'origin', 'mean-summit' or 'mean-plane'");
             ContactModel model(table, surface, separation_datum,
                                mean_summit_height.value_or(std::numeric_limits<double>::quiet_NaN()));
             for (const std::string& line : implausible_values(surface))
               if (PyErr_WarnEx(implausible_warning, line.c_str(), 1) != 0) throw py::error_already_set();
             for (const std::string& line : implausible_mean_summit_height(surface, model.mean_summit_height()))
               if (PyErr_WarnEx(implausible_warning, line.c_str(), 1) != 0) throw py::error_already_set();
             return model;
           }),
           "table"_a, "surface"_a, "datum"_a = separation_datum_name(default_separation_datum),
           "mean_summit_height"_a = py::none(),
           "datum: where separations (at_separation's argument, PhysicalState.separation, the inverses'\n"
           "answers) are measured from: 'origin' (the default, kept for existing code: the Weibull origin, the\n"
           "Gaussian's mean), 'mean-summit' (the mean summit height, GW's datum) or 'mean-plane' (the mean plane\n"
           "of the heights: give mean_summit_height [m], the mean summit height above it). Raises asperity.Error\n"
           "for a bad surface, a table without its curve or a bad datum; warns asperity.ImplausibleValueWarning\n"
           "for an implausible parameter (a unit slip). The model holds its curve and inverses (shared\n"
           "handles): it may outlive the Table, and copies (copy.copy) are cheap.")
      .def_property_readonly("datum", [](const ContactModel& model) { return separation_datum_name(model.datum()); },
                             "Where separations are measured from: 'origin', 'mean-summit' or 'mean-plane'.")
      .def_property_readonly(
          "mean_summit_height",
          [](const ContactModel& model) -> std::optional<double> {
            if (std::isnan(model.mean_summit_height())) return std::nullopt;
            return model.mean_summit_height();
          },
          "The mean summit height above the mean plane [m] ('mean-plane' datum), else None.")
      .def_property_readonly("datum_position", &ContactModel::datum_position,
                             "Where the datum is, as a separation in the origin convention [m].")
      // the range answered (a scene table's; everything for a full table's curves): outside, NaN
      // with asperity.OutOfRangeWarning
      .def_property_readonly("min_separation", &ContactModel::min_separation,
                             "The separations answered start here [m, the model's datum]: a scene table's range\n"
                             "(-inf for a full table's curves); outside, NaN with asperity.OutOfRangeWarning (the\n"
                             "bounded side answers every separation at or past first contact: no contact).")
      .def_property_readonly("max_separation", &ContactModel::max_separation,
                             "The separations answered end here [m] (+inf for a full table's curves).")
      .def_property_readonly("min_load", &ContactModel::min_load, "The least load answered [N] (at max_separation).")
      .def_property_readonly("max_load", &ContactModel::max_load, "The largest load answered [N] (at min_separation).")
      .def_property_readonly("min_real_area", &ContactModel::min_real_area, "The least real area answered [m^2].")
      .def_property_readonly("max_real_area", &ContactModel::max_real_area, "The largest real area answered [m^2].")
      .def(
          "at_separations",
          [](const ContactModel& model, const std::string& quantity, const ArrayLike& separation,
             const OptionalOut& out) {
            ContactQuantity q;
            if (!parse_contact_quantity(quantity, q))
              throw py::value_error("unknown quantity '" + quantity +
                                    "': expected 'count', 'real-area', 'area-fraction', 'load', 'pressure' or "
                                    "'stiffness'");
            // outside a scene table's range (answered NaN) counted first (the answer may overwrite
            // the input); a full table's model serves every separation: no pass
            const bool everywhere = model.min_separation() == -HUGE_VAL && model.max_separation() == HUGE_VAL;
            std::size_t total = 0, outside = 0;
            const auto count = [&](const double* in, std::size_t n) {
              total += n;
              if (!everywhere)
                for (std::size_t i = 0; i < n; ++i) outside += !std::isnan(in[i]) && !model.answers_separation(in[i]);
            };
            FloatOrArray answer = map_batch(
                separation.object, "separation", out.object,
                [&](const double* in, double* result, std::size_t n) {
                  count(in, n);
                  model.at_separations(q, in, result, n);
                },
                [&](double x) {
                  count(&x, 1);
                  double y;
                  model.at_separations(q, &x, &y, 1);
                  return y;
                });
            warn_out_of_range(outside, total, "separations", model_range(model, "separation"));
            return answer;
          },
          "quantity"_a, "separation"_a, py::kw_only(), "out"_a = py::none(),
          "One quantity ('count', 'real-area', 'area-fraction', 'load', 'pressure', 'stiffness') at separations\n"
          "[m] from the model's datum, through the vectorized batch lookup (no Python loop, the GIL released for\n"
          "large arrays): at_separation(d).<quantity> to the batch lookup's rounding (a few ulp of ln X), and\n"
          "exactly where that is NaN, 0 or infinite. A number gives a float, an array an array of its shape;\n"
          "out: an optional C-contiguous float64 array of the same size to write into.")
      .def("__repr__",
           [](const ContactModel& model) {
             const RoughSurface& s = model.surface();
             std::string text = std::string("<asperity.ContactModel ") + to_string(s.distribution) + " " + to_string(s.side);
             if (s.distribution == Distribution::weibull) text += " shape=" + py::repr(py::float_(s.shape)).cast<std::string>();
             text += std::string(" datum='") + separation_datum_name(model.datum()) + "'";
             if (model.datum() == SeparationDatum::mean_plane)
               text += " mean_summit_height=" + py::repr(py::float_(model.mean_summit_height())).cast<std::string>();
             if (model.datum() == default_separation_datum) text += " (the default)";
             return text + ">";
           })
      .def(
          "at_separation",
          [](const ContactModel& model, const ArrayLike& separation) {
            return physical_states(separation.object, "separation", model, [&](double d) { return model.at_separation(d); });
          },
          "separation"_a, "The PhysicalState at separations d [m] from the model's datum (a number or an array).")
      .def(
          "at_load",
          [](const ContactModel& model, const ArrayLike& load) {
            return physical_states(load.object, "load", model, [&](double p) { return model.at_load(p); });
          },
          "load"_a, "The PhysicalState carrying loads P [N]; P <= 0 is no contact.")
      .def(
          "at_pressure",
          [](const ContactModel& model, const ArrayLike& pressure) {
            return physical_states(pressure.object, "pressure", model, [&](double p) { return model.at_pressure(p); });
          },
          "pressure"_a, "The PhysicalState at nominal pressures P/A0 [Pa].")
      .def(
          "at_real_area",
          [](const ContactModel& model, const ArrayLike& area) {
            return physical_states(area.object, "real_area", model, [&](double a) { return model.at_real_area(a); });
          },
          "real_area"_a, "The PhysicalState with real contact areas A [m^2].")
      .def_property_readonly("surface", &ContactModel::surface, py::return_value_policy::copy,
                             "A copy of the surface (changing it does not change the model).")
      .def_property_readonly("curve", &ContactModel::curve, py::return_value_policy::copy,
                             "The model's curve (a handle sharing its data).")
      .def(
          "pressure_overclosure_card",
          [](const ContactModel& model, double pressure_min, double pressure_max, double tolerance,
             const std::string& format, const std::string& units, const std::string& description,
             const std::string& overclosure_datum) {
            OverclosureDatum datum;
            if (!parse_overclosure_datum(overclosure_datum, datum))
              throw py::value_error("unknown overclosure_datum '" + overclosure_datum +
                                    "': expected 'mean-summit', 'origin', 'zero-pressure' or 'mean-plane'");
            const PressureOverclosureTable table =
                tabulate_pressure_overclosure(model, pressure_min, pressure_max, tolerance, datum);
            std::ostringstream out;
            write_pressure_overclosure(out, table, card_format(format), card_units(units), description);
            warn_past_gw(model.at_pressure(pressure_max).area_fraction);  // the command's check
            return out.str();
          },
          "pressure_min"_a, "pressure_max"_a, "tolerance"_a = 1e-3, "format"_a = "calculix", "units"_a = "si",
          "description"_a = "", "overclosure_datum"_a = "mean-summit",
          "FE export: the contact-pressure law as the tabular pressure-overclosure card of CalculiX or Abaqus\n"
          "(format 'calculix', 'abaqus' or 'csv'; units 'si' for m and Pa, 'mm' for mm and MPa) as text, the\n"
          "overclosure from overclosure_datum ('mean-summit', the default: the mean summit height; 'origin';\n"
          "'zero-pressure': the card's first point; 'mean-plane': a model made with datum='mean-plane'),\n"
          "whatever the model's separation datum; linear interpolation within `tolerance` (relative, in\n"
          "pressure) of the law from pressure_min to pressure_max [Pa]. Raises asperity.Error for a bad range\n"
          "or tolerance.")
      .def("__copy__", [](const ContactModel& model) { return model; })
      .def("__deepcopy__", [](const ContactModel& model, py::dict) { return model; }, "memo"_a)
      .def(
          "dimensionless",
          [](const ContactModel& model, const ArrayLike& separation) {
            return map_scalar(separation.object, "separation", [&](double d) { return model.dimensionless(d); });
          },
          "separation"_a, "s (origin convention, units of sigma_s) of d [m] from the model's datum: d / sigma_s plus\n"
          "the datum's position / sigma_s.");

  py::class_<ContactCurves>(m, "ContactCurves",
                            "Contact curves against separation, served: a measured surface's exact contact tabulated\n"
                            "(asperity exact-contact --table; docs/exact-contact.md). Separation [m] from the table's\n"
                            "datum (separation_datum: a map's mean plane), nominal pressure [Pa], stiffness -dp/du\n"
                            "[Pa/m], real area fraction; NaN outside the range served (the first to the last node), with an\n"
                            "asperity.OutOfRangeWarning naming that range (the command refuses such a query).\n"
                            "Immutable: one object may serve many threads.")
      .def(py::init([](const PathName& path) { return ContactCurves::open(to_path(path.object)); }), "path"_a,
           "Opens and validates a contact-curves table (HDF5); raises asperity.Error naming the file and the problem.")
      .def_static("open", [](const PathName& path) { return ContactCurves::open(to_path(path.object)); }, "path"_a,
                  "The same as ContactCurves(path).")
      .def(
          "write",
          [](const ContactCurves& curves, const PathName& path, bool overwrite) {
            const std::string file = to_path(path.object);
            py::gil_scoped_release unlocked;
            write_contact_curves_file(curves.data(), file, overwrite);
          },
          "path"_a, py::kw_only(), "overwrite"_a = false,
          "Writes the curves as a contact-curves table (HDF5, with its integrity header): what ContactCurves(path),\n"
          "asperity contact --table and the C API read back. Under the output policy (docs/reliability.md,\n"
          "'Outputs'): a file there that is not a contact-curves table of asperity's is replaced only with\n"
          "overwrite=True; a link is never followed. Raises asperity.Error if it cannot be written.")
      .def(
          "pressure",
          [](ContactCurves curves, const ArrayLike& x) {  // a handle by value: read without the GIL
            return map_served(x.object, "separation", curves.min_separation(), curves.max_separation(), "m",
                              [&](double v) { return curves.pressure(v); });
          },
          "separation"_a, "The nominal pressure [Pa] at separations [m] (float or array).")
      .def(
          "stiffness",
          [](ContactCurves curves, const ArrayLike& x) {  // a handle by value: read without the GIL
            return map_served(x.object, "separation", curves.min_separation(), curves.max_separation(), "m",
                              [&](double v) { return curves.stiffness(v); });
          },
          "separation"_a, "The stiffness per area -dp/du [Pa/m] at separations [m].")
      .def(
          "area_fraction",
          [](ContactCurves curves, const ArrayLike& x) {  // a handle by value: read without the GIL
            return map_served(x.object, "separation", curves.min_separation(), curves.max_separation(), "m",
                              [&](double v) { return curves.area_fraction(v); });
          },
          "separation"_a, "The real contact area over the nominal area at separations [m].")
      .def(
          "summit_count",
          [](ContactCurves curves, const ArrayLike& x) {  // a handle by value: read without the GIL
            return map_served(x.object, "separation", curves.min_separation(), curves.max_separation(), "m",
                              [&](double v) { return curves.summit_count(v); });
          },
          "separation"_a,
          "Summits in contact per m^2 of nominal area at separations [m] (a law's table; NaN for a table without\n"
          "the count, such as a measured surface's exact contact).")
      .def(
          "separation_at_pressure",
          [](ContactCurves curves, const ArrayLike& x) {  // a handle by value: read without the GIL
            return map_served(x.object, "pressure", curves.min_pressure(), curves.max_pressure(), "Pa",
                              [&](double v) { return curves.separation_at_pressure(v); });
          },
          "pressure"_a,
          "The separation [m] where the served pressure is `pressure` [Pa] (the inverse; adhesive curves: on the\n"
          "stable branch, up to pull_off_separation); NaN outside the range (asperity.OutOfRangeWarning).")
      .def(
          "pressure_overclosure_card",
          [](const ContactCurves& curves, std::optional<double> pressure_min, std::optional<double> pressure_max,
             double tolerance, const std::string& format, const std::string& units, const std::string& description,
             const std::string& datum) {
            OverclosureDatum which;
            if (!parse_overclosure_datum(datum, which))
              throw Error("unknown overclosure datum '" + datum + "' (mean-summit, origin, zero-pressure, mean-plane)");
            const PressureOverclosureTable table = tabulate_pressure_overclosure(
                curves, pressure_min.value_or(curves.min_pressure()), pressure_max.value_or(curves.max_pressure()),
                tolerance, which);
            std::ostringstream out;
            write_pressure_overclosure(out, table, card_format(format), card_units(units), description);
            return out.str();
          },
          "pressure_min"_a = py::none(), "pressure_max"_a = py::none(), "tolerance"_a = 1e-3, "format"_a = "calculix",
          "units"_a = "si", "description"_a = "", "datum"_a = "mean-summit",
          "FE export: the served pressure as the tabular pressure-overclosure card of CalculiX or Abaqus (or CSV),\n"
          "overclosure from the mean summit height (datum 'mean-summit'), or 'origin' (the separation's datum) or\n"
          "'zero-pressure'; the pressures default to the whole range served. Raises asperity.Error for a range\n"
          "beyond the curves' or a bad tolerance.")
      .def_property_readonly("min_separation", &ContactCurves::min_separation)
      .def_property_readonly("max_separation", &ContactCurves::max_separation)
      .def_property_readonly("min_pressure", &ContactCurves::min_pressure,
                             "The least pressure the inverse serves [Pa]: at max_separation (adhesive curves: the\n"
                             "pull-off's, or at the stable branch's end).")
      .def_property_readonly("max_pressure", &ContactCurves::max_pressure, "At min_separation [Pa].")
      .def_property_readonly("has_tension", &ContactCurves::has_tension,
                             "Adhesive curves (an adhesive law's table): the pressure served is signed (negative:\n"
                             "tension), the stored pressure and stiffness bounds relative to the gross.")
      .def_property_readonly("pull_off_pressure", &ContactCurves::pull_off_pressure,
                             "Adhesive curves: the greatest tension [Pa, < 0]; NaN without tension or where it is\n"
                             "not inside the range.")
      .def_property_readonly("pull_off_separation", &ContactCurves::pull_off_separation,
                             "Adhesive curves: the separation [m] of the greatest tension (the net stiffness 0).")
      .def_property_readonly("limited_intervals", &ContactCurves::limited_intervals,
                             "Intervals whose Hermite slopes were limited to keep ln p monotone.")
      .def_property_readonly(
          "max_rel_error",
          [](const ContactCurves& c) {
            const double* e = c.data().max_rel_error;
            return py::make_tuple(e[0], e[1], e[2]);
          },
          "The stored bound (relative) of the served (pressure, stiffness, area fraction): measured_rel_error\n"
          "times safety_factor.")
      .def_property_readonly(
          "measured_rel_error",
          [](const ContactCurves& c) {
            const double* e = c.data().measured_rel_error;
            return py::make_tuple(e[0], e[1], e[2]);
          },
          "The largest relative errors measured against exact solves between the nodes (check_points of them).")
      .def_property_readonly("check_points", [](const ContactCurves& c) { return c.data().check_points; })
      .def_property_readonly("safety_factor", [](const ContactCurves& c) { return c.data().safety_factor; })
      .def_property_readonly("solver_tolerance", [](const ContactCurves& c) { return c.data().solver_tolerance; },
                             "The solves' own convergence tolerance (relative residual).")
      .def_property_readonly("contact_modulus", [](const ContactCurves& c) { return c.data().contact_modulus; })
      .def_property_readonly("nominal_area", [](const ContactCurves& c) { return c.data().nominal_area; })
      .def_property_readonly("mean_summit_height", [](const ContactCurves& c) { return c.data().mean_summit_height; },
                             "Above the separation's datum [m] (NaN: not stated).")
      .def_property_readonly("max_height", [](const ContactCurves& c) { return c.data().max_height; },
                             "The highest point above the separation's datum [m] (NaN: not stated).")
      .def_property_readonly("source", [](const ContactCurves& c) { return c.data().source; })
      .def_property_readonly("description", [](const ContactCurves& c) { return path_text(c.data().description); })
      .def_property_readonly("separation_datum", [](const ContactCurves& c) { return c.data().separation_datum; })
      .def_property_readonly("generator", [](const ContactCurves& c) { return c.data().generator; })
      .def_property_readonly("generator_options", [](const ContactCurves& c) { return c.data().generator_options; })
      .def_property_readonly(
          "nodes",
          [](const ContactCurves& c) {
            const ContactCurvesData& d = c.data();
            py::dict nodes;
            nodes["separation"] = py::array_t<double>(d.separation.size(), d.separation.data());
            nodes["pressure"] = py::array_t<double>(d.pressure.size(), d.pressure.data());
            nodes["stiffness"] = py::array_t<double>(d.stiffness.size(), d.stiffness.data());
            nodes["area_fraction"] = py::array_t<double>(d.area_fraction.size(), d.area_fraction.data());
            if (d.has_tension()) {
              nodes["tensile_pressure"] = py::array_t<double>(d.tensile_pressure.size(), d.tensile_pressure.data());
              nodes["tensile_stiffness"] = py::array_t<double>(d.tensile_stiffness.size(), d.tensile_stiffness.data());
            }
            if (!d.summit_count.empty())
              nodes["summit_count"] = py::array_t<double>(d.summit_count.size(), d.summit_count.data());
            return nodes;
          },
          "The table's nodes: arrays separation, pressure, stiffness, area_fraction (copies); where stored,\n"
          "tensile_pressure and tensile_stiffness (adhesive curves: pressure and stiffness are then the\n"
          "compressive parts) and summit_count.")
      .def("__copy__", [](const ContactCurves& c) { return c; })
      .def("__deepcopy__", [](const ContactCurves& c, py::dict) { return c; }, "memo"_a)
      .def("__repr__", [](const ContactCurves& c) {
        std::ostringstream text;
        text << "<asperity.ContactCurves of " << c.data().source << ": " << c.data().separation.size()
             << " nodes, separations " << c.min_separation() << " to " << c.max_separation() << " m>";
        return text.str();
      });

  py::class_<PerssonLaw>(m, "PerssonLaw",
                         "Persson's (2007) law for comparison: p = reference_pressure exp(-s / beta).")
      .def(py::init([](double beta, double reference_pressure) { return PerssonLaw{beta, reference_pressure}; }),
           "beta"_a = 0.5, "reference_pressure"_a = 1.0)
      .def_readwrite("beta", &PerssonLaw::beta)
      .def_readwrite("reference_pressure", &PerssonLaw::reference_pressure)
      .def(
          "pressure",
          [](PerssonLaw law, const ArrayLike& s) {  // by value: read without the GIL
            return map_scalar(s.object, "separation", [&](double x) { return law.pressure(x); });
          },
          "separation"_a)
      .def(
          "separation_at",
          [](PerssonLaw law, const ArrayLike& p) {
            return map_scalar(p.object, "pressure", [&](double x) { return law.separation_at(x); });
          },
          "pressure"_a)
      .def("stiffness_over_load", &PerssonLaw::stiffness_over_load, "The constant 1/beta.");

  // ---- scenes (asperity/scene.hpp, scene_curves.hpp) ----
  py::class_<SceneCurve>(m, "SceneCurve", "One curve a scene asks for.")
      .def_readonly("name", &SceneCurve::name)
      .def_readonly("distribution", &SceneCurve::distribution)
      .def_readonly("side", &SceneCurve::side)
      .def_readonly("shape", &SceneCurve::shape)
      .def_readonly("twice_orders", &SceneCurve::twice_orders)
      .def_readonly("by_load", &SceneCurve::by_load, "The range is of X_3/2, not of separation.")
      .def_readonly("range_min", &SceneCurve::range_min)
      .def_readonly("range_max", &SceneCurve::range_max)
      .def_readonly("max_rel_error", &SceneCurve::max_rel_error)
      .def_readonly("line", &SceneCurve::line, "Where the curve starts in the file.");
  py::class_<Scene>(m, "Scene", "The few curves one program needs (docs/scenes.md).")
      .def_readonly("name", &Scene::name)
      .def_property_readonly("source", [](const Scene& scene) { return path_text(scene.source); })
      .def_readonly("memory_budget_bytes", &Scene::memory_budget_bytes)
      .def_readonly("curves", &Scene::curves);
  py::class_<SceneCurveView>(m, "SceneCurveView", "A scene's curve served from a table.")
      .def_readonly("spec", &SceneCurveView::spec)
      .def_readonly("curve", &SceneCurveView::curve)
      .def_readonly("separation_min", &SceneCurveView::separation_min)
      .def_readonly("separation_max", &SceneCurveView::separation_max)
      .def_readonly("error_bound", &SceneCurveView::error_bound, "The table's error bound for these orders here.");
  m.def("read_scene_file", [](const PathName& path) { return read_scene_file(to_path(path.object)); }, "path"_a,
        "Reads a scene file (TOML); asperity.Error names the file, the line and the key.");
  m.def("parse_scene", &parse_scene, "text"_a, "source"_a = "<string>", "A scene from TOML text.");
  m.def("serve_scene", &serve_scene, "table"_a, "scene"_a,
        "The scene's curves from a table (a scene table, or any full table such as the default).");
  m.def(
      "separation_at_load",
      [](const Curve& curve, const ArrayLike& load) {
        return map_scalar(load.object, "load", [&](double x) { return separation_at_load(curve, x); });
      },
      "curve"_a, "load"_a, "The separation where X_3/2 = load (NaN if not reached).");
  m.def("quantity_twice_order", &quantity_twice_order, "quantity"_a,
        "twice_order of a quantity's integral: count 0, stiffness 1, area 2, load 3, F2 4, F5/2 5; -1 otherwise.");

  // the former names (deprecated, kept for existing code): Surface is SurfaceScales (contact_at's four
  // scales), PhysicalSurface is RoughSurface (ContactModel's surface in SI units)
  m.attr("Surface") = m.attr("SurfaceScales");
  m.attr("PhysicalSurface") = m.attr("RoughSurface");

  // ---- measured surfaces (asperity/topography/*.hpp): the submodule asperity.topography ----
  bind_topography(m, physical_state_type);
  bind_law_curves(m);
  bind_output(m);
}

}  // namespace asperity::python

PYBIND11_MODULE(_asperity, m) {
  // Types made while the module calls itself "asperity" are named asperity.Curve, ... in
  // signatures, messages and help(), as users import them.
  const py::object name = m.attr("__name__");
  m.attr("__name__") = "asperity";
  asperity::python::bind(m);
  m.attr("__name__") = name;
}
