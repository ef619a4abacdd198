// The surface file formats, in one table made from the one list ASPERITY_SURFACE_FORMATS
// (height_map_io.hpp): each format's name (and the other names it answers to), the bytes that
// start its files, its file extensions, whether its files carry units, and its reader.
// read_height_map's choice by content and extension, parse_height_map_format, the commands'
// --format and help texts and the Python bindings all read this table: a new format is an entry
// of the list and its reader read_ID (docs/architecture.md, "Recipes").
#pragma once
#include <string>
#include <vector>

#include "asperity/topography/height_map_io.hpp"

namespace asperity::topography {

struct SurfaceFormat {
  HeightMapFormat format;
  const char* name;                      // "x3p", "ascii-matrix": what --format and Python take
  const char* python_name;               // the HeightMapFormat member in Python ("ascii_matrix")
  std::vector<const char*> aliases;      // other names it answers to ("matrix")
  const char* magic;                     // the bytes its files start with; null: none (text)
  std::vector<const char*> extensions;   // lower case, without the dot: the choice by extension
                                         // (only where the first bytes tell no format)
  bool needs_units;                      // its files carry no units: ReadOptions::lateral_unit required
  const char* description;               // one line, for help texts
  HeightMap (*read)(const std::string& path, const ReadOptions& options);
};

// Every format, in the order help texts list them.
const std::vector<SurfaceFormat>& surface_formats();
// The format of `format`; null for HeightMapFormat::automatic.
const SurfaceFormat* surface_format(HeightMapFormat format);
// "auto, x3p, gsf, matrix, xyz": the names help texts and messages list (each format's shortest).
std::string surface_format_names();
// "x3p, gsf, ascii-matrix, xyz": every format's name, as descriptions list them.
std::string surface_format_list();
// "xyz": the formats whose files carry no units (needs_units), as help texts list them.
std::string surface_formats_without_units();

}  // namespace asperity::topography
