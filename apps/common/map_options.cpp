#include "map_options.hpp"

#include <cmath>
#include <vector>

#include "asperity/number_text.hpp"
#include "asperity/topography/surface_formats.hpp"
#include "asperity/topography/units.hpp"
#include "command_line.hpp"
#include "option_helpers.hpp"

namespace asperity::cli {
namespace topo = asperity::topography;

void add_map_options(CLI::App& command, MapOptions& o, const std::string& group) {
  add_text(command, "--format", o.format, topo::surface_format_names() + " (default auto: by content, then extension)")
      ->type_name("NAME")->group(group);
  add_text(command, "--pixel-size", o.pixel_size,
           "sampling interval with its unit, one or x,y (1.5um or 1.5um,2um); required when the file has none, "
           "else it overrides the file's")
      ->type_name("LENGTH[,LENGTH]")->group(group);
  add_text(command, "--unit", o.unit,
           "unit of x, y (and of heights unless --height-unit) for files without units (" +
               topo::surface_formats_without_units() + "), and of a bare --pixel-size")
      ->type_name("UNIT")->group(group);
  add_text(command, "--height-unit", o.height_unit, "unit of the heights in the file (overrides the file's)")
      ->type_name("UNIT")->group(group);
}

topo::ReadOptions read_options(const MapOptions& o) {
  topo::ReadOptions read;
  if (!o.format.empty() && !topo::parse_height_map_format(o.format, read.format))
    usage("--format: unknown format '" + quote_text(o.format) + "' (" + topo::surface_format_names() + ")");
  read.lateral_unit = o.unit;
  read.height_unit = o.height_unit;
  if (!o.pixel_size.empty()) {
    const std::vector<std::string> parts = split(o.pixel_size, ',');
    if (parts.empty() || parts.size() > 2) usage("--pixel-size: one length, or two (x,y)");
    read.pixel_size_x = topo::parse_length(parts[0], o.unit);
    read.pixel_size_y = parts.size() == 2 ? topo::parse_length(parts[1], o.unit) : read.pixel_size_x;
    if (!(read.pixel_size_x > 0 && read.pixel_size_y > 0 && std::isfinite(read.pixel_size_x) &&
          std::isfinite(read.pixel_size_y)))
      usage("--pixel-size must be positive");
  }
  return read;
}

}  // namespace asperity::cli
