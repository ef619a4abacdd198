// How a height map file is read, the same options in every command that reads one
// (`asperity surface`, `asperity exact-contact`): --format, --pixel-size, --unit, --height-unit.
#pragma once
#include <CLI/CLI.hpp>
#include <string>

#include "asperity/topography/height_map_io.hpp"

namespace asperity::cli {

struct MapOptions {
  std::string format, pixel_size, unit, height_unit;  // as given (empty: not given)
};

// The four options, in `group`.
void add_map_options(CLI::App& command, MapOptions& options, const std::string& group);

// The reader's options from them; a usage error for an unknown format or a bad --pixel-size.
topography::ReadOptions read_options(const MapOptions& options);

}  // namespace asperity::cli
