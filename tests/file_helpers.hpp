// Files for the tests of writers: a fresh folder each, its entries, a file's bytes, a file planted.
#pragma once
#include <dirent.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace test_files {

// ASPERITY_TEST_BINARY_DIR/PREFIX-NAME, emptied.
inline std::string fresh_directory(const std::string& prefix, const std::string& name) {
  const std::string path = std::string(ASPERITY_TEST_BINARY_DIR) + "/" + prefix + "-" + name;
  std::system(("rm -rf '" + path + "'").c_str());
  mkdir(path.c_str(), 0755);
  return path;
}

inline std::string read_bytes(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(file), {});
}

inline void plant(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

// The folder's entries but . and .., sorted.
inline std::vector<std::string> entries(const std::string& directory) {
  std::vector<std::string> names;
  if (DIR* listing = opendir(directory.c_str())) {
    while (const dirent* entry = readdir(listing))
      if (std::string(entry->d_name) != "." && std::string(entry->d_name) != "..") names.push_back(entry->d_name);
    closedir(listing);
  }
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace test_files
