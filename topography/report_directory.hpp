// A report folder written the way tables are (internal): each file replaced atomically (a
// temporary in the folder, fsync, rename over the name), so a planted symbolic link is
// replaced, never followed, and a planted FIFO or device is replaced without being opened;
// one run at a time (an exclusive lock on DIR/.asperity-report.lock, held until the folder is
// complete), and the files of the report that this run does not write are removed, so one
// run's files never sit beside another's. Write errors (a full disk) are reported and leave
// no temporary behind.
#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace asperity::topography::detail {

class ReportDirectory {
 public:
  // Creates the folder (and its parents) if needed, opens it, and waits for the lock. Throws
  // asperity::Error naming the folder: not a directory, no permission, cannot lock.
  explicit ReportDirectory(const std::string& path);
  ~ReportDirectory();
  ReportDirectory(const ReportDirectory&) = delete;
  ReportDirectory& operator=(const ReportDirectory&) = delete;

  // Replaces DIR/name with `bytes`; returns the file's path. A directory of that name is an
  // error (it is left as it is).
  std::string write(const std::string& name, std::string_view bytes);
  // Removes DIR/name if it is there and not a directory (a file of an earlier run).
  void remove(const std::string& name);
  // Removes what runs that died left of these files (".NAME.tmp-*"): with the lock held, no
  // other run is writing.
  void remove_stale_temporaries(const std::vector<std::string>& names);
  // Makes the renames durable (fsync of the folder); throws on an error.
  void finish();

 private:
  std::string path_;
  int directory_ = -1, lock_ = -1;
};

}  // namespace asperity::topography::detail
