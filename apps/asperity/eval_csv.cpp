#include "eval_csv.hpp"

#include <cmath>
#include <ios>
#include <istream>
#include <cstdint>
#include <list>
#include <map>
#include <ostream>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/number_text.hpp"

namespace asperity::cli {
namespace {

// Lines from a stream in blocks: LF, CRLF and a lone CR all end a line; a line longer than
// max_line_bytes is cut there (flagged) and the rest of it skipped, so memory stays bounded.
class LineReader {
 public:
  explicit LineReader(std::istream& input) : input_(input), block_(1 << 16) {}

  // False at the end of the input.
  bool next(std::string& line, bool& too_long) {
    line.clear();
    too_long = false;
    bool any = false;
    for (;;) {
      if (position_ == filled_ && !refill()) return any;
      const char c = block_[position_++];
      if (skip_lf_) {  // the LF of a CRLF
        skip_lf_ = false;
        if (c == '\n') continue;
      }
      any = true;
      if (c == '\n') return true;
      if (c == '\r') {
        skip_lf_ = true;
        return true;
      }
      if (line.size() < max_line_bytes) line += c;
      else too_long = true;
    }
  }

 private:
  bool refill() {
    try {
      filled_ = static_cast<std::size_t>(input_.rdbuf()->sgetn(block_.data(), static_cast<std::streamsize>(block_.size())));
    } catch (const std::ios_base::failure& failure) {  // libstdc++'s filebuf throws on a read error
      throw Error("reading the input failed: " + failure.code().message());
    }
    position_ = 0;
    return filled_ > 0;
  }

  std::istream& input_;
  std::vector<char> block_;
  std::size_t position_ = 0, filled_ = 0;
  bool skip_lf_ = false;
};

std::string_view trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t");
  return text.substr(first, last - first + 1);
}

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> fields;
  for (std::size_t start = 0;;) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

// The curves of the shapes met last, at most `capacity`; each answers from the table's shape
// nodes directly (Table::direct_curve: made in about 2 us, a row's six orders in about 2 us),
// so that a file whose every row has its own shape costs little more than one of a single
// shape, and a row's answer never depends on the rows before it.
class CurveCache {
 public:
  explicit CurveCache(bool lookup_grid) : lookup_grid_(lookup_grid) {}
  const Curve& get(const Table& table, Distribution distribution, Side side, double shape) {
    const Key key{static_cast<int>(distribution), static_cast<int>(side), shape};
    if (const auto found = index_.find(key); found != index_.end()) {
      order_.splice(order_.begin(), order_, found->second);  // now the most recent
      return found->second->second;
    }
    Curve curve = lookup_grid_ ? table.curve(distribution, side, shape)
                               : table.direct_curve(distribution, side, shape);  // may throw: nothing changes
    if (index_.size() >= capacity) {
      index_.erase(order_.back().first);
      order_.pop_back();
    }
    order_.emplace_front(key, std::move(curve));
    index_.emplace(key, order_.begin());
    return order_.front().second;
  }

 private:
  using Key = std::tuple<int, int, double>;
  static constexpr std::size_t capacity = 256;
  std::list<std::pair<Key, Curve>> order_;  // most recent first
  std::map<Key, std::list<std::pair<Key, Curve>>::iterator> index_;
  bool lookup_grid_;
};

}  // namespace

std::uint64_t eval_csv(const Table& table, std::istream& input, std::ostream& output, std::ostream& errors,
                       bool lookup_grid) {
  LineReader reader(input);
  std::string line;
  bool too_long = false;
  if (!reader.next(line, too_long)) {
    errors << "asperity eval: line 1: empty input, expected the header dist,side,shape,sep\n";
    return 1;
  }
  if (line.compare(0, 3, "\xEF\xBB\xBF") == 0) line.erase(0, 3);  // UTF-8 byte order mark
  const std::vector<std::string_view> header = split(line);
  if (too_long || header != std::vector<std::string_view>{"dist", "side", "shape", "sep"}) {
    errors << "asperity eval: line 1: expected the header dist,side,shape,sep, got '" << quote_text(trim(line))
           << "'\n";
    return 1;
  }
  output << eval_csv_header() << "\n";  // the columns of the rows below (eval_csv.hpp)
  // Resolving a shape costs far more than a query: keep the curves made last (least recently
  // used out first, never the whole cache at once).
  CurveCache curves(lookup_grid);
  std::uint64_t bad = 0;
  for (long line_number = 2; output && reader.next(line, too_long); ++line_number) {
    auto reject = [&](const std::string& why) {
      errors << "asperity eval: line " << line_number << ": " << why << "\n";
      ++bad;
    };
    if (too_long) {
      reject("longer than " + std::to_string(max_line_bytes) + " bytes");
      continue;
    }
    if (trim(line).empty()) continue;
    const std::vector<std::string_view> fields = split(line);
    if (fields.size() != 4) {
      reject("expected 4 fields dist,side,shape,sep, got " + std::to_string(fields.size()));
      continue;
    }
    Distribution distribution;
    Side side;
    double shape = 0, separation = 0;
    if (!parse_distribution(fields[0], distribution)) {
      reject("unknown dist '" + quote_text(fields[0]) + "' (weibull or gaussian)");
      continue;
    }
    if (!parse_side(fields[1], side)) {
      reject("unknown side '" + quote_text(fields[1]) + "' (tail or bounded)");
      continue;
    }
    if (distribution == Distribution::gaussian) {
      if (!fields[2].empty() && !read_double(fields[2], shape)) {
        reject("shape '" + quote_text(fields[2]) + "' is not a number");
        continue;
      }
      shape = 2;  // ignored for the Gaussian
    } else if (!read_double(fields[2], shape) || !std::isfinite(shape)) {
      reject("shape '" + quote_text(fields[2]) + "' is not a finite number");
      continue;
    }
    if (!read_double(fields[3], separation) || !std::isfinite(separation)) {
      reject("sep '" + quote_text(fields[3]) + "' is not a finite number");
      continue;
    }
    const Curve* found = nullptr;
    try {
      found = &curves.get(table, distribution, side, shape);
    } catch (const Error& error) {
      reject(error.what());
      continue;
    }
    const Curve& curve = *found;
    if (!curve.serves(separation)) {  // beyond what a scene table modelled: refused, never a guess
      reject("sep " + format_double(separation) + " is outside the separations this table serves for " +
             to_string(distribution) + " " + to_string(side) +
             (distribution == Distribution::gaussian ? std::string() : " " + format_double(shape)) + ": [" +
             format_double(curve.served_min_separation()) + ", " + format_double(curve.served_max_separation()) +
             "]" + (side == Side::bounded ? " (and s >= 0, where X is 0)" : ""));
      continue;
    }
    std::string row = std::string(to_string(distribution)) + "," + to_string(side) + "," +
                      (distribution == Distribution::gaussian ? std::string(fields[2]) : format_double(shape)) + "," +
                      format_double(separation);
    double logs[order_count];
    curve.log_values(separation, logs);
    for (int k = 0; k < order_count; ++k) row += "," + format_double(std::exp(logs[k]));
    for (int k = 0; k < order_count; ++k) row += "," + format_double(logs[k]);
    row += '\n';
    output << row;
  }
  return bad;
}

}  // namespace asperity::cli
