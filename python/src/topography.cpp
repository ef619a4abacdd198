// asperity.topography: the measured-surface library (include/asperity/topography/*.hpp) with the
// same names. Height maps carry their heights as a (ny, nx) float64 numpy array (a view into
// the map, x fastest); the long computations (reading, fits, the bootstrap, the analysis, the
// synthetic fields) run without the GIL, on copies taken while it is held: whatever another
// Python thread does to an object meanwhile (its properties, a map's heights through the view),
// the computation never reads memory that is being changed. The two calls that change a map
// (subtract_plane, to_weibull_marginal) keep the GIL: one pass over the heights, atomic for
// every other Python thread.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "asperity/error.hpp"
#include "asperity/output.hpp"
#include "asperity/topography/analysis.hpp"
#include "asperity/topography/contact_comparison.hpp"
#include "asperity/topography/distribution_fit.hpp"
#include "asperity/topography/exact_contact.hpp"
#include "asperity/topography/exact_contact_table.hpp"
#include "asperity/contact_curves_data.hpp"
#include "asperity/topography/persson_contact.hpp"
#include "asperity/topography/goodness_of_fit.hpp"
#include "asperity/topography/height_map.hpp"
#include "asperity/topography/height_map_io.hpp"
#include "asperity/topography/leveling.hpp"
#include "asperity/topography/statistics.hpp"
#include "asperity/topography/self_affine.hpp"
#include "asperity/topography/summits.hpp"
#include "asperity/topography/surface_formats.hpp"
#include "asperity/topography/surface_report.hpp"
#include "asperity/topography/synthetic.hpp"
#include "asperity/topography/units.hpp"
#include "bindings.hpp"
#include "interrupt.hpp"
#include "paths.hpp"

namespace asperity::python {
namespace {
namespace topo = asperity::topography;
using namespace pybind11::literals;

// Runs function() without the GIL, stopped by Ctrl-C (interrupt.hpp). What it reads must be its
// own (captured by value when the lambda is made, with the GIL held), never an object another
// Python thread can change.
template <class Function>
auto without_gil(Function&& function) {
  return interruptible(std::forward<Function>(function));
}

// A size from Python: an int (or anything with __index__) from 0 to the largest std::size_t.
std::size_t to_size(const py::handle& value, const char* name) {
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

py::list path_texts(const std::vector<std::string>& texts) {
  py::list out;
  for (const std::string& text : texts) out.append(path_text(text));
  return out;
}

topo::HeightMapFormat to_format(const py::handle& value) {
  if (py::isinstance<topo::HeightMapFormat>(value)) return value.cast<topo::HeightMapFormat>();
  if (py::isinstance<py::str>(value)) {
    topo::HeightMapFormat format;
    const std::string name = value.cast<std::string>();
    if (topo::parse_height_map_format(name, format)) return format;
    throw py::value_error("unknown height map format '" + name + "': expected one of " + topo::surface_format_names());
  }
  throw py::type_error("format must be a str or an asperity.topography.HeightMapFormat");
}

topo::HeightModel to_model(const py::handle& value) {
  if (py::isinstance<topo::HeightModel>(value)) return value.cast<topo::HeightModel>();
  if (py::isinstance<py::str>(value)) {
    std::string name = value.cast<std::string>();
    std::replace(name.begin(), name.end(), '_', '-');
    for (topo::HeightModel model : topo::all_height_models)
      if (name == topo::to_string(model)) return model;
    throw py::value_error("unknown height model '" + value.cast<std::string>() +
                          "': expected 'gaussian', 'weibull_tail' or 'weibull_bounded'");
  }
  throw py::type_error("model must be a str or an asperity.topography.HeightModel");
}

// A float64 array of values, in a vector (a copy).
std::vector<double> to_vector(py::handle values, const char* name) {
  const DoubleArray array = as_double_array(values, name);
  return std::vector<double>(array.data(), array.data() + array.size());
}

std::vector<double> sorted_vector(py::handle values, const char* name) {
  std::vector<double> sorted = to_vector(values, name);
  std::sort(sorted.begin(), sorted.end());
  return sorted;
}

template <class T>
py::array_t<T> to_array(const std::vector<T>& values) {
  py::array_t<T> out(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

// One field of every summit, as an array.
template <class T, class Field>
py::array_t<T> summit_field(const topo::Summits& summits, Field field) {
  py::array_t<T> out(static_cast<py::ssize_t>(summits.list.size()));
  T* data = out.mutable_data();
  for (std::size_t k = 0; k < summits.list.size(); ++k) data[k] = static_cast<T>(field(summits.list[k]));
  return out;
}

// A solver and the lock that makes its calls one at a time: a solve runs without the GIL and
// changes the solver's state (the warm start), so two Python threads must not run one together.
struct ExactContactHandle {
  ExactContactHandle(const topo::HeightMap& map, const topo::ExactContactOptions& options) : solver(map, options) {}
  topo::ExactContact solver;
  std::mutex lock;
};

// A field of the map's grid as a new (ny, nx) array.
py::array_t<double> grid_array(const std::vector<double>& field, std::size_t nx, std::size_t ny) {
  py::array_t<double> out({static_cast<py::ssize_t>(ny), static_cast<py::ssize_t>(nx)});
  std::copy(field.begin(), field.end(), out.mutable_data());
  return out;
}

// The heights of a map as a (ny, nx) array viewing the map's own storage; the array keeps the
// map (and whatever owns it) alive.
py::array_t<double> heights_view(py::object self) {
  topo::HeightMap& map = self.cast<topo::HeightMap&>();
  const py::ssize_t nx = static_cast<py::ssize_t>(map.nx), ny = static_cast<py::ssize_t>(map.ny);
  if (map.heights.size() != map.nx * map.ny)
    throw py::value_error("the height map holds " + std::to_string(map.heights.size()) + " heights, not nx * ny");
  return py::array_t<double>({ny, nx}, {nx * static_cast<py::ssize_t>(sizeof(double)), py::ssize_t(sizeof(double))},
                             map.heights.data(), self);
}

topo::HeightMap map_from_array(py::handle heights, double dx, double dy, std::string source, std::string format,
                               std::vector<std::string> notes) {
  const DoubleArray array = as_double_array(heights, "heights");
  if (array.ndim() != 2) throw py::value_error("heights must be a 2-d array (ny, nx), x along the last axis");
  topo::HeightMap map;
  map.ny = static_cast<std::size_t>(array.shape(0));
  map.nx = static_cast<std::size_t>(array.shape(1));
  map.dx = dx;
  map.dy = dy;
  map.heights.assign(array.data(), array.data() + array.size());
  map.source = std::move(source);
  map.format = std::move(format);
  map.notes = std::move(notes);
  map.validate();
  return map;
}

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

template <class Function>
FloatOrArray map_values(py::handle input, const char* name, Function function) {
  return map_batch(
      input, name, py::none(),
      [&](const double* in, double* out, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) out[i] = function(in[i]);
      },
      function);
}

std::string repr_interval(const topo::Interval& interval) {
  return py::str("Interval(lo={!r}, hi={!r})").format(interval.lo, interval.hi).cast<std::string>();
}

}  // namespace

void bind_topography(py::module_& parent, py::handle physical_state_type) {
  py::module_ m = parent.def_submodule(
      "topography",
      "From a measured surface to its contact curves (docs/surfaces.md): reading height maps (X3P, Gwyddion\n"
      ".gsf and ASCII matrix, xyz), leveling, height statistics and spectral moments, summits, the three\n"
      "height models fitted with their evidence (Anderson-Darling and Kolmogorov-Smirnov by parametric\n"
      "bootstrap, AIC, a verdict), the contact curves of each fit, and reports. SI units throughout.");

  // ---- height maps (height_map.hpp, height_map_io.hpp, units.hpp) ----
  py::class_<topo::HeightMap>(m, "HeightMap",
                              "A measured height map: heights [m] on a regular grid with sampling intervals dx, dy [m];\n"
                              "missing points are NaN.")
      .def(py::init([](const ArrayLike& heights, double dx, double dy, std::string source, std::string format,
                       std::vector<std::string> notes) {
             return map_from_array(heights.object, dx, dy, std::move(source), std::move(format), std::move(notes));
           }),
           "heights"_a, "dx"_a, "dy"_a, "source"_a = "array", "format"_a = "array", "notes"_a = std::vector<std::string>{},
           "A map from a 2-d array of heights [m], shape (ny, nx), x along the last axis (copied), and the\n"
           "sampling intervals dx, dy [m]. Raises asperity.Error for fewer than 3 x 3 points, intervals that\n"
           "are not positive, an infinite height or no valid point.")
      .def_property_readonly("heights", &heights_view,
                             "The heights [m] as a (ny, nx) float64 array: a view of the map's own storage (writing\n"
                             "into it changes the map); heights[j, i] is the point x = i dx, y = j dy; NaN: missing.")
      .def_readonly("nx", &topo::HeightMap::nx, "Points along x (the last axis of heights).")
      .def_readonly("ny", &topo::HeightMap::ny, "Points along y (the first axis of heights).")
      .def_readwrite("dx", &topo::HeightMap::dx, "Sampling interval along x [m].")
      .def_readwrite("dy", &topo::HeightMap::dy, "Sampling interval along y [m].")
      .def_property(
          "source", [](const topo::HeightMap& map) { return path_text(map.source); },
          [](topo::HeightMap& map, const PathName& value) { map.source = to_path(value.object, "source"); },
          "The file it came from (for messages; str, bytes or os.PathLike in, str out as os.fsdecode gives it).")
      .def_readwrite("format", &topo::HeightMap::format, "x3p, gsf, ascii-matrix, xyz, synthetic or array.")
      .def_readwrite("height_resolution", &topo::HeightMap::height_resolution,
                     "The largest rounding step of the heights as stored [m] (0: unknown): roughness at this level\n"
                     "is quantization (the analysis stops at its noise floor).")
      .def_property(
          "notes", [](const topo::HeightMap& map) { return path_texts(map.notes); },
          [](topo::HeightMap& map, std::vector<std::string> notes) { map.notes = std::move(notes); },
          "Where sizes and units came from, the instrument, what was done.")
      .def_property_readonly("missing_points", &topo::HeightMap::missing_points, "Points that are NaN.")
      .def_property_readonly("width", &topo::HeightMap::width, "nx dx [m].")
      .def_property_readonly("length", &topo::HeightMap::length, "ny dy [m].")
      .def("validate", &topo::HeightMap::validate, "Raises asperity.Error naming the source and the problem.")
      .def("__len__", &topo::HeightMap::size)
      .def("__copy__", [](const topo::HeightMap& map) { return map; })
      .def("__deepcopy__", [](const topo::HeightMap& map, py::dict) { return map; }, "memo"_a)
      .def("__repr__", [](const topo::HeightMap& map) {
        return py::str("<asperity.topography.HeightMap {} x {} points, dx={!r} m, dy={!r} m, {}: {}>")
            .format(map.nx, map.ny, map.dx, map.dy, map.format, path_text(map.source));
      });

  // the members from the formats' table (asperity/topography/surface_formats.hpp)
  py::enum_<topo::HeightMapFormat> formats(m, "HeightMapFormat",
                                           "A height map file's format (automatic: by content, then extension).");
  formats.value("automatic", topo::HeightMapFormat::automatic);
  for (const topo::SurfaceFormat& format : topo::surface_formats()) formats.value(format.python_name, format.format);

  static const std::string read_options_doc =
      "format: " + topo::surface_format_names() + " (auto: by content, then extension), or a HeightMapFormat.\n"
      "pixel_size_x, pixel_size_y [m]: sampling intervals for formats without them, or overriding the\n"
      "file's (0: the file's; pixel_size_y 0: pixel_size_x). lateral_unit, height_unit: 'um', 'nm', ...\n"
      "for formats without units (xyz), overriding the file's for the others. max_points: a header is\n"
      "never trusted to allocate more.";
  py::class_<topo::ReadOptions>(m, "ReadOptions", "How to read a height map file.")
      .def(py::init([](const py::object& format, double pixel_size_x, double pixel_size_y, std::string lateral_unit,
                       std::string height_unit, std::size_t max_points) {
             topo::ReadOptions options;
             options.format = to_format(format);
             options.pixel_size_x = pixel_size_x;
             options.pixel_size_y = pixel_size_y == 0 ? pixel_size_x : pixel_size_y;
             options.lateral_unit = std::move(lateral_unit);
             options.height_unit = std::move(height_unit);
             options.max_points = max_points;
             return options;
           }),
           "format"_a = "auto", "pixel_size_x"_a = 0.0, "pixel_size_y"_a = 0.0, "lateral_unit"_a = "",
           "height_unit"_a = "", "max_points"_a = topo::ReadOptions{}.max_points,
           read_options_doc.c_str())
      .def_property(
          "format", [](const topo::ReadOptions& o) { return o.format; },
          [](topo::ReadOptions& o, const py::object& value) { o.format = to_format(value); })
      .def_readwrite("pixel_size_x", &topo::ReadOptions::pixel_size_x)
      .def_readwrite("pixel_size_y", &topo::ReadOptions::pixel_size_y)
      .def_readwrite("lateral_unit", &topo::ReadOptions::lateral_unit)
      .def_readwrite("height_unit", &topo::ReadOptions::height_unit)
      .def_readwrite("max_points", &topo::ReadOptions::max_points);

  const char* read_doc =
      "Reads a height map (str, bytes or os.PathLike); options: a ReadOptions, or its fields as keywords.\n"
      "Raises asperity.Error naming the file and the problem (missing, truncated, wrong checksum, unknown\n"
      "unit, no pixel size where the file has none, ...).";
  auto reader = [](topo::HeightMap (*read)(const std::string&, const topo::ReadOptions&)) {
    return [read](const PathName& path, std::optional<topo::ReadOptions> options, const py::kwargs& fields) {
      topo::ReadOptions chosen = options.value_or(topo::ReadOptions{});
      if (fields.size() > 0) {
        if (options) throw py::type_error("give options or its fields as keywords, not both");
        chosen = py::type::of<topo::ReadOptions>()(**fields).cast<topo::ReadOptions>();
      }
      const std::string file = to_path(path.object);
      return without_gil([&] { return read(file, chosen); });
    };
  };
  m.def("read_height_map", reader(&topo::read_height_map), "path"_a, "options"_a = py::none(), read_doc);
  m.def("read_x3p", reader(&topo::read_x3p), "path"_a, "options"_a = py::none(), "read_height_map for an X3P file.");
  m.def("read_gsf", reader(&topo::read_gsf), "path"_a, "options"_a = py::none(),
        "read_height_map for a Gwyddion Simple Field (.gsf).");
  m.def("read_ascii_matrix", reader(&topo::read_ascii_matrix), "path"_a, "options"_a = py::none(),
        "read_height_map for Gwyddion's ASCII data matrix export.");
  m.def("read_xyz", reader(&topo::read_xyz), "path"_a, "options"_a = py::none(),
        "read_height_map for x y z columns on a regular grid (units required: lateral_unit, height_unit).");
  m.def(
      "write_gsf",
      [](const topo::HeightMap& map, const PathName& path, bool overwrite) {
        const std::string file = to_path(path.object);
        without_gil([copy = map, &file, overwrite] { topo::write_gsf(copy, file, overwrite); });
      },
      "map"_a, "path"_a, py::kw_only(), "overwrite"_a = false,
      "Writes a map as Gwyddion Simple Field (float32). A file there that is not a .gsf of asperity's is\n"
      "replaced only with overwrite=True (docs/reliability.md, 'Outputs'). Raises asperity.Error on a write error.");
  m.def("length_unit_in_metres", [](const std::string& unit) { return topo::length_unit_in_metres(unit); }, "unit"_a,
        "The metres in one unit: m, dm, cm, mm, um (µm), nm, pm, A (Å), km. asperity.Error for anything else.");
  m.def("parse_length", [](const std::string& text, const std::string& unit) { return topo::parse_length(text, unit); },
        "text"_a, "default_unit"_a = "",
        "A length with its unit ('1.5um', '2e-7 m') in metres; a bare number needs default_unit.");

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

  py::class_<topo::HeightStatistics>(m, "HeightStatistics", "Height statistics over the valid points.")
      .def_readonly("valid_points", &topo::HeightStatistics::valid_points)
      .def_readonly("missing_points", &topo::HeightStatistics::missing_points)
      .def_readonly("mean", &topo::HeightStatistics::mean, "[m]")
      .def_readonly("rms", &topo::HeightStatistics::rms, "Sq, about the mean [m].")
      .def_readonly("mean_absolute", &topo::HeightStatistics::mean_absolute, "Sa [m].")
      .def_readonly("skewness", &topo::HeightStatistics::skewness, "Ssk.")
      .def_readonly("kurtosis", &topo::HeightStatistics::kurtosis, "Sku (3 for a Gaussian).")
      .def_readonly("min", &topo::HeightStatistics::min, "[m]")
      .def_readonly("max", &topo::HeightStatistics::max, "[m]");
  m.def(
      "height_statistics",
      [](const topo::HeightMap& map) { return without_gil([copy = map] { return topo::height_statistics(copy); }); },
      "map"_a,
      "Mean, rms (Sq), Sa, skewness, kurtosis, min and max of the valid heights.");

  py::class_<topo::SpectralMoments>(m, "SpectralMoments",
                                    "Nayak's spectral moments at the map's sampling interval, one consistent scheme: slopes\n"
                                    "by forward differences, curvatures by second differences; the slope tensor's principal\n"
                                    "directions and anisotropy; m2, m4 McCool's equivalent isotropic moments (geometric means\n"
                                    "along the principal directions).")
      .def_readonly("m0", &topo::SpectralMoments::m0, "Height variance [m^2].")
      .def_readonly("m2x", &topo::SpectralMoments::m2x)
      .def_readonly("m2y", &topo::SpectralMoments::m2y)
      .def_readonly("m11", &topo::SpectralMoments::m11, "<(dh/dx)(dh/dy)>.")
      .def_readonly("m4x", &topo::SpectralMoments::m4x, "[1/m^2]")
      .def_readonly("m4y", &topo::SpectralMoments::m4y, "[1/m^2]")
      .def_readonly("principal_angle", &topo::SpectralMoments::principal_angle,
                    "The steepest principal direction's angle from x [rad].")
      .def_property_readonly("m2_principal", [](const topo::SpectralMoments& s) {
        return py::make_tuple(s.m2_principal[0], s.m2_principal[1]);
      }, "The principal slope variances, steepest first.")
      .def_property_readonly("m4_principal", [](const topo::SpectralMoments& s) {
        return py::make_tuple(s.m4_principal[0], s.m4_principal[1]);
      }, "The curvature variances along the principal directions [1/m^2].")
      .def_readonly("anisotropy", &topo::SpectralMoments::anisotropy,
                    "m2_principal[0] / m2_principal[1]; Nayak-McCool assume 1 (isotropic).")
      .def_readonly("m2", &topo::SpectralMoments::m2, "Equivalent isotropic slope variance (dimensionless).")
      .def_readonly("m4", &topo::SpectralMoments::m4, "Equivalent isotropic curvature variance [1/m^2].")
      .def_readonly("alpha", &topo::SpectralMoments::alpha, "Nayak's bandwidth m0 m4 / m2^2.")
      .def_readonly("slope_samples", &topo::SpectralMoments::slope_samples)
      .def_readonly("curvature_samples", &topo::SpectralMoments::curvature_samples);
  m.def(
      "spectral_moments",
      [](const topo::HeightMap& map) { return without_gil([copy = map] { return topo::spectral_moments(copy); }); },
      "map"_a,
      "m0, m2, m4 and Nayak's alpha of the map (heights about their mean; stencils touching a missing\n"
      "point skipped). They depend on the sampling interval: stated with it.");

  py::class_<topo::CorrelationLengths>(m, "CorrelationLengths",
                                       "Lags (points) along x and y where the height autocorrelation first falls below level.")
      .def(py::init([](std::size_t x, std::size_t y, double level) { return topo::CorrelationLengths{x, y, level}; }),
           "x"_a = 1, "y"_a = 1, "level"_a = 0.1)
      .def_readwrite("x", &topo::CorrelationLengths::x)
      .def_readwrite("y", &topo::CorrelationLengths::y)
      .def_readwrite("level", &topo::CorrelationLengths::level);
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

  // ---- summits (summits.hpp) ----
  py::class_<topo::SummitOptions>(m, "SummitOptions", "What counts as a summit.")
      .def(py::init([](int window, double min_drop) { return topo::SummitOptions{window, min_drop}; }), "window"_a = 1,
           "min_drop"_a = 0.0,
           "window: highest within this many points in x and y (1: the 8 neighbours). min_drop [m]: at least\n"
           "this high above the mean of its 8 neighbours (against instrument noise).")
      .def_readwrite("window", &topo::SummitOptions::window)
      .def_readwrite("min_drop", &topo::SummitOptions::min_drop);
  py::class_<topo::Summits>(m, "Summits",
                            "The summits of a map: per summit (arrays, one element per summit) its grid position i, j,\n"
                            "height [m], mean curvature kappa_m = -(h_xx + h_yy)/2 and principal curvatures [1/m]; and\n"
                            "over them the density [1/m^2] and the GW radius R = 1 / <kappa_m> [m].")
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
      .def_readonly("candidates", &topo::Summits::candidates, "Points whose whole window is valid.")
      .def_readonly("area_searched", &topo::Summits::area_searched, "candidates dx dy [m^2].")
      .def_readonly("density", &topo::Summits::density, "Summits per unit area [1/m^2].")
      .def_readonly("mean_curvature", &topo::Summits::mean_curvature, "<kappa_m> over the summits [1/m].")
      .def_readonly("radius", &topo::Summits::radius, "R = 1 / <kappa_m> [m].")
      .def_readonly("rejected_by_drop", &topo::Summits::rejected_by_drop)
      .def_readonly("options", &topo::Summits::options)
      .def_readonly("dx", &topo::Summits::dx)
      .def_readonly("dy", &topo::Summits::dy)
      .def("__len__", [](const topo::Summits& s) { return s.list.size(); });
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

  // ---- height distributions and their fits (distribution_fit.hpp, goodness_of_fit.hpp) ----
  py::enum_<topo::HeightModel>(m, "HeightModel",
                               "gaussian N(location, scale^2); weibull_tail x = location + scale W (the tail up, GW's\n"
                               "side); weibull_bounded x = location - scale W (bounded above: worn, polished).")
      .value("gaussian", topo::HeightModel::gaussian)
      .value("weibull_tail", topo::HeightModel::weibull_tail)
      .value("weibull_bounded", topo::HeightModel::weibull_bounded);
  m.def("describe", [](const py::object& model) { return std::string(topo::describe(to_model(model))); }, "model"_a,
        "The model in words.");
  m.def("parameter_count", [](const py::object& model) { return topo::parameter_count(to_model(model)); }, "model"_a,
        "2 for the Gaussian, 3 for the Weibulls.");

  py::class_<topo::HeightDistribution>(m, "HeightDistribution",
                                       "One of the three height models with its parameters [m] (the Gaussian: mean and\n"
                                       "standard deviation; the Weibulls: location, scale and shape a). The functions\n"
                                       "take a number (a float back) or an array of any shape (an array back).")
      .def(py::init([](const py::object& model, double location, double scale, double shape) {
             return topo::HeightDistribution{to_model(model), location, scale, shape};
           }),
           "model"_a = "gaussian", "location"_a = 0.0, "scale"_a = 1.0, "shape"_a = 0.0)
      .def_property(
          "model", [](const topo::HeightDistribution& d) { return d.model; },
          [](topo::HeightDistribution& d, const py::object& value) { d.model = to_model(value); })
      .def_readwrite("location", &topo::HeightDistribution::location)
      .def_readwrite("scale", &topo::HeightDistribution::scale)
      .def_readwrite("shape", &topo::HeightDistribution::shape)
      .def("pdf", [](topo::HeightDistribution d, const ArrayLike& x) {
        return map_values(x.object, "x", [&](double v) { return std::exp(d.log_pdf(v)); });
      }, "x"_a, "The density.")
      .def("log_pdf", [](topo::HeightDistribution d, const ArrayLike& x) {
        return map_values(x.object, "x", [&](double v) { return d.log_pdf(v); });
      }, "x"_a, "ln of the density (-inf outside the support).")
      .def("cdf", [](topo::HeightDistribution d, const ArrayLike& x) {
        return map_values(x.object, "x", [&](double v) { return d.cdf(v); });
      }, "x"_a, "P(X <= x).")
      .def("log_cdf", [](topo::HeightDistribution d, const ArrayLike& x) {
        return map_values(x.object, "x", [&](double v) { return d.log_cdf(v); });
      }, "x"_a, "ln P(X <= x).")
      .def("log_sf", [](topo::HeightDistribution d, const ArrayLike& x) {
        return map_values(x.object, "x", [&](double v) { return d.log_sf(v); });
      }, "x"_a, "ln P(X > x).")
      .def("quantile", [](topo::HeightDistribution d, const ArrayLike& p) {
        return map_values(p.object, "p", [&](double v) { return d.quantile(v); });
      }, "p"_a, "The x with P(X <= x) = p, p in (0, 1) (NaN outside).")
      .def("mean", &topo::HeightDistribution::mean,
           "The mean: NaN for parameters that are no distribution (scale <= 0, a Weibull shape <= 0, not finite),\n"
           "+-inf beyond the largest double (a Weibull shape below ~0.006).")
      .def("standard_deviation", &topo::HeightDistribution::standard_deviation,
           "The standard deviation: NaN for parameters that are no distribution, inf beyond the largest double.")
      .def("__repr__", [](const topo::HeightDistribution& d) {
        return py::str("HeightDistribution(model='{}', location={!r}, scale={!r}, shape={!r})")
            .format(py::str(py::cast(d.model).attr("name")), d.location, d.scale, d.shape);
      });

  py::class_<topo::FitOptions>(m, "FitOptions", "The Weibull shape's search range of the fits.")
      .def(py::init([](double shape_min, double shape_max) {
             topo::FitOptions options;
             options.shape_min = shape_min;
             options.shape_max = shape_max;
             return options;
           }),
           "shape_min"_a = topo::FitOptions{}.shape_min, "shape_max"_a = topo::FitOptions{}.shape_max)
      .def_readwrite("shape_min", &topo::FitOptions::shape_min)
      .def_readwrite("shape_max", &topo::FitOptions::shape_max);
  py::class_<topo::FitResult>(m, "FitResult", "A fitted distribution.")
      .def_readonly("distribution", &topo::FitResult::distribution)
      .def_readonly("objective", &topo::FitResult::objective,
                    "Maximum product of spacings: the mean log spacing S; Gaussian: the mean log-likelihood.")
      .def_readonly("shape_at_bound", &topo::FitResult::shape_at_bound, "The shape hit shape_min or shape_max.")
      .def_readonly("evaluations", &topo::FitResult::evaluations);
  m.def(
      "fit_height_distribution",
      [](const py::object& model, const ArrayLike& values, const std::optional<topo::FitOptions>& options) {
        const topo::HeightModel chosen = to_model(model);
        const std::vector<double> sorted = sorted_vector(values.object, "values");
        const topo::FitOptions fit = options.value_or(topo::FitOptions{});
        return without_gil([&] { return topo::fit_height_distribution(chosen, sorted, fit); });
      },
      "model"_a, "values"_a, "options"_a = py::none(),
      "Fits a height model to values (any order): the Gaussian by maximum likelihood, the three-parameter\n"
      "Weibulls by maximum product of spacings (well-posed for every shape, also below 1). At least 5\n"
      "finite values not all equal (asperity.Error otherwise).");
  m.def(
      "mean_log_spacing",
      [](const topo::HeightDistribution& d, const ArrayLike& values) {
        return topo::mean_log_spacing(d, sorted_vector(values.object, "values"));
      },
      "distribution"_a, "values"_a, "The MPS objective S (mean log spacing) of a distribution on values.");
  m.def(
      "log_likelihood",
      [](const topo::HeightDistribution& d, const ArrayLike& values) {
        return topo::log_likelihood(d, to_vector(values.object, "values"));
      },
      "distribution"_a, "values"_a, "ln L of values.");
  m.def(
      "anderson_darling",
      [](const topo::HeightDistribution& d, const ArrayLike& values) {
        return topo::anderson_darling(d, sorted_vector(values.object, "values"));
      },
      "distribution"_a, "values"_a, "The Anderson-Darling statistic A^2 of values against a distribution.");
  m.def(
      "kolmogorov_smirnov",
      [](const topo::HeightDistribution& d, const ArrayLike& values) {
        return topo::kolmogorov_smirnov(d, sorted_vector(values.object, "values"));
      },
      "distribution"_a, "values"_a, "The Kolmogorov-Smirnov statistic D of values against a distribution.");
  m.def(
      "draw_sample",
      [](const topo::HeightDistribution& d, std::size_t n, std::uint64_t seed) {
        return to_array(without_gil([d, n, seed] { return topo::draw_sample(d, n, seed); }));
      },
      "distribution"_a, "n"_a, "seed"_a = 1,
      "n reproducible draws (the bootstrap's generator: the same on every platform).");

  py::class_<topo::AssessmentOptions>(m, "AssessmentOptions", "The bootstrap and the tests of assess_sample.")
      .def(py::init([](int bootstrap, std::uint64_t seed, int threads, double confidence, double significance,
                       const std::optional<topo::FitOptions>& fit) {
             topo::AssessmentOptions options;
             options.bootstrap = bootstrap;
             options.seed = seed;
             options.threads = threads;
             options.confidence = confidence;
             options.significance = significance;
             if (fit) options.fit = *fit;
             return options;
           }),
           "bootstrap"_a = topo::AssessmentOptions{}.bootstrap, "seed"_a = 1, "threads"_a = 0, "confidence"_a = 0.95, "significance"_a = 0.05,
           "fit"_a = py::none(),
           "bootstrap: B parametric-bootstrap samples (0: no p-values, no intervals); seed: reproducible; threads:\n"
           "0 for all cores; confidence of the intervals; significance of the tests for the verdict.")
      .def_readwrite("bootstrap", &topo::AssessmentOptions::bootstrap)
      .def_readwrite("seed", &topo::AssessmentOptions::seed)
      .def_readwrite("threads", &topo::AssessmentOptions::threads)
      .def_readwrite("confidence", &topo::AssessmentOptions::confidence)
      .def_readwrite("significance", &topo::AssessmentOptions::significance)
      .def_readwrite("fit", &topo::AssessmentOptions::fit);
  py::class_<topo::Interval>(m, "Interval", "A percentile bootstrap interval [lo, hi].")
      .def_readonly("lo", &topo::Interval::lo)
      .def_readonly("hi", &topo::Interval::hi)
      .def("__repr__", &repr_interval);
  py::class_<topo::ModelAssessment>(m, "ModelAssessment", "One model fitted to one sample, with its evidence.")
      .def_readonly("fit", &topo::ModelAssessment::fit)
      .def_readonly("anderson_darling", &topo::ModelAssessment::anderson_darling)
      .def_readonly("anderson_darling_p", &topo::ModelAssessment::anderson_darling_p, "By parametric bootstrap.")
      .def_readonly("kolmogorov_smirnov", &topo::ModelAssessment::kolmogorov_smirnov)
      .def_readonly("kolmogorov_smirnov_p", &topo::ModelAssessment::kolmogorov_smirnov_p, "By parametric bootstrap.")
      .def_readonly("log_likelihood", &topo::ModelAssessment::log_likelihood)
      .def_readonly("aic", &topo::ModelAssessment::aic)
      .def_readonly("delta_aic", &topo::ModelAssessment::delta_aic)
      .def_readonly("akaike_weight", &topo::ModelAssessment::akaike_weight)
      .def_readonly("location", &topo::ModelAssessment::location)
      .def_readonly("scale", &topo::ModelAssessment::scale)
      .def_readonly("shape", &topo::ModelAssessment::shape, "The shape's interval (Weibull only).")
      .def_readonly("bootstrap", &topo::ModelAssessment::bootstrap)
      .def_readonly("failed_refits", &topo::ModelAssessment::failed_refits)
      .def_readonly("rejected", &topo::ModelAssessment::rejected,
                    "The Anderson-Darling p-value is below the significance.")
      .def_readonly("p_at_floor", &topo::ModelAssessment::p_at_floor,
                    "The Anderson-Darling p-value is at its floor 1/(B + 1): a bound (p <= ...), not a value.")
      .def_readonly("kolmogorov_smirnov_p_at_floor", &topo::ModelAssessment::kolmogorov_smirnov_p_at_floor,
                    "The Kolmogorov-Smirnov p-value is at its floor 1/(B + 1): a bound, not a value.")
      .def_readonly("shape_identified", &topo::ModelAssessment::shape_identified,
                    "The data pin the shape down (its interval stays inside the fit's bounds).")
      .def_readonly("identification", &topo::ModelAssessment::identification, "Why not, when not.")
      .def_readonly("bias_slope", &topo::ModelAssessment::bias_slope,
                    "The heights' Weibull shape: d(bias of ln a)/d(ln a) on the surrogates, which its interval "
                    "corrects for (NaN where not measured).")
      .def("__repr__", [](const topo::ModelAssessment& m) {
        // the p-values as the reports write them: a bound where they are one ("p <= 0.005")
        return "<asperity.topography.ModelAssessment " + std::string(topo::to_string(m.fit.distribution.model)) +
               ": AD " + topo::p_value_text(m.anderson_darling_p, m.p_at_floor) + ", KS " +
               topo::p_value_text(m.kolmogorov_smirnov_p, m.kolmogorov_smirnov_p_at_floor) + ">";
      });
  py::class_<topo::Verdict>(m, "Verdict", "Which model the evidence favours, and the evidence in words.")
      .def_readonly("gaussian_rejected", &topo::Verdict::gaussian_rejected)
      .def_readonly("best", &topo::Verdict::best, "Lowest AIC among the models not rejected.")
      .def_readonly("best_rejected", &topo::Verdict::best_rejected, "Every model was rejected: the best by AIC anyway.")
      .def_readonly("aic_gain_over_gaussian", &topo::Verdict::aic_gain_over_gaussian)
      .def_readonly("text", &topo::Verdict::text);
  py::class_<topo::SampleAssessment>(m, "SampleAssessment", "The three models fitted to one sample, and a verdict.")
      .def_readonly("name", &topo::SampleAssessment::name)
      .def_readonly("n", &topo::SampleAssessment::n)
      .def_readonly("models", &topo::SampleAssessment::models, "In HeightModel order: gaussian, weibull_tail, weibull_bounded.")
      .def_readonly("verdict", &topo::SampleAssessment::verdict)
      .def_readonly("options", &topo::SampleAssessment::options)
      .def("model", [](const topo::SampleAssessment& a, const py::object& model) { return a.model(to_model(model)); },
           "model"_a, "The assessment of one model.");
  m.def(
      "assess_sample",
      [](const std::string& name, const ArrayLike& values, const std::optional<topo::AssessmentOptions>& options) {
        std::vector<double> sample = to_vector(values.object, "values");
        const topo::AssessmentOptions chosen = options.value_or(topo::AssessmentOptions{});
        return without_gil([&] { return topo::assess_sample(name, std::move(sample), chosen); });
      },
      "name"_a, "values"_a, "options"_a = py::none(),
      "Fits the three models to values, tests each (Anderson-Darling, Kolmogorov-Smirnov, p-values by parametric\n"
      "bootstrap), gives percentile intervals, AIC and a verdict. The values are assumed independent.");

  // ---- synthetic surfaces (synthetic.hpp) ----
  py::class_<topo::SpectrumComponent>(m, "SpectrumComponent",
                                      "A Gaussian bump of the spectrum: kernel standard deviation [points], variance [m^2].")
      .def(py::init([](double correlation, double variance) { return topo::SpectrumComponent{correlation, variance}; }),
           "correlation"_a = 4.0, "variance"_a = 1.0)
      .def_readwrite("correlation", &topo::SpectrumComponent::correlation)
      .def_readwrite("variance", &topo::SpectrumComponent::variance);
  m.def(
      "gaussian_random_field",
      [](const Count& nx, const Count& ny, double dx, double dy, std::vector<topo::SpectrumComponent> spectrum,
         std::uint64_t seed) {
        const std::size_t columns = to_size(nx.object, "nx"), rows = to_size(ny.object, "ny");
        return without_gil([&] { return topo::gaussian_random_field(columns, rows, dx, dy, spectrum, seed); });
      },
      "nx"_a, "ny"_a, "dx"_a, "dy"_a, "spectrum"_a, "seed"_a = 1,
      "A Gaussian random field: white noise convolved with a Gaussian kernel per component, summed. Every\n"
      "height is exactly N(0, total variance); reproducible from seed. Limits (asperity.Error beyond them):\n"
      "3 <= nx, ny and nx * ny <= 2^26 points; each correlation in (0, 65536] points; the noise convolved,\n"
      "(nx + 2h) (ny + 2h) with h = ceil(4 correlation), at most 2^27 points; at most 2^36 multiply-adds.");
  m.def("expected_spectral_moments", &topo::expected_spectral_moments, "dx"_a, "dy"_a, "spectrum"_a,
        "The spectral moments gaussian_random_field's fields have in expectation.");
  py::enum_<topo::CorrelationFunction>(m, "CorrelationFunction",
                                       "The correlation of spectral_random_field's fields: gaussian exp(-r^2/xi^2)\n"
                                       "(narrow band), exponential exp(-r/xi) (broad band).")
      .value("gaussian", topo::CorrelationFunction::gaussian)
      .value("exponential", topo::CorrelationFunction::exponential);
  m.def(
      "spectral_random_field",
      [](const Count& nx, const Count& ny, double dx, double dy, topo::CorrelationFunction function,
         double correlation_length, std::uint64_t seed) {
        const std::size_t columns = to_size(nx.object, "nx"), rows = to_size(ny.object, "ny");
        return without_gil([&] {
          return topo::spectral_random_field(columns, rows, dx, dy, function, correlation_length, seed);
        });
      },
      "nx"_a, "ny"_a, "dx"_a, "dy"_a, "function"_a, "correlation_length"_a, "seed"_a = 1,
      "An isotropic Gaussian random field of unit variance with the named correlation (correlation_length in\n"
      "points), by FFT on a periodic grid twice the map's size, cut to the map; reproducible from seed. The\n"
      "exponential one at correlation_length 20-25 is broad-band like measured maps (Nayak alpha ~30 at 256^2).\n"
      "Limits: 3 <= nx, ny and nx * ny <= 2^26; correlation_length in (0, 65536].");
  m.def("to_weibull_marginal", &topo::to_weibull_marginal, "map"_a, "shape"_a, "bounded"_a = false,
        "Maps each height of a unit-variance Gaussian field to a unit Weibull of the shape (bounded: mirrored,\n"
        "bounded above), in place. Holds the GIL (other Python threads see the map before or after).");

  // ---- the exact contact of a map (exact_contact.hpp, self_affine.hpp) ----
  m.def(
      "self_affine_surface",
      [](const Count& nx, const Count& ny, double dx, double dy, double hurst, double rolloff_wavelength,
         double cutoff_wavelength, double rms_height, std::uint64_t seed) {
        const std::size_t columns = to_size(nx.object, "nx"), rows = to_size(ny.object, "ny");
        topo::SelfAffineSpectrum spectrum;
        spectrum.hurst = hurst;
        spectrum.rolloff_wavelength = rolloff_wavelength;
        spectrum.cutoff_wavelength = cutoff_wavelength;
        spectrum.rms_height = rms_height;
        return without_gil([&] { return topo::self_affine_surface(columns, rows, dx, dy, spectrum, seed); });
      },
      "nx"_a, "ny"_a, "dx"_a, "dy"_a, py::kw_only(), "hurst"_a = 0.8, "rolloff_wavelength"_a = 0.0,
      "cutoff_wavelength"_a = 0.0, "rms_height"_a = 1e-6, "seed"_a = 1,
      "A periodic self-affine Gaussian surface: C(q) flat below the roll-off wavenumber 2 pi / rolloff_wavelength\n"
      "(0: the map's size), q^(-2(1 + hurst)) up to 2 pi / cutoff_wavelength (0: Nyquist), zero beyond; mean 0,\n"
      "rms height exactly rms_height [m]; reproducible from seed. Raises asperity.Error for bad sizes or spectra.");
  m.def(
      "spectral_rms_gradient",
      [](const topo::HeightMap& map) { return without_gil([copy = map] { return topo::spectral_rms_gradient(copy); }); },
      "map"_a,
      "The rms gradient sqrt(<|grad h|^2>) of a map taken as periodic, from its Fourier spectrum: the slope in\n"
      "the area-load law A/A0 = kappa p / (E* h'_rms). Raises asperity.Error for missing points.");
  py::class_<topo::ContactStep>(m, "ContactStep",
                                "One load step of the exact contact: nominal pressure and load, the mean gap (the\n"
                                "separation of the flat from the mean plane), that less the mean summit height (the GW\n"
                                "curves' datum), area, stiffness -dP/d(mean gap) from the incremental solve, contact\n"
                                "patches, and the solve's iterations and residual.")
      .def_readonly("pressure", &topo::ContactStep::pressure, "Mean nominal pressure [Pa].")
      .def_readonly("load", &topo::ContactStep::load, "[N] on the map's area.")
      .def_readonly("mean_gap", &topo::ContactStep::mean_gap, "Separation of the flat from the mean plane [m].")
      .def_readonly("separation_from_mean_summit", &topo::ContactStep::separation_from_mean_summit,
                    "mean_gap less the mean summit height [m].")
      .def_readonly("approach", &topo::ContactStep::approach, "The flat's rigid-body position [m].")
      .def_readonly("area_fraction", &topo::ContactStep::area_fraction)
      .def_readonly("real_area", &topo::ContactStep::real_area, "[m^2]")
      .def_readonly("stiffness", &topo::ContactStep::stiffness, "-dP/d(mean gap) [N/m].")
      .def_readonly("stiffness_per_area", &topo::ContactStep::stiffness_per_area, "[N/m^3]")
      .def_readonly("approach_stiffness", &topo::ContactStep::approach_stiffness, "-dP/d(approach) [N/m].")
      .def_readonly("max_pressure", &topo::ContactStep::max_pressure, "[Pa]")
      .def_readonly("contact_points", &topo::ContactStep::contact_points)
      .def_readonly("clusters", &topo::ContactStep::clusters, "Contact patches (4-neighbour; wrapped when periodic).")
      .def_readonly("iterations", &topo::ContactStep::iterations)
      .def_readonly("solves", &topo::ContactStep::solves)
      .def_readonly("residual", &topo::ContactStep::residual)
      .def_readonly("coarse_iterations", &topo::ContactStep::coarse_iterations)
      .def_readonly("stiffness_iterations", &topo::ContactStep::stiffness_iterations)
      .def_readonly("stiffness_residual", &topo::ContactStep::stiffness_residual)
      .def("__repr__", [](const topo::ContactStep& s) {
        return "ContactStep(pressure=" + std::string(py::repr(py::float_(s.pressure))) +
               ", mean_gap=" + std::string(py::repr(py::float_(s.mean_gap))) +
               ", area_fraction=" + std::string(py::repr(py::float_(s.area_fraction))) + ")";
      });
  py::class_<ExactContactHandle>(
      m, "ExactContact",
      "The exact elastic contact of a height map with a flat (boundary elements on FFTs, a constrained conjugate\n"
      "gradient; docs/exact-contact.md). boundary: 'periodic' or 'padded' (non-periodic, zero padding); kernel:\n"
      "'fourier' (point force) or 'love' (pixel-constant pressure); solver: 'preconditioned' (by the inverse\n"
      "Green's function's 3 x 3 stencil) or 'polonsky-keer' (as published). Each step starts from the solution\n"
      "on the map coarsened 2 x 2 (coarse_start) or else from the last solution. A solve that does not converge raises asperity.Error. Calls on one solver run\n"
      "one at a time (a lock), without the GIL. max_memory: the bytes it may allocate (None: no limit): a map whose\n"
      "estimate (its arrays, counted) exceeds it raises asperity.Error before anything is allocated, as running out\n"
      "of memory does, with the map's size and the estimate. A pressure below one node of contact or beyond the\n"
      "solver's numerical range raises asperity.Error before iterating, naming the bound; a periodic map without\n"
      "missing points pressed flat (above its full-contact pressure, from one FFT) is answered in closed form.")
      .def(py::init([](const topo::HeightMap& map, double contact_modulus, const std::string& boundary,
                       const std::string& kernel, double tolerance, int max_iterations, int love_aliases,
                       bool stiffness, int threads, const std::string& solver, bool coarse_start,
                       std::optional<std::size_t> max_memory) {
             topo::ExactContactOptions options;
             options.contact_modulus = contact_modulus;
             if (!topo::parse_contact_boundary(boundary, options.boundary))
               throw py::value_error("boundary must be 'periodic' or 'padded', not '" + boundary + "'");
             if (!topo::parse_contact_kernel(kernel, options.kernel))
               throw py::value_error("kernel must be 'fourier' or 'love', not '" + kernel + "'");
             if (!topo::parse_contact_solver(solver, options.solver))
               throw py::value_error("solver must be 'preconditioned' or 'polonsky-keer', not '" + solver + "'");
             options.coarse_start = coarse_start;
             options.tolerance = tolerance;
             options.max_iterations = max_iterations;
             options.love_aliases = love_aliases;
             options.stiffness = stiffness;
             options.threads = threads;
             options.max_memory = max_memory.value_or(0);  // None: no limit
             return without_gil([copy = map, &options] { return std::make_unique<ExactContactHandle>(copy, options); });
           }),
           "map"_a, py::kw_only(), "contact_modulus"_a, "boundary"_a = "periodic", "kernel"_a = "fourier",
           "tolerance"_a = 1e-8, "max_iterations"_a = 20000, "love_aliases"_a = 16, "stiffness"_a = true,
           "threads"_a = 0, "solver"_a = "preconditioned", "coarse_start"_a = true, "max_memory"_a = py::none())
      .def(
          "at_pressure",
          [](ExactContactHandle& h, double pressure) {
            return without_gil([&] {
              std::lock_guard<std::mutex> guard(h.lock);
              return h.solver.at_pressure(pressure);
            });
          },
          "pressure"_a, "The contact at a mean nominal pressure [Pa] >= 0.")
      .def(
          "at_mean_gap",
          [](ExactContactHandle& h, double mean_gap) {
            return without_gil([&] {
              std::lock_guard<std::mutex> guard(h.lock);
              return h.solver.at_mean_gap(mean_gap);
            });
          },
          "mean_gap"_a, "The contact at a mean gap [m] > 0 (the separation from the mean plane).")
      .def(
          "write_table",
          [](ExactContactHandle& h, const PathName& path, const std::vector<double>& pressures, double safety_factor,
             const std::string& description, bool overwrite) {
            const std::string file = to_path(path.object);
            topo::ExactContactTable table;
            without_gil([&] {
              std::lock_guard<std::mutex> guard(h.lock);
              OutputPlan plan(overwrite);  // the output checked before the first solve too
              plan.file("path", file, output_kinds::contact_curves_table);
              plan.check();
              for (std::size_t i = 1; i < pressures.size(); ++i)
                if (!(pressures[i] > pressures[i - 1])) throw Error("write_table needs the pressures in ascending order");
              // every limit of the table checked before the first solve
              topo::check_exact_contact_table_nodes(pressures);
              for (double pressure : pressures) h.solver.check_pressure(pressure);
              const std::string options = topo::exact_contact_table_generator_options(
                  "asperity.topography.ExactContact.write_table: ", pressures);
              topo::check_exact_contact_table_text(description, options);
              std::vector<topo::ContactStep> nodes;
              for (double pressure : pressures) nodes.push_back(h.solver.at_pressure(pressure));
              table = topo::measure_exact_contact_table(h.solver, nodes, description, options, safety_factor);
              write_contact_curves_file(table.data, file, overwrite);
            });
            py::list nodes;
            for (const topo::ContactStep& step : table.nodes) nodes.append(step);
            return nodes;
          },
          "path"_a, "pressures"_a, "safety_factor"_a = topo::default_table_safety_factor, "description"_a = "",
          py::kw_only(), "overwrite"_a = false,
          "Writes the map's contact curves as a contact-curves table (asperity.ContactCurves serves it): solves at\n"
          "the pressures [Pa] (ascending, at least 3) as nodes, one more solve between each two to measure the\n"
          "served curves' error; the stored bound is that times safety_factor. Returns the nodes' ContactSteps. The\n"
          "pressures, the description's length, the solver's range and the output (a file there that is not a\n"
          "contact-curves table of asperity's is replaced only with overwrite=True) are checked before the first solve.")
      .def(
          "pressure_field",
          [](ExactContactHandle& h) {
            const std::vector<double> field = without_gil([&] {
              std::lock_guard<std::mutex> guard(h.lock);
              return h.solver.pressure_field();
            });
            return grid_array(field, h.solver.nx(), h.solver.ny());
          },
          "The last solution's pressure [Pa] as a (ny, nx) array (0 off contact).")
      .def(
          "gap_field",
          [](ExactContactHandle& h) {
            const std::vector<double> field = without_gil([&] {
              std::lock_guard<std::mutex> guard(h.lock);
              return h.solver.gap_field();
            });
            return grid_array(field, h.solver.nx(), h.solver.ny());
          },
          "The last solution's gap [m] as a (ny, nx) array (0 in contact, NaN at missing points).")
      .def_property_readonly("nx", [](const ExactContactHandle& h) { return h.solver.nx(); })
      .def_property_readonly("full_contact_pressure",
                             [](const ExactContactHandle& h) { return h.solver.pressure_range().full_contact; },
                             "The nominal pressure [Pa] above which the whole map touches (a periodic map without missing\n"
                             "points, from one FFT; inf otherwise): at_pressure answers above it in closed form.")
      .def_property_readonly("memory_estimate", [](const ExactContactHandle& h) { return h.solver.memory_estimate(); },
                             "The bytes the solver needs, as max_memory counts them.")
      .def_property_readonly("ny", [](const ExactContactHandle& h) { return h.solver.ny(); })
      .def_property_readonly("rms_height", [](const ExactContactHandle& h) { return h.solver.rms_height(); },
                             "About the mean plane [m].")
      .def_property_readonly("max_height", [](const ExactContactHandle& h) { return h.solver.max_height(); },
                             "The highest point above the mean plane [m].")
      .def_property_readonly("mean_summit_height",
                             [](const ExactContactHandle& h) { return h.solver.mean_summit_height(); },
                             "Above the mean plane [m] (NaN without summits).")
      .def_property_readonly("summits", [](const ExactContactHandle& h) { return h.solver.summits(); })
      .def_property_readonly("nominal_area", [](const ExactContactHandle& h) { return h.solver.nominal_area(); },
                             "[m^2]");

  // ---- Persson's theory of a map's spectrum (persson_contact.hpp) ----
  py::class_<topo::RadialPowerSpectrum>(
      m, "RadialPowerSpectrum",
      "The isotropic power spectral density C(q) of a map [m^4] (integral d^2q C = variance), constant over\n"
      "annuli [edges[k], edges[k + 1]) one wavenumber step 2 pi / L wide.")
      .def_property_readonly("edges", [](const topo::RadialPowerSpectrum& s) { return to_array(s.edges); }, "[1/m]")
      .def_property_readonly("density", [](const topo::RadialPowerSpectrum& s) { return to_array(s.density); }, "[m^4]")
      .def_property_readonly("points", [](const topo::RadialPowerSpectrum& s) { return to_array(s.points); })
      .def_property_readonly("edges_treatment",
                             [](const topo::RadialPowerSpectrum& s) {
                               return s.edges_treatment == topo::SpectrumEdges::none ? "none"
                                      : s.edges_treatment == topo::SpectrumEdges::hann ? "hann"
                                                                                         : "periodic_component";
                             })
      .def_readonly("map_variance", &topo::RadialPowerSpectrum::map_variance, "[m^2]")
      .def_readonly("variance", &topo::RadialPowerSpectrum::variance, "2 pi integral q C dq [m^2]")
      .def_readonly("mean_square_gradient", &topo::RadialPowerSpectrum::mean_square_gradient,
                    "2 pi integral q^3 C dq");
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
  py::class_<topo::PerssonState>(m, "PerssonState", "Persson's theory at one nominal pressure (SI units).")
      .def_readonly("pressure", &topo::PerssonState::pressure, "[Pa]")
      .def_readonly("mean_gap", &topo::PerssonState::mean_gap, "From the mean plane [m].")
      .def_readonly("area_fraction", &topo::PerssonState::area_fraction)
      .def_readonly("stiffness_per_area", &topo::PerssonState::stiffness_per_area, "-dp/du [N/m^3]");
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

  // ---- contact curves of the fits (contact_comparison.hpp) ----
  py::class_<topo::ContactOptions>(m, "ContactOptions", "The contact curves of each fit.")
      .def(py::init([](double contact_modulus, double nominal_area, std::vector<double> pressures, int curve_points,
                       double scene_tolerance, const PathName& table_path, int threads, bool persson, bool exact,
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
             options.exact = exact;
             if (!topo::parse_contact_boundary(exact_boundary, options.exact_boundary))
               throw py::value_error("exact_boundary must be 'periodic' or 'padded', not '" + exact_boundary + "'");
             if (!topo::parse_contact_kernel(exact_kernel, options.exact_kernel))
               throw py::value_error("exact_kernel must be 'fourier' or 'love', not '" + exact_kernel + "'");
             options.exact_points = exact_points;
             options.exact_tolerance = exact_tolerance;
             return options;
           }),
           "contact_modulus"_a, "nominal_area"_a = 0.0, "pressures"_a = std::vector<double>{}, "curve_points"_a = 61,
           "scene_tolerance"_a = 1e-8, "table_path"_a = "", "threads"_a = 0, "persson"_a = true, "exact"_a = false,
           "exact_boundary"_a = "padded", "exact_kernel"_a = "love", "exact_points"_a = 13, "exact_tolerance"_a = 1e-8,
           "contact_modulus E* [Pa] (plane strain); nominal_area A0 [m^2] (0: the measured area); pressures of\n"
           "interest [Pa] (empty: E* x 1e-5, 1e-4, 1e-3); table_path: a full table for the Weibull curves\n"
           "instead of exact-shape scene tables made for the fitted shapes; persson: Persson's theory of the\n"
           "map's spectrum beside them; exact: the exact elastic contact of the map (boundary elements,\n"
           "exact_boundary 'padded' or 'periodic', exact_kernel 'love' or 'fourier', exact_points solves along\n"
           "the pressure range), which every curve is then compared with.")
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
      .def_readwrite("exact", &topo::ContactOptions::exact)
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
  py::class_<topo::ModelContact>(m, "ModelContact", "The contact curve of one height model.")
      .def_readonly("label", &topo::ModelContact::label,
                    "measured-summits, measured-summits-own-radii, gaussian-moments, gaussian, weibull-tail,\n"
                    "weibull-bounded, persson or exact.")
      .def_readonly("served", &topo::ModelContact::served)
      .def_property_readonly("note", [](const topo::ModelContact& c) { return path_text(c.note); },
                             "The table that served it, or why there is no curve.")
      .def_readonly("surface", &topo::ModelContact::surface)
      .def_readonly("mean_summit_height", &topo::ModelContact::mean_summit_height, "[m], in the map's height frame.")
      .def_property_readonly("curve", [physical_state_type](const topo::ModelContact& c) {
        return states_record(physical_state_type, c.curve);
      }, "asperity.PhysicalState of arrays over the pressure range.")
      .def_property_readonly("at_pressures", [physical_state_type](const topo::ModelContact& c) {
        return states_record(physical_state_type, c.at_pressures);
      }, "asperity.PhysicalState of arrays at the pressures of interest.")
      .def_property_readonly("stiffness_over_measured", [](const topo::ModelContact& c) { return to_array(c.stiffness_over_measured); })
      .def_property_readonly("separation_minus_measured", [](const topo::ModelContact& c) { return to_array(c.separation_minus_measured); }, "[m]")
      .def_property_readonly("stiffness_over_exact", [](const topo::ModelContact& c) { return to_array(c.stiffness_over_exact); })
      .def_property_readonly("area_over_exact", [](const topo::ModelContact& c) { return to_array(c.area_over_exact); })
      .def_property_readonly("separation_minus_exact", [](const topo::ModelContact& c) { return to_array(c.separation_minus_exact); }, "[m]");
  py::class_<topo::ContactComparison>(m, "ContactComparison", "The contact curves of the fits side by side.")
      .def_readonly("options", &topo::ContactComparison::options)
      .def_property_readonly("pressures", [](const topo::ContactComparison& c) { return to_array(c.pressures); })
      .def_readonly("pressure_min", &topo::ContactComparison::pressure_min)
      .def_readonly("pressure_max", &topo::ContactComparison::pressure_max)
      .def_readonly("nominal_area", &topo::ContactComparison::nominal_area)
      .def_readonly("models", &topo::ContactComparison::models)
      .def_readonly("closest", &topo::ContactComparison::closest, "The fitted model nearest the measured summits.")
      .def_readonly("headline", &topo::ContactComparison::headline)
      .def_readonly("exact_method", &topo::ContactComparison::exact_method, "How the exact contact was solved.")
      .def_readonly("closest_to_exact", &topo::ContactComparison::closest_to_exact)
      .def_readonly("exact_headline", &topo::ContactComparison::exact_headline)
      .def(
          "find",
          [](const topo::ContactComparison& c, const std::string& label) -> std::optional<topo::ModelContact> {
            const topo::ModelContact* found = c.find(label);
            return found ? std::optional<topo::ModelContact>(*found) : std::nullopt;
          },
          "label"_a, "The model of that label, or None.");

  // ---- the whole path (analysis.hpp, surface_report.hpp) ----
  py::class_<topo::SamplingRow>(m, "SamplingRow", "Summits and moments at factor times the sampling interval.")
      .def_readonly("factor", &topo::SamplingRow::factor)
      .def_readonly("dx", &topo::SamplingRow::dx)
      .def_readonly("dy", &topo::SamplingRow::dy)
      .def_readonly("summits", &topo::SamplingRow::summits)
      .def_readonly("density", &topo::SamplingRow::density)
      .def_readonly("radius", &topo::SamplingRow::radius)
      .def_readonly("m2", &topo::SamplingRow::m2)
      .def_readonly("m4", &topo::SamplingRow::m4)
      .def_readonly("alpha", &topo::SamplingRow::alpha)
      .def_readonly("anisotropy", &topo::SamplingRow::anisotropy);
  py::class_<topo::SurfaceVerdict>(m, "SurfaceVerdict",
                                   "Is the surface Gaussian (its heights' and its summit heights' tests against surrogate\n"
                                   "surfaces of its own spectrum, each at half the significance), which way its heights\n"
                                   "lean, and the model named for the contact, in words.")
      .def_readonly("tested", &topo::SurfaceVerdict::tested)
      .def_readonly("gaussian_rejected", &topo::SurfaceVerdict::gaussian_rejected)
      .def_readonly("p_heights", &topo::SurfaceVerdict::p_heights)
      .def_readonly("p_summits", &topo::SurfaceVerdict::p_summits)
      .def_readonly("p_heights_bound", &topo::SurfaceVerdict::p_heights_bound)
      .def_readonly("p_summits_bound", &topo::SurfaceVerdict::p_summits_bound)
      .def_readonly("orientation", &topo::SurfaceVerdict::orientation,
                    "The heights' Weibull (weibull_tail or weibull_bounded), or gaussian: no orientation found.")
      .def_readonly("named", &topo::SurfaceVerdict::named)
      .def_readonly("model", &topo::SurfaceVerdict::model, "The model named for the contact (when named).")
      .def_readonly("text", &topo::SurfaceVerdict::text)
      .def("__repr__", [](const topo::SurfaceVerdict& v) { return v.text; });
  py::class_<topo::AnalysisOptions>(m, "AnalysisOptions", "What analyse_height_map and analyse_surface_file do.")
      .def(py::init([](const std::optional<topo::ReadOptions>& read, bool level,
                       const std::optional<topo::SummitOptions>& summits,
                       const std::optional<topo::AssessmentOptions>& assessment, bool fit_heights,
                       std::size_t max_height_sample, std::vector<std::size_t> sampling_factors,
                       std::optional<topo::ContactOptions> contact, std::size_t max_fit_sample) {
             topo::AnalysisOptions options;
             if (read) options.read = *read;
             options.level = level;
             if (summits) options.summits = *summits;
             if (assessment) options.assessment = *assessment;
             options.fit_heights = fit_heights;
             options.max_height_sample = max_height_sample;
             options.sampling_factors = std::move(sampling_factors);
             options.contact = std::move(contact);
             options.max_fit_sample = max_fit_sample;
             return options;
           }),
           "read"_a = py::none(), "level"_a = true, "summits"_a = py::none(), "assessment"_a = py::none(),
           "fit_heights"_a = true, "max_height_sample"_a = topo::AnalysisOptions{}.max_height_sample,
           "sampling_factors"_a = topo::AnalysisOptions{}.sampling_factors, "contact"_a = py::none(),
           "max_fit_sample"_a = topo::AnalysisOptions{}.max_fit_sample,
           "read: ReadOptions (files only); level: subtract the least-squares plane; summits: SummitOptions;\n"
           "assessment: AssessmentOptions (the bootstrap); fit_heights: also fit the heights, thinned to one per\n"
           "correlation length and at most max_height_sample; sampling_factors: summits at k dx; contact:\n"
           "ContactOptions for the contact curves of each fit (None: no curves); max_fit_sample: the summit\n"
           "heights fitted, all up to this many, else a reproducible random subsample of this many.")
      .def_readwrite("read", &topo::AnalysisOptions::read)
      .def_readwrite("level", &topo::AnalysisOptions::level)
      .def_readwrite("summits", &topo::AnalysisOptions::summits)
      .def_readwrite("assessment", &topo::AnalysisOptions::assessment)
      .def_readwrite("fit_heights", &topo::AnalysisOptions::fit_heights)
      .def_readwrite("max_height_sample", &topo::AnalysisOptions::max_height_sample)
      .def_readwrite("sampling_factors", &topo::AnalysisOptions::sampling_factors)
      .def_readwrite("contact", &topo::AnalysisOptions::contact)
      .def_readwrite("max_fit_sample", &topo::AnalysisOptions::max_fit_sample);

  py::class_<topo::ReportOutcome>(m, "ReportOutcome", "What write_report wrote.")
      .def_property_readonly("files", [](const topo::ReportOutcome& o) { return path_texts(o.files); })
      .def_readonly("plots", &topo::ReportOutcome::plots)
      .def_readonly("plot_note", &topo::ReportOutcome::plot_note, "Why there are no plots (a map at its noise floor).");

  auto write_report = [](const topo::SurfaceAnalysis& analysis, const PathName& directory, bool overwrite) {
    const std::string path = to_path(directory.object, "directory");
    return without_gil([copy = analysis, &path, overwrite] { return topo::write_report(copy, path, overwrite); });
  };
  const char* report_doc =
      "Writes a report folder (created if needed): report.md with the plots, report.json, curves.csv,\n"
      "summits.csv, fits.svg and contact.svg (drawn by the library: nothing is run). Each file is replaced\n"
      "atomically, no link in the folder is followed, one run writes the folder at a time and an earlier\n"
      "report's files are not left beside this one's; a file of the user's under a report file's name is\n"
      "kept (the call fails) unless overwrite=True. Raises asperity.Error on a write error.";
  py::class_<topo::NoiseFloor>(m, "NoiseFloor",
                               "A roughness at the level of the heights' quantization q: Sq under 10 q / sqrt(12).")
      .def_readonly("reached", &topo::NoiseFloor::reached)
      .def_readonly("resolution", &topo::NoiseFloor::resolution, "q [m] (HeightMap.height_resolution).")
      .def_readonly("rms_limit", &topo::NoiseFloor::rms_limit, "10 q / sqrt(12) [m].")
      .def_readonly("text", &topo::NoiseFloor::text)
      .def("__repr__", [](const topo::NoiseFloor& f) {
        return py::str("NoiseFloor(reached={!r}, resolution={!r})").format(f.reached, f.resolution);
      });

  py::class_<topo::SurfaceAnalysis>(m, "SurfaceAnalysis",
                                    "A measured surface analysed: the map as analysed, statistics, moments, summits, the fits\n"
                                    "with their evidence, and the contact curves. to_dict() gives all of it as the JSON document\n"
                                    "(schema asperity-surface/2) that `asperity surface --json` writes.")
      .def_readonly("map", &topo::SurfaceAnalysis::map, "The map as analysed (leveled when asked).")
      .def_readonly("leveled", &topo::SurfaceAnalysis::leveled)
      .def_readonly("plane", &topo::SurfaceAnalysis::plane, "The plane subtracted.")
      .def_readonly("statistics", &topo::SurfaceAnalysis::statistics)
      .def_readonly("moments", &topo::SurfaceAnalysis::moments)
      .def_readonly("correlation", &topo::SurfaceAnalysis::correlation)
      .def_readonly("summits", &topo::SurfaceAnalysis::summits)
      .def_readonly("sampling", &topo::SurfaceAnalysis::sampling, "Summits and moments at 1, 2, 4 times dx.")
      .def_readonly("noise_floor", &topo::SurfaceAnalysis::noise_floor,
                    "Whether the roughness is at the level of the heights' quantization (then no summits, fits\n"
                    "or contact curves follow the statistics).")
      .def_readonly("summit_heights", &topo::SurfaceAnalysis::summit_heights, "The fits of the summit heights.")
      .def_readonly("summits_fitted", &topo::SurfaceAnalysis::summits_fitted,
                    "The summit heights fitted (all, or a random subsample of AnalysisOptions.max_fit_sample).")
      .def_readonly("heights", &topo::SurfaceAnalysis::heights,
                    "The fits of the heights (a fixed random sample of points), or None.")
      .def_readonly("surrogates", &topo::SurfaceAnalysis::surrogates, "The ensemble's size.")
      .def_readonly("verdict", &topo::SurfaceAnalysis::verdict)
      .def_readonly("contact", &topo::SurfaceAnalysis::contact, "The contact curves, or None (no contact modulus).")
      .def_readonly("options", &topo::SurfaceAnalysis::options)
      .def("to_dict", [](const topo::SurfaceAnalysis& a) {
        return py::module_::import("json").attr("loads")(path_text(topo::analysis_json(a)));
      }, "The analysis as a dict: the JSON document (schema asperity-surface/2); NaN is None.")
      .def("json", [](const topo::SurfaceAnalysis& a) { return path_text(topo::analysis_json(a)); },
           "The JSON document (schema asperity-surface/2) as text.")
      .def("summary", [](const topo::SurfaceAnalysis& a) { return path_text(topo::analysis_summary(a)); },
           "The short summary `asperity surface` prints.")
      .def("write_report", write_report, "directory"_a, py::kw_only(), "overwrite"_a = false, report_doc);

  auto analysis_options = [](std::optional<topo::AnalysisOptions> options, const py::kwargs& fields) {
    if (fields.size() == 0) return options.value_or(topo::AnalysisOptions{});
    if (options) throw py::type_error("give options or its fields as keywords, not both");
    return py::type::of<topo::AnalysisOptions>()(**fields).cast<topo::AnalysisOptions>();
  };
  m.def(
      "analyse_height_map",
      [analysis_options](const topo::HeightMap& map, std::optional<topo::AnalysisOptions> options,
                         const py::kwargs& fields) {
        const topo::AnalysisOptions chosen = analysis_options(std::move(options), fields);
        return without_gil(
            [copy = map, &chosen]() mutable { return topo::analyse_height_map(std::move(copy), chosen); });
      },
      "map"_a, "options"_a = py::none(),
      "The whole path on a map (not changed): leveling, statistics, moments, summits, the fits of the summit\n"
      "heights (and of the thinned heights) with their evidence, and the contact curves when options.contact\n"
      "is given. options: an AnalysisOptions, or its fields as keywords. Raises asperity.Error (e.g. fewer than\n"
      "5 summits).");
  m.def(
      "analyse_surface_file",
      [analysis_options](const PathName& path, std::optional<topo::AnalysisOptions> options, const py::kwargs& fields) {
        const topo::AnalysisOptions chosen = analysis_options(std::move(options), fields);
        const std::string file = to_path(path.object);
        return without_gil([&] { return topo::analyse_surface_file(file, chosen); });
      },
      "path"_a, "options"_a = py::none(),
      "read_height_map and analyse_height_map in one call: options.read says how to read the file (format,\n"
      "pixel sizes, units); options: an AnalysisOptions, or its fields as keywords.");
  m.def(
      "analysis_json", [](const topo::SurfaceAnalysis& a) { return path_text(topo::analysis_json(a)); }, "analysis"_a,
      "The JSON document (schema asperity-surface/2) as text.");
  m.def(
      "analysis_summary", [](const topo::SurfaceAnalysis& a) { return path_text(topo::analysis_summary(a)); },
      "analysis"_a, "The short summary `asperity surface` prints.");
  m.def("write_report", write_report, "analysis"_a, "directory"_a, py::kw_only(), "overwrite"_a = false, report_doc);
}

}  // namespace asperity::python
