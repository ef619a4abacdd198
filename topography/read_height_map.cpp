#include <algorithm>
#include <cctype>
#include <cstring>
#include <limits>

#include "asperity/topography/height_map_io.hpp"
#include "asperity/topography/surface_formats.hpp"
#include "input_file.hpp"
#include "reader_support.hpp"

namespace asperity::topography {

const std::vector<SurfaceFormat>& surface_formats() {
  static const std::vector<SurfaceFormat> formats = {
      {HeightMapFormat::x3p, "x3p", "x3p", {}, "PK\x03\x04", {"x3p"},
       "ISO 25178-72 XML 3D surface profile (a zip archive)", &read_x3p},
      {HeightMapFormat::gsf, "gsf", "gsf", {}, "Gwyddion Simple Field", {"gsf"}, "Gwyddion Simple Field",
       &read_gsf},
      {HeightMapFormat::ascii_matrix, "ascii-matrix", "ascii_matrix", {"matrix"}, nullptr, {"txt", "asc", "dat"},
       "a matrix of heights as text (Gwyddion's ASCII export, AFM text dumps)", &read_ascii_matrix},
      {HeightMapFormat::xyz, "xyz", "xyz", {"csv"}, nullptr, {"xyz", "csv"}, "x y z points on a grid, as text",
       &read_xyz},
  };
  return formats;
}

const SurfaceFormat* surface_format(HeightMapFormat format) {
  for (const SurfaceFormat& entry : surface_formats())
    if (entry.format == format) return &entry;
  return nullptr;
}

std::string surface_format_names() {
  std::string names = "auto";
  for (const SurfaceFormat& entry : surface_formats()) {
    std::string shortest = entry.name;
    for (const char* alias : entry.aliases)
      if (std::strlen(alias) < shortest.size()) shortest = alias;
    names += ", " + shortest;
  }
  return names;
}

bool parse_height_map_format(const std::string& name, HeightMapFormat& out) {
  if (name == "auto") {
    out = HeightMapFormat::automatic;
    return true;
  }
  for (const SurfaceFormat& entry : surface_formats()) {
    bool match = name == entry.name;
    for (const char* alias : entry.aliases) match = match || name == alias;
    if (match) {
      out = entry.format;
      return true;
    }
  }
  return false;
}

HeightMap read_height_map(const std::string& path, const ReadOptions& options) {
  const SurfaceFormat* chosen = surface_format(options.format);
  if (!chosen) {  // automatic: by the first bytes, then by the extension
    std::vector<unsigned char> head;
    {
      detail::InputFile file(path, std::numeric_limits<std::uint64_t>::max());
      head.resize(static_cast<std::size_t>(std::min<std::uint64_t>(32, file.size())));
      file.read_at(0, head.data(), head.size());
    }
    const auto starts = [&](const char* magic) {
      return head.size() >= std::strlen(magic) && std::memcmp(head.data(), magic, std::strlen(magic)) == 0;
    };
    std::string extension;
    if (const std::size_t dot = path.find_last_of('.'); dot != std::string::npos && path.find('/', dot) == std::string::npos)
      extension = path.substr(dot + 1);
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (const SurfaceFormat& entry : surface_formats())
      if (!chosen && entry.magic && starts(entry.magic)) chosen = &entry;
    for (const SurfaceFormat& entry : surface_formats())
      if (!chosen && !entry.magic)
        for (const char* known : entry.extensions)
          if (extension == known) chosen = &entry;
    if (!chosen) {
      std::string text_extensions;
      for (const SurfaceFormat& entry : surface_formats())
        if (!entry.magic) {
          std::string list;
          for (const char* known : entry.extensions) list += (list.empty() ? "." : "/.") + std::string(known);
          text_extensions += (text_extensions.empty() ? "" : " or ") + list + " (" + entry.name + ")";
        }
      detail::fail(path, "unknown format (not X3P or GSF by its first bytes, and the extension '" +
                             detail::printable(extension) + "' is not " + text_extensions + "): give --format");
    }
  }
  return chosen->read(path, options);
}

}  // namespace asperity::topography
