// asperity._output: the one output policy (asperity/output.hpp) for the module's pure-Python parts
// (asperity.batch): a file written as a temporary in its folder and renamed into place, never
// through a planted link, never over a file that is not of its kind; and a folder's lock file,
// opened only inside the folder and never through a link.
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <map>
#include <string>

#include "arrays.hpp"
#include "asperity/error.hpp"
#include "asperity/output.hpp"
#include "bindings.hpp"
#include "paths.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace asperity::python {
namespace {

const std::map<std::string, const OutputKind*>& kinds_by_name() {
  static const std::map<std::string, const OutputKind*> kinds = {
      {"results_csv", &output_kinds::results_csv}, {"results_json", &output_kinds::results_json},
      {"report_file", &output_kinds::report_file}, {"card", &output_kinds::card},
      {"lock", &output_kinds::lock},               {"any_file", &output_kinds::any_file},
  };
  return kinds;
}

const OutputKind& kind_named(const std::string& name) {
  const auto found = kinds_by_name().find(name);
  if (found != kinds_by_name().end()) return *found->second;
  std::string known;
  for (const auto& entry : kinds_by_name()) known += (known.empty() ? "" : ", ") + entry.first;
  throw py::value_error("kind must be one of " + known + ", not '" + name + "'");
}

// An exclusive lock on FOLDER/NAME: opened relative to the folder (a name, no '/'), created there if
// missing, never through a link (O_NOFOLLOW) or onto a FIFO (O_NONBLOCK, then a regular file only).
// Returns the descriptor (os.close releases it); -1 if another process holds the lock.
int lock_folder(const std::string& folder, const std::string& name) {
  if (name.empty() || name == "." || name == ".." || name.find('/') != std::string::npos)
    throw py::value_error("a lock file's name must be a plain file name, not '" + printable_path(name) + "'");
  const int directory = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (directory < 0) throw Error(printable_path(folder) + ": cannot open the folder: " + std::strerror(errno));
  const int fd = ::openat(directory, name.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC, 0644);
  const int open_error = errno;
  ::close(directory);
  const std::string path = printable_path(folder + "/" + name);
  if (fd < 0)
    throw Error(path + ": cannot open the lock file: " +
                (open_error == ELOOP ? std::string("it is a symbolic link") : std::strerror(open_error)));
  struct stat status {};
  if (::fstat(fd, &status) != 0 || !S_ISREG(status.st_mode)) {
    ::close(fd);
    throw Error(path + ": cannot lock: not a regular file");
  }
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    ::close(fd);
    if (error == EWOULDBLOCK) return -1;
    throw Error(path + ": cannot lock: " + std::strerror(error));
  }
  return fd;
}

}  // namespace

void bind_output(py::module_& parent) {
  py::module_ m = parent.def_submodule(
      "_output", "The output policy for asperity's Python parts (internal: asperity.batch writes through it).");
  m.def(
      "write_file",
      [](const PathName& path, const py::bytes& data, const std::string& kind, bool overwrite) {
        const std::string file = to_path(path.object);
        std::string bytes = data;  // a copy: written without the GIL
        const OutputKind& chosen = kind_named(kind);
        py::gil_scoped_release unlocked;
        write_output_file(file, bytes, chosen, overwrite, "path");
      },
      "path"_a, "data"_a, "kind"_a, "overwrite"_a = false,
      "Writes data to path as a temporary in its folder renamed into place: never through a link, never over a\n"
      "file that is not of this kind ('results_csv', 'results_json', 'report_file', 'card', 'lock', 'any_file')\n"
      "unless overwrite. Raises asperity.Error naming the file and the system's reason.");
  m.def(
      "lock_folder",
      [](const PathName& folder, const std::string& name) {
        const std::string directory = to_path(folder.object, "folder");
        py::gil_scoped_release unlocked;
        return lock_folder(directory, name);
      },
      "folder"_a, "name"_a,
      "An exclusive lock on folder/name (created there, never through a link): the descriptor (os.close releases\n"
      "it), or -1 if another process holds it. Raises asperity.Error for a link, a FIFO or an OS error.");
}

}  // namespace asperity::python
