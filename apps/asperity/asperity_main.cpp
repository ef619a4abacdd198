// The asperity command: subcommands on CLI11 (command_line.hpp has the shared conventions).
//
// Adding a subcommand: write it in its own source file NAME_command.cpp (listed in
// CMakeLists.txt's asperity_cli) exposing `void add_NAME_command(CLI::App& app)` in
// NAME_command.hpp. That function calls app.add_subcommand("NAME", "one-line description"),
// adds its options with the helpers of command_line.hpp (add_text, add_number,
// add_whole_number, add_table_option: one number reader, an option given twice refused), ends
// its --help with a footer that includes exit_status_help, and sets its action with
// set_action(), which returns the exit status (errors are thrown: asperity::Error for bad
// input, CLI::ValidationError for bad usage). Then register it below with one call. Options
// live in a std::shared_ptr the action captures.
#include <CLI/CLI.hpp>

#include "command_line.hpp"
#include "contact_command.hpp"
#include "eval_command.hpp"
#include "exact_contact_command.hpp"
#include "summary_command.hpp"
#include "surface_command.hpp"

int main(int argc, char** argv) {
  using namespace asperity::cli;
  CLI::App app("asperity: Greenwood-Williamson asperity integrals from precomputed tables", "asperity");
  app.require_subcommand(1);
  app.get_formatter()->column_width(34);
  add_version_flag(app, print_version, "print the version, the table a command would use and its schema, then exit");
  add_eval_command(app);
  add_summary_command(app);
  add_contact_command(app);
  add_surface_command(app);
  add_exact_contact_command(app);
  app.footer(std::string("Run 'asperity COMMAND --help' for a command's options.\n") + exit_status_help);
  return run(app, argc, argv);
}
