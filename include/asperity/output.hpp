// The one output policy: every file the project writes (tables, cards, report folders, field
// images, CSV and JSON files, the batch's results and lock) is written through this header, by
// every command and binding. docs/reliability.md ("Outputs") states the rules:
//
//  - A planted symbolic link, FIFO or device is never followed or opened: a file is written
//    as a temporary in its folder (O_EXCL | O_NOFOLLOW) and renamed over the name.
//  - A file the run did not create is never deleted or replaced, unless the user named it as
//    this output and it is of the same kind (a contact-curves table over a contact-curves
//    table, a report file over the same report file); anything else needs `overwrite`.
//  - An input is never written over; two outputs naming one file are refused.
//  - All of it is checked by OutputPlan::check() before any work, and written by one
//    OutputTransaction: the temporaries are renamed into place only once everything is
//    written; an error, an exception or an Interrupted (asperity/interrupt.hpp) removes them,
//    so no partial output is left behind. A second SIGINT/SIGTERM in a command that called
//    install_output_signal_cleanup() removes the temporaries being written and exits.
//  - Every failure names the file (printable) and the operating system's reason.
#pragma once
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "asperity/error.hpp"

namespace asperity {

// What a file of ours is: its name in messages, and how to recognise one already on disk
// (called only for a regular file, never through a link; most read its first bytes with
// read_output_head).
struct OutputKind {
  const char* name;  // "a contact-curves table", "a pressure-overclosure card"
  bool (*recognise)(const std::string& path);
};

// The first bytes (at most 4096) of a regular file, read without following a link or waiting on
// a FIFO; empty for anything else.
std::string read_output_head(const std::string& path);

// The kinds the project writes (one list; the writers name theirs).
namespace output_kinds {
extern const OutputKind gw_table;            // Greenwood-Williamson integrals (HDF5)
extern const OutputKind contact_curves_table;  // contact curves against separation (HDF5)
extern const OutputKind card;                // a pressure-overclosure card (CalculiX, Abaqus, CSV)
extern const OutputKind field_image;         // exact-contact --fields: a 16-bit PGM
extern const OutputKind report_file;         // a surface report's file (report.json, .md, .csv, .svg)
extern const OutputKind results_csv;         // asperity CSV results (batch rows, sweeps)
extern const OutputKind results_json;        // asperity JSON results
extern const OutputKind gsf_height_map;      // a height map as a Gwyddion simple field (write_gsf)
extern const OutputKind lock;                // a lock file of ours (empty)
extern const OutputKind any_file;            // any regular file the user names (tablegen --out)
}  // namespace output_kinds

// A file a run writes into a folder: its name there and its kind.
struct FolderEntry {
  std::string name;
  const OutputKind* kind;
};

// One run's inputs and outputs, checked together before any work.
class OutputPlan {
 public:
  explicit OutputPlan(bool overwrite = false) : overwrite_(overwrite) {}
  // A file the run reads: no output may name it.
  void input(const std::string& path);
  // A file the user named as an output (`option` as they wrote it: "--card").
  void file(const std::string& option, const std::string& path, const OutputKind& kind);
  // A folder the user named, and the files the run writes into it. The folder is created when
  // the transaction commits; `stale` lists the names an earlier run of the same kind may have
  // left there, removed when this run does not write them (only if they are ours).
  void folder(const std::string& option, const std::string& path, std::vector<FolderEntry> entries,
              std::vector<FolderEntry> stale = {});
  // Throws Error listing every problem: an output that is an input, two outputs on one file, a
  // link, FIFO, device or directory where a file goes, a file that is not ours of this kind
  // (without overwrite), a folder that cannot be made or written.
  void check() const;

  bool overwrite() const { return overwrite_; }

 private:
  friend class OutputTransaction;
  struct Output {
    std::string option, path;
    const OutputKind* kind;
  };
  struct Folder {
    std::string option, path;
    std::vector<FolderEntry> entries, stale;
  };
  bool overwrite_;
  std::vector<std::string> inputs_;
  std::vector<Output> files_;
  std::vector<Folder> folders_;
};

// Writes a plan's outputs: each staged as a temporary beside its name, all renamed into place
// by commit(). Destroyed without commit() (an error, an exception, Interrupted): every
// temporary is removed and nothing the user had is touched.
class OutputTransaction {
 public:
  // Checks the plan again (the files may have changed since).
  explicit OutputTransaction(const OutputPlan& plan);
  ~OutputTransaction();
  OutputTransaction(const OutputTransaction&) = delete;
  OutputTransaction& operator=(const OutputTransaction&) = delete;

  // Stages the contents of a file the plan names (`path` exactly as given to file()).
  void stage(const std::string& path, std::string_view bytes);
  // Stages a file of a folder the plan names (`name` as given in its entries).
  void stage(const std::string& folder, const std::string& name, std::string_view bytes);
  // Renames every staged file into place (creating folders as needed), removes the stale files
  // of ours, syncs the folders. Returns the paths written. A failure part way through leaves
  // the files already renamed (complete) and removes the rest, and throws.
  std::vector<std::string> commit();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// One file under the policy, for a writer with a single output (Python's ContactCurves.write,
// tablegen --out): plan, check, stage and commit in one call.
void write_output_file(const std::string& path, std::string_view bytes, const OutputKind& kind,
                       bool overwrite = false, const std::string& option = "output");

// Commands: a first SIGINT/SIGTERM/SIGHUP asks the InterruptScope this opens to stop (the run
// unwinds and removes its temporaries); a second removes the temporaries being written and
// exits at once with 128 + the signal. The scope lives until the program ends.
void install_output_signal_cleanup();

// The file name as it may be shown on any stream: control characters and invalid UTF-8
// escaped, at most `limit` bytes.
std::string printable_path(std::string_view path, std::size_t limit = 4096);

}  // namespace asperity
