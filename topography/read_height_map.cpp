#include <algorithm>
#include <cctype>
#include <cstring>
#include <limits>

#include "asperity/topography/height_map_io.hpp"
#include "input_file.hpp"
#include "reader_support.hpp"

namespace asperity::topography {

bool parse_height_map_format(const std::string& name, HeightMapFormat& out) {
  if (name == "auto") out = HeightMapFormat::automatic;
  else if (name == "x3p") out = HeightMapFormat::x3p;
  else if (name == "gsf") out = HeightMapFormat::gsf;
  else if (name == "ascii-matrix" || name == "matrix") out = HeightMapFormat::ascii_matrix;
  else if (name == "xyz" || name == "csv") out = HeightMapFormat::xyz;
  else return false;
  return true;
}

HeightMap read_height_map(const std::string& path, const ReadOptions& options) {
  HeightMapFormat format = options.format;
  if (format == HeightMapFormat::automatic) {
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
    if (starts("PK\x03\x04")) format = HeightMapFormat::x3p;
    else if (starts("Gwyddion Simple Field")) format = HeightMapFormat::gsf;
    else if (extension == "xyz" || extension == "csv") format = HeightMapFormat::xyz;
    else if (extension == "txt" || extension == "asc" || extension == "dat") format = HeightMapFormat::ascii_matrix;
    else
      detail::fail(path, "unknown format (not X3P or GSF by its first bytes, and the extension '" +
                             detail::printable(extension) +
                             "' is not .txt/.asc/.dat (matrix) or .xyz/.csv): give --format");
  }
  switch (format) {
    case HeightMapFormat::x3p: return read_x3p(path, options);
    case HeightMapFormat::gsf: return read_gsf(path, options);
    case HeightMapFormat::ascii_matrix: return read_ascii_matrix(path, options);
    case HeightMapFormat::xyz: return read_xyz(path, options);
    case HeightMapFormat::automatic: break;
  }
  detail::fail(path, "unknown format");
}

}  // namespace asperity::topography
