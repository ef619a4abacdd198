// asperity.ContactModel (asperity/contact_model.hpp): a rough surface's contact in SI units, with the
// warnings of implausible units and of areas past Greenwood-Williamson's range.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <sstream>
#include <string>

#include "bindings.hpp"
#include "card_settings.hpp"
#include "helpers.hpp"
#include "asperity/contact_model.hpp"
#include "asperity/plausibility.hpp"
#include "asperity/pressure_overclosure.hpp"
#include "asperity/separation_datum.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace asperity::python {

namespace {

// asperity.ImplausibleValueWarning (a UserWarning), made once at import (bind_contact_model).
PyObject* implausible_warning = nullptr;

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

// the queries: a quantity by the batch path, the PhysicalState at separations, loads, pressures, areas
void bind_contact_model_queries(py::class_<ContactModel>& contact_model) {
  contact_model
      .def(
          "at_separations",
          [](const ContactModel& model, const std::string& quantity, const ArrayLike& separation,
             const OptionalOut& out) {
            ContactQuantity q;
            if (!parse_contact_quantity(quantity, q))
              throw py::value_error("unknown quantity '" + quantity +
                                    "': expected 'count', 'real-area', 'area-fraction', 'load', 'pressure' or "
                                    "'stiffness' (or the field's spelling: 'real_area', 'area_fraction')");
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
          "real_area"_a, "The PhysicalState with real contact areas A [m^2].");
}

// what a model gives beyond its answers: its surface and curve, its FE card, copies, s from d

void bind_contact_model_export(py::class_<ContactModel>& contact_model) {
  contact_model
      .def_property_readonly("surface", &ContactModel::surface, py::return_value_policy::copy,
                             "A copy of the surface (changing it does not change the model).")
      .def_property_readonly("curve", &ContactModel::curve, py::return_value_policy::copy,
                             "The model's curve (a handle sharing its data).")
      .def(
          "pressure_overclosure_card",
          [](const ContactModel& model, double pressure_min, double pressure_max, double tolerance,
             const std::string& format, const std::string& units, const std::string& description,
             const std::string& overclosure_datum, std::optional<long long> max_points,
             std::optional<double> face_size) {
            const CardSettings settings =
                card_settings(format, units, "overclosure_datum", overclosure_datum, max_points, face_size);
            const PressureOverclosureTable table = tabulate_pressure_overclosure(
                model, pressure_min, pressure_max, tolerance, settings.datum, settings.max_points);
            const std::string card = card_text(table, settings, description);
            warn_past_gw(model.at_pressure(pressure_max).area_fraction);  // the command's check
            return card;
          },
          "pressure_min"_a, "pressure_max"_a, "tolerance"_a = 1e-3, "format"_a = "calculix", "units"_a = "si",
          "description"_a = "", "overclosure_datum"_a = "zero-pressure", "max_points"_a = py::none(),
          "face_size"_a = py::none(),
          "FE export: the contact-pressure law as the tabular pressure-overclosure card of CalculiX or Abaqus\n"
          "(format 'calculix', 'abaqus' or 'csv'; units 'si' for m and Pa, 'mm' for mm and MPa) as text, as\n"
          "`asperity contact --export` writes it: the overclosure from overclosure_datum ('zero-pressure', the\n"
          "default: the card's first point, start the model with the surfaces touching; 'mean-summit': the mean\n"
          "summit height; 'origin'; 'mean-plane': a model made with datum='mean-plane'), whatever the model's\n"
          "separation datum; linear interpolation within `tolerance` (relative, in pressure) of the law from\n"
          "pressure_min to pressure_max [Pa], in at most max_points rows (None: 200 for calculix, what its\n"
          "node-to-surface contact holds, no cap otherwise; a tolerance that needs more is loosened, as the\n"
          "header says). face_size: the slave faces' edge in the card's units (calculix only): warns (UserWarning,\n"
          "and in the header) where the card reaches beyond CalculiX's contact-spring cut-off 1e-3 face_size.\n"
          "Raises asperity.Error for a bad range or tolerance, ValueError for a bad option.")
      .def("__copy__", [](const ContactModel& model) { return model; })
      .def("__deepcopy__", [](const ContactModel& model, py::dict) { return model; }, "memo"_a)
      .def(
          "dimensionless",
          [](const ContactModel& model, const ArrayLike& separation) {
            return map_scalar(separation.object, "separation", [&](double d) { return model.dimensionless(d); });
          },
          "separation"_a, "s (origin convention, units of sigma_s) of d [m] from the model's datum: d / sigma_s plus\n"
          "the datum's position / sigma_s.");
}

}  // namespace

void bind_contact_model(py::module_& m) {
  // Units caught (asperity/plausibility.hpp): a UserWarning subclass, raised where a model is made
  implausible_warning =
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
  py::class_<ContactModel> contact_model(m, "ContactModel",
                           "Contact of a flat with a RoughSurface, forward and inverse, SI units. Separations "
                           "are lengths [m] from the model's datum (docs/model.md section 2): 'origin' by default "
                           "(the Weibull origin, the Gaussian's mean), 'mean-summit' or 'mean-plane'. Where the real area "
                           "passes gw_area_fraction_limit (0.1) of the nominal area the answers come with an "
                           "asperity.AreaFractionWarning (warnings.warn), as the command warns.");
  contact_model
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
      .def_property_readonly("max_real_area", &ContactModel::max_real_area, "The largest real area answered [m^2].");
  bind_contact_model_queries(contact_model);
  bind_contact_model_export(contact_model);
}

}  // namespace asperity::python
