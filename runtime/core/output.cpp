// The one output policy (asperity/output.hpp). Every file is staged as a temporary in its own
// folder (O_CREAT | O_EXCL | O_NOFOLLOW: nothing planted is followed or opened), synced, and
// renamed over its name when the whole run's output is ready.
#include "asperity/output.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <map>

#include "asperity/interrupt.hpp"
#include "asperity/number_text.hpp"

namespace asperity {
namespace {

namespace fs = std::filesystem;

std::string reason(int error) { return std::strerror(error); }

// ---- temporaries: named for this host and process, so the dead writers' can be told apart ----

constexpr const char* temporary_prefix = ".asperity-";

std::string host_tag() {
  char name[256] = {};
  if (::gethostname(name, sizeof name - 1) != 0) return "host";
  std::string tag;
  for (const char* c = name; *c && tag.size() < 64; ++c)
    tag += (std::isalnum(static_cast<unsigned char>(*c)) || *c == '.' || *c == '_') ? *c : '_';
  return tag.empty() ? "host" : tag;
}

// Removes the temporaries of writers that died: only a name of ours for this host, a regular
// file of this user, whose process is gone, unchanged for 10 minutes (a writer in another PID
// namespace on this host may still be writing one changed more recently). Never fails.
void remove_stale_temporaries(int directory) {
  const int listing_fd = ::dup(directory);
  if (listing_fd < 0) return;
  DIR* listing = ::fdopendir(listing_fd);
  if (!listing) {
    ::close(listing_fd);
    return;
  }
  const std::string prefix = std::string(temporary_prefix) + host_tag() + "-";
  const std::time_t now = std::time(nullptr);
  while (const dirent* entry = ::readdir(listing)) {
    const std::string name = entry->d_name;
    if (name.compare(0, prefix.size(), prefix) != 0 || name.size() < prefix.size() + 7 ||
        name.compare(name.size() - 4, 4, ".tmp") != 0)
      continue;
    const std::string rest = name.substr(prefix.size(), name.size() - prefix.size() - 4);  // PID-N
    const std::size_t dash = rest.find('-');
    if (dash == 0 || dash == std::string::npos || rest.find_first_not_of("0123456789-") != std::string::npos ||
        rest.find('-', dash + 1) != std::string::npos || dash + 1 == rest.size() || dash > 9)
      continue;
    long long pid = 0;
    if (!read_whole_number(rest.substr(0, dash), 1, INT_MAX, pid) || pid == static_cast<long long>(::getpid()))
      continue;
    if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;  // alive, or not ours to know
    struct stat status {};
    if (::fstatat(directory, name.c_str(), &status, AT_SYMLINK_NOFOLLOW) != 0 || !S_ISREG(status.st_mode) ||
        status.st_uid != ::geteuid() || now - status.st_mtime < 600)
      continue;
    ::unlinkat(directory, name.c_str(), 0);
  }
  ::closedir(listing);
}

// ---- the temporaries a hard stop (a second signal) removes: a fixed table, async-signal-safe ----

struct LiveTemporary {
  std::atomic<int> directory{-1};
  char name[96] = {};
};
LiveTemporary live_temporaries[64];

int remember_temporary(int directory, const std::string& name) {
  for (int slot = 0; slot < 64; ++slot) {
    int free = -1;  // -2 while the name is being written: the handler skips it
    if (!live_temporaries[slot].directory.compare_exchange_strong(free, -2)) continue;
    std::snprintf(live_temporaries[slot].name, sizeof live_temporaries[slot].name, "%s", name.c_str());
    live_temporaries[slot].directory.store(directory);
    return slot;
  }
  return -1;  // more at once than the table holds: those are cleaned by the next run instead
}

void forget_temporary(int slot) {
  if (slot >= 0) live_temporaries[slot].directory.store(-1);
}

// ---- what is at a path now ----

struct SplitPath {
  std::string folder, base;  // folder "." for a bare name
};

SplitPath split(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  if (slash == std::string::npos) return {".", path};
  return {slash == 0 ? "/" : path.substr(0, slash), path.substr(slash + 1)};
}

}  // namespace

std::string read_output_head(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) return {};
  struct stat status {};
  std::string head;
  if (::fstat(fd, &status) == 0 && S_ISREG(status.st_mode)) {
    head.resize(4096);
    ssize_t count;
    do count = ::read(fd, &head[0], head.size());
    while (count < 0 && errno == EINTR);
    head.resize(count > 0 ? static_cast<std::size_t>(count) : 0);
  }
  ::close(fd);
  return head;
}

namespace {

// Why `kind` cannot be written at `path`, or "" (a file of ours of that kind, or nothing there
// and a folder that takes it). `folder_made_later`: the folder is created by the run.
std::string problem_at(const std::string& path, const OutputKind& kind, bool overwrite, bool folder_made_later) {
  const SplitPath parts = split(path);
  if (path.empty()) return "no output file named";
  if (path.find('\0') != std::string::npos) return "the name has a NUL character (the system would stop there)";
  if (parts.base.empty() || parts.base == "." || parts.base == "..")
    return "names a directory, not a file";
  if (parts.base.size() > NAME_MAX)
    return "the file name has " + std::to_string(parts.base.size()) + " characters, more than a file name may have (" +
           std::to_string(NAME_MAX) + ")";
  struct stat status {};
  if (::lstat(path.c_str(), &status) != 0) {
    const int error = errno;
    if (error != ENOENT) return "cannot be examined: " + reason(error);
    if (folder_made_later) return "";
    struct stat folder {};
    if (::stat(parts.folder.c_str(), &folder) != 0)
      { const int error = errno; return "cannot open the directory '" + printable_path(parts.folder) + "': " + reason(error); }
    if (!S_ISDIR(folder.st_mode)) return "cannot open the directory '" + printable_path(parts.folder) + "': " + reason(ENOTDIR);
    if (::access(parts.folder.c_str(), W_OK | X_OK) != 0)
      { const int error = errno; return "cannot write in the directory '" + printable_path(parts.folder) + "': " + reason(error); }
    return "";
  }
  if (S_ISDIR(status.st_mode)) return "is a directory";
  if (S_ISLNK(status.st_mode))
    return overwrite ? "" : "is a symbolic link, never followed: name the file itself, or remove the link";
  if (!S_ISREG(status.st_mode)) return "is a device, FIFO or socket; only regular files are ever replaced";
  if (::access(path.c_str(), W_OK) != 0) return "is read-only; make it writable or remove it first";
  if (!overwrite && !(kind.recognise && kind.recognise(path)))
    return "holds something that is not " + std::string(kind.name) +
           " written by asperity: it is left as it is (--overwrite replaces it)";
  return "";
}

// A key naming one file however the path was spelled (the folder resolved; the name as given).
std::string file_key(const std::string& path) {
  const SplitPath parts = split(path);
  std::error_code error;
  const fs::path folder = fs::weakly_canonical(fs::path(parts.folder), error);
  return (error ? fs::path(parts.folder) : folder).string() + "/" + parts.base;
}

bool same_file(const std::string& a, const std::string& b) {
  struct stat x {}, y {};
  return ::stat(a.c_str(), &x) == 0 && ::stat(b.c_str(), &y) == 0 && x.st_dev == y.st_dev && x.st_ino == y.st_ino;
}

bool starts_with(std::string_view text, std::string_view prefix) { return text.substr(0, prefix.size()) == prefix; }

std::atomic<int> pending_signal{0};

bool signal_asked(void*) { return pending_signal.load() != 0; }

extern "C" void on_stop_signal(int signal_number) {
  if (pending_signal.exchange(signal_number) == 0) {
    static const char message[] = "asperity: stopping (again to stop at once)\n";
    [[maybe_unused]] const ssize_t ignored = ::write(2, message, sizeof message - 1);
    return;
  }
  for (LiveTemporary& temporary : live_temporaries) {
    const int directory = temporary.directory.load();
    if (directory >= 0) ::unlinkat(directory, temporary.name, 0);
  }
  ::_exit(128 + signal_number);
}

}  // namespace

// ---- the kinds ----

namespace output_kinds {
namespace {
bool is_card(const std::string& path) {
  const std::string head = read_output_head(path);
  return starts_with(head, "** asperity") || starts_with(head, "pressure_Pa,overclosure_m\n") ||
         starts_with(head, "pressure_MPa,overclosure_mm\n");
}
bool is_field_image(const std::string& path) { return starts_with(read_output_head(path), "P5\n# asperity"); }
bool is_report_file(const std::string& path) {
  const std::string head = read_output_head(path);
  return starts_with(head, "# Surface report: ") || starts_with(head, "i,j,x_m,y_m,height_m,") ||
         // curves.csv: "model," and PhysicalState's columns (asperity-surface/3), or the older spelling
         starts_with(head, "model,separation_m,mean_separation_m,count,") ||
         starts_with(head, "model,pressure_Pa,load_N,mean_separation_m,separation_m,") ||
         starts_with(head, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
                           "version=\"1.1\" width=\"") ||
         (starts_with(head, "{") && head.find("\"schema\": \"asperity-surface/") != std::string::npos);
}
bool is_results_csv(const std::string& path) {
  const std::string head = read_output_head(path);
  return starts_with(head, "# asperity") || starts_with(head, "source,");
}
bool is_results_json(const std::string& path) {
  const std::string head = read_output_head(path);
  return starts_with(head, "{") && head.find("\"schema\": \"asperity-") != std::string::npos;
}
bool is_gsf(const std::string& path) { return starts_with(read_output_head(path), "Gwyddion Simple Field 1.0\n"); }
bool is_lock(const std::string& path) { return read_output_head(path).empty(); }
bool is_any_file(const std::string&) { return true; }
}  // namespace

const OutputKind card{"a pressure-overclosure card", is_card};
const OutputKind field_image{"a field image (PGM)", is_field_image};
const OutputKind report_file{"a surface report's file", is_report_file};
const OutputKind results_csv{"asperity's CSV results", is_results_csv};
const OutputKind results_json{"asperity's JSON results", is_results_json};
const OutputKind gsf_height_map{"a Gwyddion simple field", is_gsf};
const OutputKind lock{"a lock file (empty)", is_lock};
const OutputKind any_file{"a file", is_any_file};
}  // namespace output_kinds

std::string printable_path(std::string_view path, std::size_t limit) { return terminal_text(quote_text(path, limit)); }

// ---- the plan ----

void OutputPlan::input(const std::string& path) { inputs_.push_back(path); }

void OutputPlan::file(const std::string& option, const std::string& path, const OutputKind& kind) {
  files_.push_back({option, path, &kind});
}

void OutputPlan::folder(const std::string& option, const std::string& path, std::vector<FolderEntry> entries,
                        std::vector<FolderEntry> stale) {
  folders_.push_back({option, path, std::move(entries), std::move(stale)});
}

namespace {
// A folder's problem as an output, or "": it is a directory we may write in, or can be made.
std::string folder_problem(const std::string& path, bool& made_later) {
  made_later = false;
  if (path.empty()) return "no folder named";
  if (path.find('\0') != std::string::npos) return "the name has a NUL character (the system would stop there)";
  struct stat status {};
  if (::stat(path.c_str(), &status) == 0) {
    if (!S_ISDIR(status.st_mode)) return "is not a directory";
    if (::access(path.c_str(), W_OK | X_OK) != 0) { const int error = errno; return "cannot write in it: " + reason(error); }
    return "";
  }
  const int error = errno;
  if (error == ENOTDIR) return "cannot be made: a part of its path is not a directory";
  if (error != ENOENT) return "cannot be examined: " + reason(error);
  // the nearest folder above that exists must take a new one
  // ("out/" names the folder out: its trailing separator is no file name)
  fs::path folder = fs::path(path).lexically_normal();
  if (!folder.has_filename()) folder = folder.parent_path();
  fs::path above = folder.parent_path();
  if (above.empty()) above = ".";
  while (::stat(above.c_str(), &status) != 0) {
    if (errno != ENOENT) { const int error = errno; return "cannot be made: '" + printable_path(above.string()) + "': " + reason(error); }
    // a relative path's first folder missing too: the working directory must take it
    if (above == above.parent_path() || above == ".") return "cannot be made: no folder above it exists";
    above = above.parent_path().empty() ? fs::path(".") : above.parent_path();
  }
  if (!S_ISDIR(status.st_mode)) return "cannot be made: '" + printable_path(above.string()) + "' is not a directory";
  if (::access(above.c_str(), W_OK | X_OK) != 0)
    { const int error = errno; return "cannot be made in '" + printable_path(above.string()) + "': " + reason(error); }
  made_later = true;
  return "";
}
}  // namespace

void OutputPlan::check() const {
  std::vector<std::string> problems;
  std::map<std::string, std::string> claimed;  // file key -> the output that names it
  // false when the path is already claimed or is an input (its one problem said)
  const auto claim = [&](const std::string& option, const std::string& path) {
    const std::string key = file_key(path);
    const auto [at, fresh] = claimed.emplace(key, option + " " + printable_path(path));
    if (!fresh) {
      problems.push_back(option + " " + printable_path(path) + ": the same file as " + at->second);
      return false;
    }
    for (const std::string& input : inputs_)
      if (file_key(input) == key || same_file(input, path)) {
        problems.push_back(option + " " + printable_path(path) + ": is an input of this run (" +
                           printable_path(input) + "); it is never written over");
        return false;
      }
    return true;
  };
  for (const Output& output : files_) {
    if (!claim(output.option, output.path)) continue;
    const std::string problem = problem_at(output.path, *output.kind, overwrite_, false);
    if (!problem.empty()) problems.push_back(output.option + " " + printable_path(output.path) + ": " + problem);
  }
  for (const Folder& folder : folders_) {
    if (!claim(folder.option, folder.path)) continue;  // a folder where another output is a file
    bool made_later = false;
    const std::string problem = folder_problem(folder.path, made_later);
    if (!problem.empty()) {
      problems.push_back(folder.option + " " + printable_path(folder.path) + ": " + problem);
      continue;
    }
    for (const FolderEntry& entry : folder.entries) {
      const std::string path = (fs::path(folder.path) / entry.name).string();
      if (!claim(folder.option, path)) continue;
      const std::string entry_problem = problem_at(path, *entry.kind, overwrite_, made_later);
      if (!entry_problem.empty())
        problems.push_back(folder.option + " " + printable_path(folder.path) + ": " + printable_path(entry.name) + " " +
                           entry_problem);
    }
  }
  if (problems.empty()) return;
  std::string message = problems.size() == 1 ? "cannot write the output: " : "cannot write the outputs:";
  for (const std::string& problem : problems) message += (problems.size() == 1 ? "" : "\n  ") + problem;
  throw Error(message);
}

// ---- the transaction ----

namespace {
// An exclusive lock on FOLDER/.asperity.lock: a regular file of ours (O_NOFOLLOW: a planted link
// is refused; O_NONBLOCK: a planted FIFO does not hang the open).
class FolderLock {
 public:
  FolderLock(int directory, const std::string& folder) {
    fd_ = ::openat(directory, ".asperity.lock", O_RDWR | O_CREAT | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC, 0644);
    struct stat status {};
    if (fd_ < 0 || ::fstat(fd_, &status) != 0 || !S_ISREG(status.st_mode)) {
      const int error = fd_ < 0 ? errno : EINVAL;
      if (fd_ >= 0) ::close(fd_);
      fd_ = -1;
      throw Error(printable_path(folder) + "/.asperity.lock: cannot lock the folder (not a regular file?): " +
                  reason(error));
    }
    while (::flock(fd_, LOCK_EX) != 0)
      if (errno != EINTR) {
        const int error = errno;
        ::close(fd_);
        fd_ = -1;
        throw Error(printable_path(folder) + ": cannot lock the folder: " + reason(error));
      }
  }
  FolderLock(FolderLock&& other) noexcept : fd_(other.fd_) { other.fd_ = -1; }
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;
  FolderLock& operator=(FolderLock&&) = delete;
  ~FolderLock() {
    if (fd_ >= 0) ::close(fd_);
  }

 private:
  int fd_ = -1;
};
}  // namespace

struct OutputTransaction::Impl {
  struct Staged {
    std::string path, folder, base, temporary;
    int directory = -1;  // owned
    int slot = -1;       // in live_temporaries
    bool committed = false;
    const OutputKind* kind = nullptr;
  };
  OutputPlan plan;
  std::vector<Staged> staged;
  std::vector<std::string> made_folders;  // created by this run: removed if left empty
  std::map<std::string, int> directories;  // folder -> descriptor (owned)
  unsigned long serial = 0;
  std::string host = host_tag();
  bool committed = false;

  int directory_of(const std::string& folder, bool make) {
    const auto at = directories.find(folder);
    if (at != directories.end()) return at->second;
    if (make) make_folders(folder);
    const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) { const int error = errno; throw Error("cannot open the directory '" + printable_path(folder) + "': " + reason(error)); }
    directories.emplace(folder, fd);
    remove_stale_temporaries(fd);
    return fd;
  }

  void make_folders(const std::string& folder) {
    std::vector<fs::path> missing;
    for (fs::path at = fs::path(folder).lexically_normal(); !at.empty(); at = at.parent_path()) {
      struct stat status {};
      if (::stat(at.c_str(), &status) == 0) break;
      missing.push_back(at);
      if (at == at.parent_path()) break;
    }
    for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
      if (::mkdir(it->c_str(), 0777) != 0 && errno != EEXIST)
        { const int error = errno; throw Error("cannot make the folder '" + printable_path(it->string()) + "': " + reason(error)); }
      made_folders.push_back(it->string());
    }
  }

  void stage(const std::string& path, const std::string& folder, const std::string& base, std::string_view bytes,
             bool make_folder, const OutputKind& kind) {
    poll_interrupt();
    Staged file{path, folder, base, {}, ::dup(directory_of(folder, make_folder))};
    if (file.directory < 0) { const int error = errno; throw Error(printable_path(path) + ": cannot write: " + reason(error)); }
    int fd = -1;
    for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
      file.temporary = std::string(temporary_prefix) + host + "-" + std::to_string(::getpid()) + "-" +
                       std::to_string(++serial) + ".tmp";
      fd = ::openat(file.directory, file.temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0666);
      if (fd < 0 && errno != EEXIST) {
        const int error = errno;
        ::close(file.directory);
        throw Error(printable_path(path) + ": cannot create a temporary file in '" + printable_path(folder) +
                    "': " + reason(error));
      }
    }
    if (fd < 0) {
      ::close(file.directory);
      throw Error(printable_path(path) + ": cannot find a free temporary name in '" + printable_path(folder) + "'");
    }
    file.slot = remember_temporary(file.directory, file.temporary);
    file.kind = &kind;
    staged.push_back(file);  // from here the destructor removes it
    const auto fail = [&](const std::string& what, int error) {
      ::close(fd);
      throw Error(printable_path(path) + ": " + what + ": " + reason(error));
    };
    for (std::size_t written = 0; written < bytes.size();) {
      const ssize_t count = ::write(fd, bytes.data() + written, bytes.size() - written);
      if (count < 0 && errno == EINTR) continue;
      if (count <= 0) fail("write error", count < 0 ? errno : EIO);
      written += static_cast<std::size_t>(count);
    }
    struct stat target {};  // a file replaced keeps its permission bits
    if (::fstatat(file.directory, base.c_str(), &target, AT_SYMLINK_NOFOLLOW) == 0 && S_ISREG(target.st_mode) &&
        ::fchmod(fd, target.st_mode & 07777) != 0)
      fail("keeping its mode", errno);
    if (::fsync(fd) != 0) fail("syncing it to disk", errno);
    if (::close(fd) != 0) { const int error = errno; throw Error(printable_path(path) + ": closing it: " + reason(error)); }
  }

  ~Impl() {
    for (Staged& file : staged) {
      if (!file.committed) ::unlinkat(file.directory, file.temporary.c_str(), 0);
      forget_temporary(file.slot);
      ::close(file.directory);
    }
    for (const auto& [folder, fd] : directories) ::close(fd);
    if (!committed)
      for (auto it = made_folders.rbegin(); it != made_folders.rend(); ++it) ::rmdir(it->c_str());  // only if empty
  }
};

OutputTransaction::OutputTransaction(const OutputPlan& plan) : impl_(std::make_unique<Impl>()) {
  plan.check();
  impl_->plan = plan;
}

OutputTransaction::~OutputTransaction() = default;

void OutputTransaction::stage(const std::string& path, std::string_view bytes) {
  for (const OutputPlan::Output& output : impl_->plan.files_)
    if (output.path == path) {
      const SplitPath parts = split(path);
      impl_->stage(path, parts.folder, parts.base, bytes, false, *output.kind);
      return;
    }
  throw Error("internal: " + printable_path(path) + " is not an output of the plan");
}

void OutputTransaction::stage(const std::string& folder, const std::string& name, std::string_view bytes) {
  for (const OutputPlan::Folder& planned : impl_->plan.folders_)
    if (planned.path == folder)
      for (const FolderEntry& entry : planned.entries)
        if (entry.name == name) {
          impl_->stage((fs::path(folder) / name).string(), folder, name, bytes, true, *entry.kind);
          return;
        }
  throw Error("internal: " + printable_path(folder) + "/" + printable_path(name) + " is not an output of the plan");
}

std::vector<std::string> OutputTransaction::commit() {
  Impl& t = *impl_;
  check_interrupt_now();
  // one run's files at a time in a folder: each folder's lock held while its files are renamed
  std::vector<FolderLock> locks;
  for (const OutputPlan::Folder& folder : t.plan.folders_)
    if (t.directories.count(folder.path)) locks.emplace_back(t.directories.at(folder.path), folder.path);
  // every name checked again before the first rename (the work may have taken hours): a file of
  // the user's, a link, FIFO or directory that appeared meanwhile is not replaced, and nothing is
  for (const Impl::Staged& file : t.staged) {
    const std::string problem = problem_at(file.path, *file.kind, t.plan.overwrite(), false);
    if (!problem.empty())
      throw Error(printable_path(file.path) + ": " + problem + " (found when the outputs were to be renamed into "
                  "place: nothing was written)");
  }
  std::vector<std::string> written;
  for (Impl::Staged& file : t.staged) {
    if (::renameat(file.directory, file.temporary.c_str(), file.directory, file.base.c_str()) != 0)
      { const int error = errno; throw Error(printable_path(file.path) + ": renaming the finished file into place: " + reason(error)); }
    file.committed = true;
    written.push_back(file.path);
  }
  t.committed = true;
  // a folder's files of ours that this run did not write (an earlier run's): removed through the
  // folder's own descriptor (a folder swapped for a link meanwhile is not followed); best effort:
  // everything asked is already in place
  for (const OutputPlan::Folder& folder : t.plan.folders_) {
    const auto opened = t.directories.find(folder.path);
    if (opened == t.directories.end()) continue;
    std::vector<FolderEntry> candidates = folder.entries;
    candidates.insert(candidates.end(), folder.stale.begin(), folder.stale.end());
    for (const FolderEntry& old : candidates) {
      const std::string path = (fs::path(folder.path) / old.name).string();
      if (std::find(written.begin(), written.end(), path) != written.end()) continue;
      struct stat status {};
      if (::fstatat(opened->second, old.name.c_str(), &status, AT_SYMLINK_NOFOLLOW) == 0 && S_ISREG(status.st_mode) &&
          old.kind->recognise && old.kind->recognise(path))
        ::unlinkat(opened->second, old.name.c_str(), 0);
    }
  }
  for (const auto& [folder, fd] : t.directories)
    if (::fsync(fd) != 0 && errno != EINVAL && errno != EROFS)
      { const int error = errno; throw Error("'" + printable_path(folder) + "' was written, but syncing it failed: " + reason(error)); }
  return written;
}

void write_output_file(const std::string& path, std::string_view bytes, const OutputKind& kind, bool overwrite,
                       const std::string& option) {
  OutputPlan plan(overwrite);
  plan.file(option, path, kind);
  OutputTransaction transaction(plan);
  transaction.stage(path, bytes);
  transaction.commit();
}

void install_output_signal_cleanup() {
  static InterruptScope scope(signal_asked, nullptr);
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  action.sa_flags = SA_RESTART;  // a read or write under way goes on; the work stops at its next poll
  sigemptyset(&action.sa_mask);
  for (int signal_number : {SIGINT, SIGTERM, SIGHUP}) ::sigaction(signal_number, &action, nullptr);
}

}  // namespace asperity
