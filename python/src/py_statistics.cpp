// Leveling, height statistics, spectral moments, correlation lengths and summits
// (asperity/topography/leveling.hpp, statistics.hpp, summits.hpp).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <optional>

#include "bindings.hpp"
#include "record_bindings.hpp"
#include "topography_helpers.hpp"
#include "asperity/topography/height_map.hpp"
#include "asperity/topography/leveling.hpp"
#include "asperity/topography/statistics.hpp"
#include "asperity/topography/summits.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace asperity::python {

namespace topo = asperity::topography;

namespace {

// One field of every summit, as an array.
template <class T, class Field>
py::array_t<T> summit_field(const topo::Summits& summits, Field field) {
  py::array_t<T> out(static_cast<py::ssize_t>(summits.list.size()));
  T* data = out.mutable_data();
  for (std::size_t k = 0; k < summits.list.size(); ++k) data[k] = static_cast<T>(field(summits.list[k]));
  return out;
}

}  // namespace

void bind_statistics(py::module_& m) {
  // ---- leveling, statistics, spectral moments (leveling.hpp, statistics.hpp) ----
  py::class_<topo::Plane>(m, "Plane", "z = offset + slope_x x + slope_y y, x = i dx, y = j dy [m].")
      .def(py::init([](double offset, double slope_x, double slope_y) { return topo::Plane{offset, slope_x, slope_y}; }),
           "offset"_a = 0.0, "slope_x"_a = 0.0, "slope_y"_a = 0.0)
      .def_readwrite("offset", &topo::Plane::offset)
      .def_readwrite("slope_x", &topo::Plane::slope_x)
      .def_readwrite("slope_y", &topo::Plane::slope_y)
      .def("__repr__", [](const topo::Plane& p) {
        return py::str("Plane(offset={!r}, slope_x={!r}, slope_y={!r})").format(p.offset, p.slope_x, p.slope_y);
      });
  m.def(
      "fit_plane",
      [](const topo::HeightMap& map) { return without_gil([copy = map] { return topo::fit_plane(copy); }); }, "map"_a,
      "The least-squares plane over the valid points.");
  m.def("subtract_plane", &topo::subtract_plane, "map"_a, "plane"_a,
        "Subtracts the plane from the map in place; missing points stay missing. Holds the GIL (other Python\n"
        "threads see the map before or after, never half done).");

  // each result record's attributes from its one list (record_fields.hpp), its meanings the docstrings
  py::class_<topo::HeightStatistics> height_statistics(m, "HeightStatistics", "Height statistics over the valid points.");
  def_record_fields(height_statistics);
  m.def(
      "height_statistics",
      [](const topo::HeightMap& map) { return without_gil([copy = map] { return topo::height_statistics(copy); }); },
      "map"_a,
      "Mean, rms (Sq), Sa, skewness, kurtosis, min and max of the valid heights.");

  py::class_<topo::SpectralMoments> spectral_moments(
      m, "SpectralMoments",
      "Nayak's spectral moments at the map's sampling interval, one consistent scheme: slopes\n"
      "by forward differences, curvatures by second differences; the slope tensor's principal\n"
      "directions and anisotropy; m2, m4 McCool's equivalent isotropic moments (geometric means\n"
      "along the principal directions).");
  def_record_fields(spectral_moments);
  m.def(
      "spectral_moments",
      [](const topo::HeightMap& map) { return without_gil([copy = map] { return topo::spectral_moments(copy); }); },
      "map"_a,
      "m0, m2, m4 and Nayak's alpha of the map (heights about their mean; stencils touching a missing\n"
      "point skipped). They depend on the sampling interval: stated with it.");

  py::class_<topo::CorrelationLengths> correlation_lengths(
      m, "CorrelationLengths", "Lags (points) along x and y where the height autocorrelation first falls below level.");
  correlation_lengths.def(
      py::init([](std::size_t x, std::size_t y, double level) { return topo::CorrelationLengths{x, y, level}; }),
      "x"_a = 1, "y"_a = 1, "level"_a = 0.1);
  def_record_fields(correlation_lengths, true);
  m.def(
      "correlation_lengths",
      [](const topo::HeightMap& map, double level) {
        return without_gil([copy = map, level] { return topo::correlation_lengths(copy, level); });
      },
      "map"_a, "level"_a = 0.1,
      "The lags where the autocorrelation falls below level (capped at half the map).");
  m.def(
      "thinned_heights",
      [](const topo::HeightMap& map, const topo::CorrelationLengths& lengths, std::size_t max_count) {
        return to_array(without_gil([copy = map, lengths, max_count] {
          return topo::thinned_heights(copy, lengths, max_count);
        }));
      },
      "map"_a, "lengths"_a, "max_count"_a = 0,
      "The valid heights one point every lengths.x by lengths.y, then at most max_count of them (0: all).");
}

void bind_summits(py::module_& m) {
  // ---- summits (summits.hpp) ----
  py::class_<topo::SummitOptions>(m, "SummitOptions", "What counts as a summit.")
      .def(py::init([](int window, double min_drop) { return topo::SummitOptions{window, min_drop}; }), "window"_a = 1,
           "min_drop"_a = 0.0,
           "window: highest within this many points in x and y (1: the 8 neighbours). min_drop [m]: at least\n"
           "this high above the mean of its 8 neighbours (against instrument noise).")
      .def_readwrite("window", &topo::SummitOptions::window)
      .def_readwrite("min_drop", &topo::SummitOptions::min_drop);
  py::class_<topo::Summits> summits(m, "Summits",
                            "The summits of a map: per summit (arrays, one element per summit) its grid position i, j,\n"
                            "height [m], mean curvature kappa_m = -(h_xx + h_yy)/2 and principal curvatures [1/m]; and\n"
                            "over them the density [1/m^2] and the GW radius R = 1 / <kappa_m> [m].");
  summits
      .def_property_readonly("i", [](const topo::Summits& s) {
        return summit_field<std::int64_t>(s, [](const topo::Summit& t) { return t.i; });
      }, "Grid index along x of each summit.")
      .def_property_readonly("j", [](const topo::Summits& s) {
        return summit_field<std::int64_t>(s, [](const topo::Summit& t) { return t.j; });
      }, "Grid index along y of each summit.")
      .def_property_readonly("heights", [](const topo::Summits& s) {
        return summit_field<double>(s, [](const topo::Summit& t) { return t.height; });
      }, "Height of each summit [m].")
      .def_property_readonly("mean_curvatures", [](const topo::Summits& s) {
        return summit_field<double>(s, [](const topo::Summit& t) { return t.mean_curvature; });
      }, "Mean curvature kappa_m of each summit [1/m].")
      .def_property_readonly("kappa1", [](const topo::Summits& s) {
        return summit_field<double>(s, [](const topo::Summit& t) { return t.kappa1; });
      }, "Larger principal curvature of each summit [1/m].")
      .def_property_readonly("kappa2", [](const topo::Summits& s) {
        return summit_field<double>(s, [](const topo::Summit& t) { return t.kappa2; });
      }, "Smaller principal curvature of each summit [1/m].")
      .def("__len__", [](const topo::Summits& s) { return s.list.size(); });
  def_record_fields(summits);
  m.def(
      "find_summits",
      [](const topo::HeightMap& map, std::optional<topo::SummitOptions> options, std::optional<int> window,
         std::optional<double> min_drop) {
        topo::SummitOptions chosen = options.value_or(topo::SummitOptions{});
        if (options && (window || min_drop)) throw py::type_error("give options or window/min_drop, not both");
        if (window) chosen.window = *window;
        if (min_drop) chosen.min_drop = *min_drop;
        return without_gil([copy = map, chosen] { return topo::find_summits(copy, chosen); });
      },
      "map"_a, "options"_a = py::none(), py::kw_only(), "window"_a = py::none(), "min_drop"_a = py::none(),
      "The summits of a map (8-neighbour maxima, or the highest within window points; raster-order ties).\n"
      "Raises asperity.Error for window < 1 or a negative min_drop.");
  m.def(
      "decimated",
      [](const topo::HeightMap& map, std::size_t factor) {
        return without_gil([copy = map, factor] { return topo::decimated(copy, factor); });
      },
      "map"_a, "factor"_a,
      "Every factor-th point in x and y: the map sampled at factor dx, factor dy.");
}

}  // namespace asperity::python
