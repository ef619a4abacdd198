// asperity.ContactCurves (asperity/contact_curves.hpp): a contact-curves table, served.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <limits>
#include <optional>
#include <sstream>
#include <string>

#include "bindings.hpp"
#include "card_settings.hpp"
#include "helpers.hpp"
#include "paths.hpp"
#include "asperity/contact_curves.hpp"
#include "asperity/pressure_overclosure.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace asperity::python {



namespace {

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

// The state (ContactCurvesState: floats, or arrays shaped like the input) at separations or pressures
// `input`, as map_served warns of those outside [lo, hi]
template <class Answer>
py::object curves_states(py::handle input, const char* name, double lo, double hi, const char* unit, Answer answer) {
  constexpr std::size_t fields = RecordFields<ContactCurvesState>::count;
  std::size_t total = 0, outside = 0;
  py::object record = make_record(contact_curves_state_type,
                                  map_records<fields>(input, name, [&](double x, double** out, std::size_t i) {
                                    ++total;
                                    outside += !std::isnan(x) && !(x >= lo && x <= hi);
                                    ContactCurvesState state = answer(x);
                                    std::size_t k = 0;
                                    RecordFields<ContactCurvesState>::for_each(
                                        state, [&](const RecordField&, double& value) { out[k++][i] = value; });
                                  }));
  if (outside > 0)
    warn_out_of_range(outside, total, (std::string(name) + "s").c_str(),
                      std::string(name) + "s " + g(lo) + " to " + g(hi) + " " + unit);
  return record;
}

// the served curves and their inverse at separations (pressures), and the FE card
void bind_contact_curves_queries(py::class_<ContactCurves>& contact_curves) {
  contact_curves
      .def(
          "at_separation",
          [](ContactCurves curves, const ArrayLike& x) {  // a handle by value: read without the GIL
            return curves_states(x.object, "separation", curves.min_separation(), curves.max_separation(), "m",
                                 [&](double v) { return curves.at_separation(v); });
          },
          "separation"_a,
          "The ContactCurvesState (separation, pressure, stiffness per area, area_fraction) at separations [m]\n"
          "(float or array), as ContactModel.at_separation gives a PhysicalState; NaN outside the range\n"
          "(asperity.OutOfRangeWarning).")
      .def(
          "at_pressure",
          [](ContactCurves curves, const ArrayLike& x) {  // a handle by value: read without the GIL
            return curves_states(x.object, "pressure", curves.min_pressure(), curves.max_pressure(), "Pa",
                                 [&](double v) { return curves.at_pressure(v); });
          },
          "pressure"_a,
          "The ContactCurvesState at nominal pressures [Pa] (float or array), as ContactModel.at_pressure gives a\n"
          "PhysicalState: the separation where the served pressure is that (adhesive curves: on the stable\n"
          "branch) and the curves there; NaN outside [min_pressure, max_pressure] (asperity.OutOfRangeWarning).")
;
  // the served curves at separations [m] (float or array), a binding each from this list
  using Served = double (ContactCurves::*)(double) const noexcept;
  const struct {
    const char* name;
    Served curve;
    const char* doc;
  } curves_at_separations[] = {
      {"pressure", &ContactCurves::pressure, "The nominal pressure [Pa] at separations [m] (float or array)."},
      {"stiffness", &ContactCurves::stiffness, "The stiffness per area -dp/du [Pa/m] at separations [m]."},
      {"area_fraction", &ContactCurves::area_fraction, "The real contact area over the nominal area at separations [m]."},
      {"summit_count", &ContactCurves::summit_count,
       "Summits in contact per m^2 of nominal area at separations [m] (a law's table; NaN for a table without\n"
       "the count, such as a measured surface's exact contact)."},
  };
  for (const auto& served : curves_at_separations)
    contact_curves.def(
        served.name,
        [curve = served.curve](ContactCurves curves, const ArrayLike& x) {  // a handle by value: read without the GIL
          return map_served(x.object, "separation", curves.min_separation(), curves.max_separation(), "m",
                            [&](double v) { return (curves.*curve)(v); });
        },
        "separation"_a, served.doc);
  contact_curves
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
             const std::string& overclosure_datum, std::optional<long long> max_points, std::optional<double> face_size,
             std::optional<std::string> datum) {
            // `datum`: this method's keyword before ContactModel's name was taken for both
            const char* keyword = "overclosure_datum";
            std::string chosen = overclosure_datum;
            if (datum) {
              if (overclosure_datum != "zero-pressure" && *datum != overclosure_datum)
                throw py::value_error("give the overclosure datum once: overclosure_datum ('datum' is its old name)");
              PyErr_WarnEx(PyExc_DeprecationWarning,
                           "ContactCurves.pressure_overclosure_card: 'datum' is now 'overclosure_datum' (as "
                           "ContactModel's and the command's --overclosure-datum)",
                           1);
              if (PyErr_Occurred()) throw py::error_already_set();
              keyword = "datum";
              chosen = *datum;
            }
            const CardSettings settings = card_settings(format, units, keyword, chosen, max_points, face_size);
            const PressureOverclosureTable table = tabulate_pressure_overclosure(
                curves, pressure_min.value_or(curves.min_pressure()), pressure_max.value_or(curves.max_pressure()),
                tolerance, settings.datum, settings.max_points);
            return card_text(table, settings, description);
          },
          "pressure_min"_a = py::none(), "pressure_max"_a = py::none(), "tolerance"_a = 1e-3, "format"_a = "calculix",
          "units"_a = "si", "description"_a = "", "overclosure_datum"_a = "zero-pressure", "max_points"_a = py::none(),
          "face_size"_a = py::none(), "datum"_a = py::none(),
          "FE export: the served pressure as the tabular pressure-overclosure card of CalculiX or Abaqus (or CSV),\n"
          "as `asperity contact --table FILE --export` writes it: overclosure from where the card's pressure\n"
          "reaches zero (overclosure_datum 'zero-pressure', the default), or 'mean-summit' (the mean summit height)\n"
          "or 'origin' (the separation's datum); the pressures default to the whole range served; max_points and\n"
          "face_size as ContactModel.pressure_overclosure_card's ('datum' is overclosure_datum's old name:\n"
          "DeprecationWarning). Raises asperity.Error for a range beyond the curves' or a bad tolerance, ValueError\n"
          "for a bad option.");
}

// the table's bounds, provenance and nodes
void bind_contact_curves_properties(py::class_<ContactCurves>& contact_curves) {
  contact_curves
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
      .def_property_readonly("approach_separation",
                             [](const ContactCurves& c) { return c.data().approach_separation; },
                             "Adhesive curves: the separation [m] of the approach their withdrawal (unloading, fixed\n"
                             "grips) branch follows, at or below min_separation; NaN for the approach (loading)\n"
                             "branch or curves without tension. Finite: the pull-off is the withdrawal's.")
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
          "summit_count_max_rel_error",
          [](const ContactCurves& c) {
            return c.data().summit_count.empty() ? std::numeric_limits<double>::quiet_NaN()
                                                 : c.data().summit_count_max_rel_error;
          },
          "The stored bound (relative) of the served summit_count (a law's table; NaN for a table without the\n"
          "count). On a Weibull tail it may exceed the asked error (the count's quadrature there is harder).")
      .def_property_readonly(
          "measured_rel_error",
          [](const ContactCurves& c) {
            const double* e = c.data().measured_rel_error;
            return py::make_tuple(e[0], e[1], e[2]);
          },
          "The largest relative errors measured against exact solves between the nodes (check_points of them).")
      .def_property_readonly("check_points", [](const ContactCurves& c) { return c.data().check_points; })
      .def_property_readonly(
          "bound_method", [](const ContactCurves& c) { return std::string(to_string(c.data().bound_method)); },
          "How the stored bound was measured: 'checks-until-settled' (a map's exact contact),\n"
          "'checks-split-to-tolerance' (a law's curves), or 'unstated' (a table written before it was stored).")
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
}

}  // namespace

void bind_contact_curves(py::module_& m) {
  py::class_<ContactCurves> contact_curves(m, "ContactCurves",
                            "Contact curves against separation, served: a measured surface's exact contact tabulated\n"
                            "(asperity exact-contact --table; docs/exact-contact.md). Separation [m] from the table's\n"
                            "datum (separation_datum: a map's mean plane), nominal pressure [Pa], stiffness -dp/du\n"
                            "[Pa/m], real area fraction; NaN outside the range served (the first to the last node), with an\n"
                            "asperity.OutOfRangeWarning naming that range (the command refuses such a query).\n"
                            "Immutable: one object may serve many threads.");
  contact_curves
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
          "overwrite=True; a link is never followed. Raises asperity.Error if it cannot be written.");
  bind_contact_curves_queries(contact_curves);
  bind_contact_curves_properties(contact_curves);
}

}  // namespace asperity::python
