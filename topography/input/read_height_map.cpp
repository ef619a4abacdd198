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
#define ASPERITY_LIST_ITEMS(...) __VA_ARGS__
#define ASPERITY_SURFACE_FORMAT_ENTRY(id, name, aliases, magic, extensions, needs_units, description)           \
  SurfaceFormat{HeightMapFormat::id, name, #id, {ASPERITY_LIST_ITEMS aliases}, magic, {ASPERITY_LIST_ITEMS extensions}, \
                needs_units, description, &read_##id},
      ASPERITY_SURFACE_FORMATS(ASPERITY_SURFACE_FORMAT_ENTRY)
#undef ASPERITY_SURFACE_FORMAT_ENTRY
#undef ASPERITY_LIST_ITEMS
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

std::string surface_format_list() {
  std::string names;
  for (const SurfaceFormat& entry : surface_formats()) names += (names.empty() ? "" : ", ") + std::string(entry.name);
  return names;
}

std::string surface_formats_without_units() {
  std::string names;
  for (const SurfaceFormat& entry : surface_formats())
    if (entry.needs_units) names += (names.empty() ? "" : ", ") + std::string(entry.name);
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
      std::string by_magic, text_extensions;  // "X3P or GSF": the formats told by their first bytes
      for (const SurfaceFormat& entry : surface_formats())
        if (entry.magic) {
          std::string name = entry.name;
          std::transform(name.begin(), name.end(), name.begin(),
                         [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
          by_magic += (by_magic.empty() ? "" : " or ") + name;
        } else {
          std::string list;
          for (const char* known : entry.extensions) list += (list.empty() ? "." : "/.") + std::string(known);
          text_extensions += (text_extensions.empty() ? "" : " or ") + list + " (" + entry.name + ")";
        }
      detail::fail(path, "unknown format (not " + by_magic + " by its first bytes, and the extension '" +
                             detail::printable(extension) + "' is not " + text_extensions + "): give --format");
    }
  }
  return chosen->read(path, options);
}

}  // namespace asperity::topography
