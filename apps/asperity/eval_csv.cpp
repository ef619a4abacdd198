#include "eval_csv.hpp"

#include <cmath>
#include <cstdio>
#include <istream>
#include <map>
#include <ostream>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "asperity/error.hpp"

namespace asperity::cli {
namespace {

std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  std::string field;
  while (std::getline(stream, field, ',')) fields.push_back(trim(field));
  if (!line.empty() && line.back() == ',') fields.push_back("");
  return fields;
}

bool parse_double(const std::string& text, double& value) {
  if (text.empty()) return false;
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return *end == '\0';
}

std::string number(double value) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

}  // namespace

int eval_csv(const Table& table, std::istream& input, std::ostream& output, std::ostream& errors) {
  std::string line;
  if (!std::getline(input, line)) {
    errors << "asperity eval: line 1: empty input, expected the header dist,side,shape,sep\n";
    return 1;
  }
  if (!line.empty() && static_cast<unsigned char>(line[0]) == 0xEF) line.erase(0, 3);  // UTF-8 BOM
  if (split(line) != std::vector<std::string>{"dist", "side", "shape", "sep"}) {
    errors << "asperity eval: line 1: expected the header dist,side,shape,sep, got '" << trim(line) << "'\n";
    return 1;
  }
  output << "dist,side,shape,sep,I0,I1_2,I1,I3_2,I2,I5_2,lnI0,lnI1_2,lnI1,lnI3_2,lnI2,lnI5_2\n";
  // Resolving a shape costs more than a query: keep the curves already made (bounded cache).
  std::map<std::tuple<int, int, double>, Curve> curves;
  int bad = 0;
  for (long line_number = 2; std::getline(input, line); ++line_number) {
    if (trim(line).empty()) continue;
    auto reject = [&](const std::string& why) {
      errors << "asperity eval: line " << line_number << ": " << why << "\n";
      ++bad;
    };
    const std::vector<std::string> fields = split(line);
    if (fields.size() != 4) {
      reject("expected 4 fields dist,side,shape,sep, got " + std::to_string(fields.size()));
      continue;
    }
    Distribution distribution;
    Side side;
    double shape = 0, separation = 0;
    if (!parse_distribution(fields[0], distribution)) { reject("unknown dist '" + fields[0] + "' (weibull or gaussian)"); continue; }
    if (!parse_side(fields[1], side)) { reject("unknown side '" + fields[1] + "' (tail or bounded)"); continue; }
    if (distribution == Distribution::gaussian) {
      if (!fields[2].empty() && !parse_double(fields[2], shape)) { reject("shape '" + fields[2] + "' is not a number"); continue; }
      shape = 2;  // ignored for the Gaussian
    } else if (!parse_double(fields[2], shape) || !std::isfinite(shape)) {
      reject("shape '" + fields[2] + "' is not a finite number");
      continue;
    }
    if (!parse_double(fields[3], separation) || !std::isfinite(separation)) {
      reject("sep '" + fields[3] + "' is not a finite number");
      continue;
    }
    const auto key = std::make_tuple(static_cast<int>(distribution), static_cast<int>(side), shape);
    auto found = curves.find(key);
    if (found == curves.end()) {
      try {
        if (curves.size() >= 64) curves.clear();
        found = curves.emplace(key, table.curve(distribution, side, shape)).first;
      } catch (const Error& error) {
        reject(error.what());
        continue;
      }
    }
    const Curve& curve = found->second;
    std::string row = std::string(to_string(distribution)) + "," + to_string(side) + "," +
                      (distribution == Distribution::gaussian ? fields[2] : number(shape)) + "," + number(separation);
    double logs[order_count];
    curve.log_values(separation, logs);
    for (int k = 0; k < order_count; ++k) row += "," + number(std::exp(logs[k]));
    for (int k = 0; k < order_count; ++k) row += "," + number(logs[k]);
    output << row << "\n";
  }
  return bad;
}

}  // namespace asperity::cli
