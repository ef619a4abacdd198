// The contact of a measured surface by theory (asperity/topography/persson_contact.hpp,
// contact_comparison.hpp): Persson's theory of its spectrum, the contact curves of the fits side by side.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "record_bindings.hpp"
#include "topography_helpers.hpp"
#include "asperity/topography/contact_comparison.hpp"
#include "asperity/topography/persson_contact.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace asperity::python {

namespace topo = asperity::topography;

namespace {

// PhysicalStates as the asperity.PhysicalState record of arrays.
py::object states_record(py::handle type, const std::vector<PhysicalState>& states) {
  constexpr std::size_t fields = physical_state_field_count;
  std::vector<py::array_t<double>> arrays;
  for (std::size_t k = 0; k < fields; ++k) arrays.emplace_back(static_cast<py::ssize_t>(states.size()));
  for (std::size_t i = 0; i < states.size(); ++i) {
    const PhysicalState& s = states[i];
    for (std::size_t k = 0; k < fields; ++k) arrays[k].mutable_data()[i] = s.*physical_state_members[k];
  }
  py::tuple arguments(fields);
  for (std::size_t k = 0; k < fields; ++k) arguments[k] = arrays[k];
  return type(*arguments);
}

}  // namespace

void bind_persson_contact(py::module_& m) {
  // ---- Persson's theory of a map's spectrum (persson_contact.hpp) ----
  py::class_<topo::RadialPowerSpectrum> spectrum(
      m, "RadialPowerSpectrum",
      "The isotropic power spectral density C(q) of a map [m^4] (integral d^2q C = variance), constant over\n"
      "annuli [edges[k], edges[k + 1]) one wavenumber step 2 pi / L wide.");
  def_record_fields(spectrum);  // its fields from its list (persson_contact.hpp)
  m.def(
      "radial_power_spectrum",
      [](const topo::HeightMap& map, const std::string& edges) {
        topo::SpectrumEdges treatment;
        if (edges == "none") treatment = topo::SpectrumEdges::none;
        else if (edges == "hann") treatment = topo::SpectrumEdges::hann;
        else if (edges == "periodic_component") treatment = topo::SpectrumEdges::periodic_component;
        else throw py::value_error("edges must be 'none', 'hann' or 'periodic_component', not '" + edges + "'");
        return without_gil([copy = map, treatment] { return topo::radial_power_spectrum(copy, treatment); });
      },
      "map"_a, "edges"_a = "periodic_component",
      "The radial power spectrum of a map. edges: 'periodic_component' (Moisan's periodic component: a\n"
      "measured map), 'hann' (a Hann window each way) or 'none' (the map taken as periodic).");
  // the curves' names a ContactComparison holds (ModelContact.label), as the JSON documents spell
  // them (contact_comparison.hpp's one table), in ContactModelKind's order
  py::list contact_model_names;
  for (topo::ContactModelKind kind : topo::all_contact_model_kinds) contact_model_names.append(topo::to_string(kind));
  m.attr("contact_model_names") = py::tuple(contact_model_names);
  // the fewest measured summits in contact at a pressure for a closest model to be named there
  m.attr("MIN_SUMMITS_TO_COMPARE") = topo::min_summits_to_compare;
  m.attr("EXACT_AUTO_MAX_POINTS") = topo::exact_auto_max_points;
  py::class_<topo::PerssonState> persson_state(m, "PerssonState", "Persson's theory at one nominal pressure (SI units).");
  // its fields from their one list (PerssonState's, persson_contact.hpp), each with its meaning
#define ASPERITY_BIND_FIELD(type, name, column, meaning) persson_state.def_readonly(#name, &topo::PerssonState::name, meaning);
  ASPERITY_PERSSON_STATE_FIELDS(ASPERITY_BIND_FIELD)
#undef ASPERITY_BIND_FIELD
  py::class_<topo::PerssonContact>(
      m, "PerssonContact",
      "Persson's theory of contact (2007; Yang and Persson 2008) from a radial power spectrum: mean gap, real\n"
      "area and stiffness against nominal pressure.")
      .def(py::init([](const topo::RadialPowerSpectrum& spectrum, double contact_modulus, double gamma) {
             return topo::PerssonContact(spectrum, contact_modulus, gamma);
           }),
           "spectrum"_a, py::kw_only(), "contact_modulus"_a, "gamma"_a = topo::yang_persson_gamma)
      .def("at_pressure", &topo::PerssonContact::at_pressure, "pressure"_a,
           "The state at a nominal pressure [Pa] > 0 (NaN fields otherwise).", py::call_guard<py::gil_scoped_release>())
      .def_property_readonly("contact_modulus", &topo::PerssonContact::contact_modulus)
      .def_property_readonly("gamma", &topo::PerssonContact::gamma)
      .def_property_readonly("area_slope", &topo::PerssonContact::area_slope,
                             "A/A0 -> area_slope p / E* as p -> 0 (sqrt(8/pi) / h'_rms).");
}

void bind_contact_comparison(py::module_& m) {
  // ---- contact curves of the fits (contact_comparison.hpp) ----
  py::class_<topo::ContactOptions>(m, "ContactOptions", "The contact curves of each fit.")
      .def(py::init([](double contact_modulus, double nominal_area, std::vector<double> pressures, int curve_points,
                       double scene_tolerance, const PathName& table_path, int threads, bool persson,
                       std::optional<bool> exact,
                       const std::string& exact_boundary, const std::string& exact_kernel, int exact_points,
                       double exact_tolerance) {
             topo::ContactOptions options;
             options.contact_modulus = contact_modulus;
             options.nominal_area = nominal_area;
             options.pressures = std::move(pressures);
             options.curve_points = curve_points;
             options.scene_tolerance = scene_tolerance;
             options.table_path = to_path(table_path.object, "table_path");
             options.threads = threads;
             options.persson = persson;
             options.exact = exact.value_or(false);  // None: by the map's size (exact_auto)
             options.exact_auto = !exact.has_value();
             if (!topo::parse_contact_boundary(exact_boundary, options.exact_boundary))
               throw py::value_error("exact_boundary must be 'periodic' or 'padded', not '" + exact_boundary + "'");
             if (!topo::parse_contact_kernel(exact_kernel, options.exact_kernel))
               throw py::value_error("exact_kernel must be 'fourier' or 'love', not '" + exact_kernel + "'");
             options.exact_points = exact_points;
             options.exact_tolerance = exact_tolerance;
             return options;
           }),
           "contact_modulus"_a, "nominal_area"_a = 0.0, "pressures"_a = std::vector<double>{}, "curve_points"_a = 61,
           "scene_tolerance"_a = 1e-8, "table_path"_a = "", "threads"_a = 0, "persson"_a = true, "exact"_a = py::none(),
           "exact_boundary"_a = "padded", "exact_kernel"_a = "love", "exact_points"_a = 13, "exact_tolerance"_a = 1e-8,
           "contact_modulus E* [Pa] (plane strain); nominal_area A0 [m^2] (0: the measured area); pressures of\n"
           "interest [Pa] (empty: E* x 1e-5, 1e-4, 1e-3); table_path: a full table for the Weibull curves\n"
           "instead of exact-shape scene tables made for the fitted shapes; persson: Persson's theory of the\n"
           "map's spectrum beside them; exact: the exact elastic contact of the map (boundary elements,\n"
           "exact_boundary 'padded' or 'periodic', exact_kernel 'love' or 'fourier', exact_points solves along\n"
           "the pressure range), which every curve is then compared with: True at any size, False never, None\n"
           "(the default) where the map has at most EXACT_AUTO_MAX_POINTS points.")
      .def_readwrite("contact_modulus", &topo::ContactOptions::contact_modulus)
      .def_readwrite("nominal_area", &topo::ContactOptions::nominal_area)
      .def_readwrite("pressures", &topo::ContactOptions::pressures)
      .def_readwrite("curve_points", &topo::ContactOptions::curve_points)
      .def_readwrite("scene_tolerance", &topo::ContactOptions::scene_tolerance)
      .def_property(
          "table_path", [](const topo::ContactOptions& o) { return path_text(o.table_path); },
          [](topo::ContactOptions& o, const PathName& value) { o.table_path = to_path(value.object, "table_path"); })
      .def_readwrite("threads", &topo::ContactOptions::threads)
      .def_readwrite("persson", &topo::ContactOptions::persson)
      .def_property(
          "exact",
          [](const topo::ContactOptions& o) -> std::optional<bool> {
            if (o.exact) return true;
            if (!o.exact_auto) return false;
            return std::nullopt;
          },
          [](topo::ContactOptions& o, std::optional<bool> value) {
            o.exact = value.value_or(false);
            o.exact_auto = !value.has_value();
          },
          "True: solved at any size; False: never; None: where the map has at most EXACT_AUTO_MAX_POINTS points.")
      .def_property(
          "exact_boundary", [](const topo::ContactOptions& o) { return std::string(topo::contact_boundary_name(o.exact_boundary)); },
          [](topo::ContactOptions& o, const std::string& name) {
            if (!topo::parse_contact_boundary(name, o.exact_boundary))
              throw py::value_error("exact_boundary must be 'periodic' or 'padded', not '" + name + "'");
          })
      .def_property(
          "exact_kernel", [](const topo::ContactOptions& o) { return std::string(topo::contact_kernel_name(o.exact_kernel)); },
          [](topo::ContactOptions& o, const std::string& name) {
            if (!topo::parse_contact_kernel(name, o.exact_kernel))
              throw py::value_error("exact_kernel must be 'fourier' or 'love', not '" + name + "'");
          })
      .def_readwrite("exact_points", &topo::ContactOptions::exact_points)
      .def_readwrite("exact_tolerance", &topo::ContactOptions::exact_tolerance);
  // ModelContact's, SamplingContact's and ContactComparison's attributes from their lists
  // (contact_comparison.hpp), each with its meaning; the states as one asperity.PhysicalState of
  // arrays, the note as a path's text, the summits in contact as a list (as before the lists)
  py::class_<topo::ModelContact> model_contact(m, "ModelContact", "The contact curve of one height model.");
  model_contact
      .def_property_readonly("label", &topo::ModelContact::label,
                    "Its kind's name: measured-summits, measured-summits-own-radii, gaussian-moments, gaussian, weibull-tail,\n"
                    "weibull-bounded, persson or exact.")
      .def_property_readonly("note", [](const topo::ModelContact& c) { return path_text(c.note); },
                             record_meaning<topo::ModelContact>("note"))
      .def_property_readonly("curve", [](const topo::ModelContact& c) {
        return states_record(physical_state_type, c.curve);
      }, record_meaning<topo::ModelContact>("curve"))
      .def_property_readonly("at_pressures", [](const topo::ModelContact& c) {
        return states_record(physical_state_type, c.at_pressures);
      }, record_meaning<topo::ModelContact>("at_pressures"));
  def_record_fields(model_contact);
  py::class_<topo::SamplingContact> sampling_contact(
      m, "SamplingContact", "The measured-summit answer at a coarser sampling (every factor-th point).");
  def_record_fields(sampling_contact);
  py::class_<topo::ContactComparison> comparison(m, "ContactComparison", "The contact curves of the fits side by side.");
  comparison
      .def_property_readonly(
          "measured_summits_in_contact",
          [](const topo::ContactComparison& c) { return std::vector<std::size_t>(c.measured_summits_in_contact); },
          record_meaning<topo::ContactComparison>("measured_summits_in_contact"))
      .def_property_readonly(
          "compared_at_pressures",
          [](const topo::ContactComparison& c) {
            std::vector<bool> compared;
            for (std::size_t k = 0; k < c.pressures.size(); ++k) compared.push_back(c.compared_at(k));
            return compared;
          },
          "At each pressure: at least MIN_SUMMITS_TO_COMPARE measured summits in contact, so models are compared there.");
  def_record_fields(comparison)
      .def(
          "find",
          [](const topo::ContactComparison& c, const std::string& label) -> std::optional<topo::ModelContact> {
            const topo::ModelContact* found = c.find(label);
            return found ? std::optional<topo::ModelContact>(*found) : std::nullopt;
          },
          "label"_a, "The model of that label, or None.");
}

}  // namespace asperity::python
