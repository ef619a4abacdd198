#include "eval_command.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>

#include "asperity/error.hpp"
#include "command_line.hpp"
#include "eval_csv.hpp"
#include "asperity/number_text.hpp"

namespace asperity::cli {

void add_eval_command(CLI::App& app) {
  struct Options {
    std::string table, input;
    bool grid = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "eval", "the six integrals X_n (values and logs) at the separations of a CSV file or standard input");
  command->add_option("INPUT", options->input, "CSV with the header dist,side,shape,sep (default or '-': standard input)")
      ->type_name("INPUT.csv")
      ->check(CLI::Validator([](std::string& path) { return path.empty() ? std::string("an empty path") : std::string(); },
                             ""));
  add_table_option(*command, options->table);
  command->add_flag("--grid", options->grid,
                    "build each shape's lookup grid (2-60 ms a shape between the table's nodes, then about 10 ns\n"
                    "a row) instead of answering from the nodes (about 2 us a shape, 2 us a row): for files of few\n"
                    "shapes and many rows; the two agree within 2e-13 of ln X");
  add_quiet_option(*command);
  command->footer(
      "Input: CSV with the header dist,side,shape,sep; dist is weibull or gaussian, side tail or\n"
      "bounded, shape the Weibull shape (empty or ignored for the Gaussian), sep the separation from\n"
      "the Weibull origin (the Gaussian's mean) in units of sigma_s. Lines end with LF, CRLF or CR.\n"
      "Output: " + eval_csv_header() + ", numbers in\n"
      "the shortest form that reads back to the same double; I* underflow to 0 below ~1e-308, lnI*\n"
      "stay finite (-inf where the value is exactly 0). A bad row is named by its line on standard\n"
      "error and skipped; every good row is written. A scene table (docs/scenes.md) serves each curve\n"
      "over its scene's separations only: a row outside them is refused, naming the range.\n" +
      std::string(exit_status_help));
  set_action(*command, [options] {
    const Table table = open_table(options->table);
    std::uint64_t bad = 0;
    if (options->input.empty() || options->input == "-") {
      bad = eval_csv(table, std::cin, std::cout, std::cerr, options->grid);
      if (std::ferror(stdin)) throw Error("reading standard input failed");
    } else {
      std::error_code code;
      if (std::filesystem::is_directory(options->input, code))
        throw Error("cannot read '" + quote_text(options->input) + "': it is a directory");
      std::ifstream input(options->input, std::ios::binary);
      if (!input) throw Error("cannot read '" + quote_text(options->input) + "': " + std::strerror(errno));
      bad = eval_csv(table, input, std::cout, std::cerr, options->grid);
    }
    // Say why now: errno of the failed write is gone once the table is closed.
    if (!std::cout || std::ferror(stdout)) throw Error(std::string("writing the output failed: ") + std::strerror(errno));
    return bad == 0 ? exit_success : exit_bad_rows;
  });
}

}  // namespace asperity::cli
