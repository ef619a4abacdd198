// The output policy (asperity/output.hpp) against a hostile folder: the input's bytes plant
// files, links (to a victim outside the folder), FIFOs and directories under the names a run
// writes, then plan outputs (kinds, an input among them, overwrite or not) and either commit
// or abandon them. Whatever the bytes: the victim and the input never change, a planted FIFO is
// never opened (a blocking open would hang: libFuzzer's timeout), no temporary is left, an
// abandoned or refused run leaves the folder exactly as it was, and a committed one leaves each
// output a regular file with exactly the bytes staged.
#include <dirent.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/output.hpp"

namespace {
using namespace asperity;

struct Bytes {
  const std::uint8_t* data;
  std::size_t size, at = 0;
  unsigned next(unsigned limit) { return at < size ? data[at++] % limit : 0; }
};

const char* const names[] = {"a.inp", "b.h5", "step-1-gap.pgm", "report.md", "curves.csv", "map.txt"};
const OutputKind* const kinds[] = {&output_kinds::card, &output_kinds::contact_curves_table, &output_kinds::field_image,
                                   &output_kinds::report_file, &output_kinds::results_csv, &output_kinds::any_file};
const char* const heads[] = {"** asperity card\n", "P5\n# asperity x\n1 1\n65535\nab", "# Surface report: m\n",
                             "model,pressure_Pa,x\n", "the user's own\n", ""};

std::string read_all(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(file), {});
}

// Every entry of the folder (and one level below): its type and, for a regular file, its bytes.
std::map<std::string, std::string> snapshot(const std::string& folder) {
  std::map<std::string, std::string> state;
  DIR* listing = opendir(folder.c_str());
  if (!listing) return state;
  while (const dirent* entry = readdir(listing)) {
    const std::string name = entry->d_name;
    if (name == "." || name == "..") continue;
    const std::string path = folder + "/" + name;
    struct stat status {};
    lstat(path.c_str(), &status);
    if (S_ISREG(status.st_mode)) state[name] = "file:" + read_all(path);
    else if (S_ISLNK(status.st_mode)) state[name] = "link";
    else if (S_ISFIFO(status.st_mode)) state[name] = "fifo";
    else if (S_ISDIR(status.st_mode)) {
      state[name] = "dir";
      for (const auto& [inner, what] : snapshot(path)) state[name + "/" + inner] = what;
    } else state[name] = "other";
  }
  closedir(listing);
  return state;
}

void clear(const std::string& folder) { std::system(("rm -rf '" + folder + "'/* '" + folder + "'/.[!.]*").c_str()); }

void plant(Bytes& in, const std::string& folder, const std::string& victim) {
  for (const char* name : names) {
    const std::string path = folder + "/" + name;
    switch (in.next(6)) {
      case 0: break;  // nothing there
      case 1: std::ofstream(path, std::ios::binary) << heads[in.next(6)]; break;
      case 2: symlink(victim.c_str(), path.c_str()); break;
      case 3: mkfifo(path.c_str(), 0600); break;
      case 4: mkdir(path.c_str(), 0755); break;
      default: std::ofstream(path, std::ios::binary) << heads[in.next(6)] << in.next(256); break;
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string root = [] {
    char pattern[] = "/tmp/fuzz-output-XXXXXX";
    const std::string made = mkdtemp(pattern);
    mkdir((made + "/out").c_str(), 0755);
    std::ofstream(made + "/victim") << "the victim";
    return made;
  }();
  const std::string folder = root + "/out", victim = root + "/victim";
  clear(folder);
  Bytes in{data, size};
  plant(in, folder, victim);
  const std::map<std::string, std::string> before = snapshot(folder);

  OutputPlan plan(in.next(2) == 1);
  const std::string input = folder + "/map.txt";
  plan.input(input);
  std::vector<std::string> files;
  for (unsigned k = 0, count = 1 + in.next(3); k < count; ++k) {
    const std::string path = folder + (in.next(4) == 0 ? "/./" : "/") + names[in.next(6)];
    plan.file("--out" + std::to_string(k), path, *kinds[in.next(6)]);
    files.push_back(path);
  }
  const bool with_folder = in.next(2) == 1;
  const std::string subfolder = folder + "/" + names[in.next(6)];
  if (with_folder) plan.folder("--fields", subfolder, {{"x.pgm", &output_kinds::field_image}});
  const bool commit = in.next(3) != 0;
  bool committed = false;
  try {
    OutputTransaction outputs(plan);
    for (std::size_t k = 0; k < files.size(); ++k) outputs.stage(files[k], "staged " + std::to_string(k));
    if (with_folder) outputs.stage(subfolder, "x.pgm", "staged image");
    if (commit) {
      outputs.commit();
      committed = true;
    }
  } catch (const Error&) {
  }
  if (read_all(victim) != "the victim") __builtin_trap();
  const std::map<std::string, std::string> after = snapshot(folder);
  for (const auto& [name, what] : after)
    if (name.find(".asperity-") != std::string::npos && name.find(".asperity.lock") == std::string::npos)
      __builtin_trap();  // a temporary left
  if (before.count("map.txt") && after.count("map.txt") && before.at("map.txt") != after.at("map.txt"))
    __builtin_trap();  // the input changed
  if (!committed) {
    std::map<std::string, std::string> without_lock = after;
    for (auto it = without_lock.begin(); it != without_lock.end();)
      it = it->first.find(".asperity.lock") != std::string::npos ? without_lock.erase(it) : std::next(it);
    if (without_lock != before) __builtin_trap();  // refused or abandoned: the folder as it was
  } else {
    for (std::size_t k = 0; k < files.size(); ++k)
      if (read_all(files[k]) != "staged " + std::to_string(k)) __builtin_trap();
  }
  return 0;
}
