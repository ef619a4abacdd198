// The surface file formats, in one table: each format's name (and the other names it answers
// to), the bytes that start its files, its file extensions and its reader. read_height_map's
// choice by content and extension, parse_height_map_format, the command's --format help and the
// Python bindings all read this table: a new format is an entry here, its HeightMapFormat value
// and its reader (height_map_io.hpp).
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
  const char* description;               // one line, for help texts
  HeightMap (*read)(const std::string& path, const ReadOptions& options);
};

// Every format, in the order help texts list them.
const std::vector<SurfaceFormat>& surface_formats();
// The format of `format`; null for HeightMapFormat::automatic.
const SurfaceFormat* surface_format(HeightMapFormat format);
// "auto, x3p, gsf, matrix, xyz": the names help texts and messages list (each format's shortest).
std::string surface_format_names();

}  // namespace asperity::topography
