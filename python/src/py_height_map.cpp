// Height maps (asperity/topography/height_map.hpp, height_map_io.hpp, units.hpp): HeightMap, the
// formats' enum, the readers and the writer, lengths with units.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "topography_helpers.hpp"
#include "asperity/topography/height_map.hpp"
#include "asperity/topography/height_map_io.hpp"
#include "asperity/topography/surface_formats.hpp"
#include "asperity/topography/units.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace asperity::python {

namespace topo = asperity::topography;

namespace {

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

// HeightMapFormat (from the formats' table), ReadOptions, the readers, write_gsf and the units
void bind_height_map_io(py::module_& m) {
  // the members from the formats' table (asperity/topography/surface_formats.hpp)
  py::enum_<topo::HeightMapFormat> formats(m, "HeightMapFormat",
                                           "A height map file's format (automatic: by content, then extension).");
  formats.value("automatic", topo::HeightMapFormat::automatic);
  for (const topo::SurfaceFormat& format : topo::surface_formats()) formats.value(format.python_name, format.format);

  static const std::string read_options_doc =
      "format: " + topo::surface_format_names() + " (auto: by content, then extension), or a HeightMapFormat.\n"
      "pixel_size_x, pixel_size_y [m]: sampling intervals for formats without them, or overriding the\n"
      "file's (0: the file's; pixel_size_y 0: pixel_size_x). lateral_unit, height_unit: 'um', 'nm', ...\n"
      "for formats without units (" + topo::surface_formats_without_units() +
      "), overriding the file's for the others. max_points: a header is\n"
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
  // read_ID for each format of the table: its reader, documented by its description
  static std::deque<std::string> reader_texts;  // pybind11 keeps the name's and the docstring's pointers
  for (const topo::SurfaceFormat& format : topo::surface_formats()) {
    const std::string& name = reader_texts.emplace_back(std::string("read_") + format.python_name);
    const std::string& doc = reader_texts.emplace_back(
        std::string("read_height_map for one format: ") + format.description + " ('" + format.name + "')." +
        (format.needs_units ? " Its files carry no units: lateral_unit is required." : ""));
    m.def(name.c_str(), reader(format.read), "path"_a, "options"_a = py::none(), doc.c_str());
  }
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
}

}  // namespace

void bind_height_map(py::module_& m) {
  // ---- height maps (height_map.hpp, height_map_io.hpp, units.hpp) ----
  static const std::string map_format_doc = topo::surface_format_list() + ", synthetic or array.";
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
      .def_readwrite("format", &topo::HeightMap::format, map_format_doc.c_str())
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

  bind_height_map_io(m);
}

}  // namespace asperity::python
