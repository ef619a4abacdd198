// What every command line of the project shares (the `asperity` subcommands and `tablegen`),
// on CLI11: one error style ("<program> <command>: <message>", usage errors pointing at the
// command's --help), one table of exit statuses, every number read by one reader
// (number_text.hpp), an option given twice refused, and standard output checked for write
// errors before the exit status is returned.
#pragma once
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

#include "asperity/table.hpp"

namespace asperity::cli {

// Exit statuses of every command.
inline constexpr int exit_success = 0;
inline constexpr int exit_bad_rows = 1;  // eval: some rows refused (named on stderr), the others written
inline constexpr int exit_failure = 2;   // bad usage, input, table or output
inline constexpr int exit_interrupted = 130;  // SIGINT/SIGTERM: stopped, nothing half-written left
inline constexpr const char* exit_status_help =
    "Exit status: 0 done; 1 some input rows refused (eval: each named on standard error, the\n"
    "others written); 2 bad usage, a bad or missing input or table, or output that could not be\n"
    "written; 130 stopped by Ctrl-C or SIGTERM (no output left half-written; a second signal stops\n"
    "at once).";

// Sets what a (sub)command does once its options are read: `action` returns the exit status.
// An exception from it is reported as "<program> <command>: <what>" with exit status 2; a
// CLI::ParseError (e.g. CLI::ValidationError) as a usage error.
void set_action(CLI::App& command, std::function<int()> action);

// Adds --version: prints what `print` writes (to standard output) and exits with its status.
void add_version_flag(CLI::App& app, std::function<int()> print, const std::string& description);

// Parses the command line, runs the chosen action, flushes standard output and reports a write
// error on it. Returns the exit status.
int run(CLI::App& app, int argc, const char* const* argv);

// Options that may be given once, each read by the one reader: text (not empty), a finite
// number, a whole number within [lo, hi].
CLI::Option* add_text(CLI::App& command, const std::string& name, std::string& value, const std::string& description);
CLI::Option* add_number(CLI::App& command, const std::string& name, double& value, const std::string& description);
// A comma-separated list of numbers ("1e5,1e6"), each read as add_number reads one; left empty
// when the option is not given.
CLI::Option* add_numbers(CLI::App& command, const std::string& name, std::vector<double>& values,
                         const std::string& description);
CLI::Option* add_whole_number(CLI::App& command, const std::string& name, long long& value, long long lo,
                              long long hi, const std::string& description);

// --table FILE; open_table("") opens the default table (Table::default_path()).
CLI::Option* add_table_option(CLI::App& command, std::string& path);
Table open_table(const std::string& path);

// A finite number from text, or CLI::ValidationError naming `what` (for parts of compound
// values such as --sweep KIND:FROM:TO:COUNT).
double number_from_text(const std::string& text, const std::string& what);

// --modulus, or --e1 --nu1 --e2 --nu2 (NaN: not given), checked by the library's one check
// (asperity/surface.hpp's contact_modulus_given): NaN where none is given; its refusal as a usage
// error.
double contact_modulus_option(double modulus, double e1, double nu1, double e2, double nu2);

// The material options of every command that takes one (contact, surface, exact-contact), each
// NaN when not given: --modulus (its help `modulus_help`: what the command does with it), or
// --e1 --nu1 --e2 --nu2, in `group`.
struct MaterialOptions {
  double modulus = 0.0 / 0.0, e1 = 0.0 / 0.0, nu1 = 0.0 / 0.0, e2 = 0.0 / 0.0, nu2 = 0.0 / 0.0;
  // contact_modulus_option of the five: NaN where none is given
  double contact_modulus() const { return contact_modulus_option(modulus, e1, nu1, e2, nu2); }
  bool any_given() const;  // any of the five
};
void add_material_options(CLI::App& command, MaterialOptions& material, const std::string& modulus_help,
                          const std::string& group);

// "<program> <command>" of a (sub)command, for messages.
std::string command_name(const CLI::App& command);
// One line on standard error: "<program> <command>: warning: <message>" and "...: <message>".
void warn(const CLI::App& command, const std::string& message);
void note(const CLI::App& command, const std::string& message);

// --quiet, the same in every command: no notes (information lines) and no progress on standard
// error; warnings and errors are still written. `quiet_flag` is set too (a command's own progress).
CLI::Option* add_quiet_option(CLI::App& command, bool* quiet_flag = nullptr);
bool quiet();

// `asperity --version`: the version, the table a command would use, and that table's schema.
int print_version();

}  // namespace asperity::cli
