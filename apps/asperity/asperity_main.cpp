// The asperity command.
//   asperity eval [--table FILE] [INPUT.csv]   values of the six integrals, CSV in and out
//   asperity summary [--table FILE]            load, area and stiffness for a few shapes
//   asperity contact ...                       a physical surface, forward and inverse (contact_cli.cpp)
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "asperity/contact.hpp"
#include "asperity/error.hpp"
#include "asperity/table.hpp"
#include "contact_cli.hpp"
#include "eval_csv.hpp"
#include "surface_command.hpp"

namespace {

const char* usage =
    "usage: asperity eval [--table FILE] [INPUT.csv]\n"
    "       asperity summary [--table FILE]\n"
    "       asperity contact [--table FILE] SURFACE QUERY   (asperity contact --help)\n"
    "       asperity surface FILE [--pixel-size L] [--modulus E*] [--report DIR] ...   (asperity surface --help)\n"
    "  eval     reads CSV with header dist,side,shape,sep (file or standard input) and writes\n"
    "           dist,side,shape,sep,I0,I1_2,I1,I3_2,I2,I5_2,lnI0,...,lnI5_2 (%.17g)\n"
    "  summary  count, area, load and stiffness for a few shapes on both sides\n"
    "  --table  a table file (default: $ASPERITY_TABLE, else the shipped default table)\n";

asperity::Table open_table(const std::string& path) {
  return path.empty() ? asperity::Table::open_default() : asperity::Table::open(path);
}

int summary(const asperity::Table& table) {
  using namespace asperity;
  const Surface unit;  // N = R = sigma_s = E* = 1: the values are the dimensionless X_n scaled
  std::printf("Unit surface (N = R = sigma_s = E* = 1). sep: origin convention; xi: (s - mean)/rms.\n");
  std::printf("%-9s %-8s %6s %9s %9s %12s %12s %12s %12s %10s\n", "dist", "side", "shape", "sep", "xi", "count",
              "area", "load", "stiffness", "K/P");
  struct Row { Distribution distribution; Side side; double shape; };
  const std::vector<Row> rows = {{Distribution::gaussian, Side::tail, 2}, {Distribution::weibull, Side::tail, 1},
                                 {Distribution::weibull, Side::tail, 2},  {Distribution::weibull, Side::tail, 5},
                                 {Distribution::weibull, Side::bounded, 1}, {Distribution::weibull, Side::bounded, 2},
                                 {Distribution::weibull, Side::bounded, 5}};
  for (const Row& row : rows) {
    const Curve curve = table.curve(row.distribution, row.side, row.shape);
    const std::vector<double> positions = row.side == Side::tail ? std::vector<double>{0, 1, 2, 3}
                                                                 : std::vector<double>{-0.05, -0.2, -0.5, -1};
    for (double position : positions) {
      const double separation = row.side == Side::tail ? origin_from_standardized(curve, position) : position;
      ContactState state;
      contact_at(curve, unit, separation, state);
      std::printf("%-9s %-8s %6.2g %9.4f %9.4f %12.5g %12.5g %12.5g %12.5g %10.4g\n", to_string(row.distribution),
                  to_string(row.side), row.shape, separation, standardized_from_origin(curve, separation),
                  state.count, state.area, state.load, state.stiffness, state.stiffness_ratio);
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fputs(usage, stderr);
    return 2;
  }
  const std::string command = argv[1];
  if (command == "surface") return asperity::cli::surface_command(argc - 1, argv + 1);
  if (command == "contact") {
    try {
      return asperity::cli::contact_command(argc - 1, argv + 1);
    } catch (const std::exception& error) {
      std::fprintf(stderr, "asperity %s\n", error.what());
      return 2;
    }
  }
  std::string table_path, input_path;
  for (int i = 2; i < argc; ++i) {
    const std::string argument = argv[i];
    if (argument == "--table" && i + 1 < argc) table_path = argv[++i];
    else if (argument == "--help" || argument == "-h") { std::fputs(usage, stdout); return 0; }
    else if (command == "eval" && input_path.empty() && (argument.empty() || argument[0] != '-')) input_path = argument;
    else { std::fprintf(stderr, "asperity: unexpected argument '%s'\n%s", argument.c_str(), usage); return 2; }
  }
  try {
    if (command == "summary") return summary(open_table(table_path));
    if (command == "eval") {
      const asperity::Table table = open_table(table_path);
      int bad;
      if (input_path.empty()) {
        bad = asperity::cli::eval_csv(table, std::cin, std::cout, std::cerr);
      } else {
        std::ifstream input(input_path);
        if (!input) { std::fprintf(stderr, "asperity eval: cannot read '%s'\n", input_path.c_str()); return 2; }
        bad = asperity::cli::eval_csv(table, input, std::cout, std::cerr);
      }
      std::cout.flush();
      return bad == 0 ? 0 : 1;
    }
    if (command == "--help" || command == "-h") { std::fputs(usage, stdout); return 0; }
    std::fprintf(stderr, "asperity: unknown command '%s'\n%s", command.c_str(), usage);
    return 2;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "asperity: %s\n", error.what());
    return 2;
  }
}
