// The `asperity eval` contract: header, numbers in the shortest form that reads back to the same
// double, logs finite below 1e-308, -inf where the value is exactly 0, bad rows named by line
// with good rows kept, any line ending; and the one number reader and writer of the commands.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "eval_csv.hpp"
#include "asperity/number_text.hpp"

namespace {
using namespace asperity;

const Table& table() {
  static const Table instance = Table::open(ASPERITY_TEST_TABLE);
  return instance;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream stream(text);
  std::string line;
  while (std::getline(stream, line)) out.push_back(line);
  return out;
}

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream stream(line);
  std::string field;
  while (std::getline(stream, field, ',')) out.push_back(field);
  return out;
}

TEST(EvalCsv, WritesTheContractHeaderAndValues) {
  std::stringstream input("dist,side,shape,sep\nweibull,tail,2,0\ngaussian,tail,,1.5\nweibull,tail,0.5,1e6\n"
                          "weibull,bounded,3,0.25\n");
  std::stringstream output, errors;
  EXPECT_EQ(cli::eval_csv(table(), input, output, errors), 0);
  EXPECT_EQ(errors.str(), "");
  const auto rows = lines(output.str());
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(rows[0], "dist,side,shape,sep,I0,I1_2,I1,I3_2,I2,I5_2,lnI0,lnI1_2,lnI1,lnI3_2,lnI2,lnI5_2");
  auto first = fields(rows[1]);
  ASSERT_EQ(first.size(), 16u);
  EXPECT_NEAR(std::stod(first[4]), 1.0, 1e-15);
  EXPECT_NEAR(std::stod(first[6]), std::sqrt(M_PI) / 2, 1e-15);  // J_1(0) = Gamma(3/2) for a = 2
  auto far = fields(rows[3]);  // J_n ~ exp(-1000): values underflow, logs stay finite
  EXPECT_EQ(std::stod(far[4]), 0.0);
  EXPECT_NEAR(std::stod(far[10]), -1000.0, 1e-9);
  auto zero = fields(rows[4]);  // bounded side out of contact: exactly 0, log -inf
  EXPECT_EQ(zero[9], "0");
  EXPECT_EQ(zero[15], "-inf");
  // the shortest text that reads back to the same double
  EXPECT_EQ(fields(rows[2])[3], "1.5");
  for (const std::string& row : rows)
    for (const std::string& field : fields(row)) {
      double value;
      if (!read_double(field, value) || !std::isfinite(value)) continue;
      EXPECT_EQ(format_double(value), field) << "not the shortest form: " << field;
    }
}

// Each row answered from the table's shape nodes (Table::direct_curve): a row's numbers do not
// depend on the rows before it (more than the cache holds: 300 shapes between two asks of one),
// and --grid's lookup grids agree within 2e-13 of ln X.
TEST(EvalCsv, ARowsAnswerIsItsOwnAndTheGridsAgree) {
  std::string text = "dist,side,shape,sep\nweibull,tail,1.73,0.8\n";
  for (int i = 0; i < 300; ++i) text += "weibull,tail," + format_double(0.6 + i * 0.05) + ",0.8\n";
  text += "weibull,tail,1.73,0.8\n";
  std::stringstream direct_input(text), grid_input(text), direct, grid, errors;
  EXPECT_EQ(cli::eval_csv(table(), direct_input, direct, errors), 0u) << errors.str();
  EXPECT_EQ(cli::eval_csv(table(), grid_input, grid, errors, true), 0u) << errors.str();
  const auto rows = lines(direct.str()), grid_rows = lines(grid.str());
  ASSERT_EQ(rows.size(), 303u);
  ASSERT_EQ(grid_rows.size(), 303u);
  EXPECT_EQ(rows[1], rows[302]);
  for (std::size_t r = 1; r < rows.size(); ++r) {
    const auto a = fields(rows[r]), b = fields(grid_rows[r]);
    for (std::size_t k = 10; k < 16; ++k) {
      const double x = std::stod(a[k]), y = std::stod(b[k]);
      EXPECT_LE(std::fabs(x - y), 2e-13 * (1 + std::fabs(y))) << rows[r] << "\n" << grid_rows[r];
    }
  }
}

TEST(EvalCsv, BadRowsAreNamedAndGoodRowsKept) {
  std::stringstream input(
      "dist,side,shape,sep\nweibull,tail,2,1\nweibull,tail,2,nan\nbeta,tail,2,1\nweibull,middle,2,1\n"
      "weibull,tail,100,1\nweibull,tail,2\ngaussian,bounded,,1\nweibull,tail,2,inf\nweibull,tail,x,1\nweibull,tail,2,2\n");
  std::stringstream output, errors;
  EXPECT_EQ(cli::eval_csv(table(), input, output, errors), 8);
  const auto rows = lines(output.str());
  ASSERT_EQ(rows.size(), 3u);  // header and the two good rows
  const std::string messages = errors.str();
  for (const char* expected : {"line 3: sep 'nan'", "line 4: unknown dist 'beta'", "line 5: unknown side 'middle'",
                               "line 6: shape 100 is outside", "line 7: expected 4 fields", "line 8: the Gaussian has no bounded side",
                               "line 9: sep 'inf'", "line 10: shape 'x'"})
    EXPECT_NE(messages.find(expected), std::string::npos) << expected << "\n" << messages;
}

TEST(EvalCsv, RejectsAMissingOrWrongHeader) {
  std::stringstream empty(""), wrong("a,b,c,d\nweibull,tail,2,1\n"), output, errors;
  EXPECT_EQ(cli::eval_csv(table(), empty, output, errors), 1);
  EXPECT_EQ(cli::eval_csv(table(), wrong, output, errors), 1);
  EXPECT_NE(errors.str().find("line 1"), std::string::npos);
}

TEST(EvalCsv, EchoesShapesInTheShortestFormThatReadsBack) {
  std::stringstream input("dist,side,shape,sep\nweibull,tail,1.6,0.1\nweibull,tail,1.60,3e-1\n");
  std::stringstream output, errors;
  ASSERT_EQ(cli::eval_csv(table(), input, output, errors), 0) << errors.str();
  const auto rows = lines(output.str());
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(fields(rows[1])[2], "1.6");  // not 1.6000000000000001
  EXPECT_EQ(fields(rows[2])[2], "1.6");
  EXPECT_EQ(fields(rows[2])[3], "0.3");
}

TEST(EvalCsv, ReadsEveryLineEnding) {
  for (const char* text : {"dist,side,shape,sep\nweibull,tail,2,0\nweibull,tail,2,1\n",
                           "dist,side,shape,sep\r\nweibull,tail,2,0\r\nweibull,tail,2,1\r\n",
                           "dist,side,shape,sep\rweibull,tail,2,0\rweibull,tail,2,1\r",
                           "dist,side,shape,sep\rweibull,tail,2,0\r\nweibull,tail,2,1"}) {
    std::stringstream input(text), output, errors;
    EXPECT_EQ(cli::eval_csv(table(), input, output, errors), 0) << errors.str();
    EXPECT_EQ(lines(output.str()).size(), 3u) << output.str();
  }
  // A lone CR counts as a line: the bad row is named by its line.
  std::stringstream input("dist,side,shape,sep\rweibull,tail,2,0\rweibull,tail,2,x\r"), output, errors;
  EXPECT_EQ(cli::eval_csv(table(), input, output, errors), 1);
  EXPECT_NE(errors.str().find("line 3: sep 'x'"), std::string::npos) << errors.str();
}

TEST(EvalCsv, RefusesBytesAfterANumber) {
  using namespace std::string_literals;  // the text holds NUL bytes
  const std::string text = "dist,side,shape,sep\nweibull,tail,0.5\0junk,1\nweibull,tail,2,1\0\n"s;
  std::stringstream input(text), output, errors;
  EXPECT_EQ(cli::eval_csv(table(), input, output, errors), 2);
  EXPECT_NE(errors.str().find("line 2: shape '0.5\\x00junk'"), std::string::npos) << errors.str();
  EXPECT_NE(errors.str().find("line 3: sep '1\\x00'"), std::string::npos) << errors.str();
  EXPECT_EQ(lines(output.str()).size(), 1u);
}

TEST(EvalCsv, NamesAShapeOutsideTheTableWithItsOwnDigits) {
  std::stringstream input("dist,side,shape,sep\nweibull,tail,0.4999999,1\n"), output, errors;
  EXPECT_EQ(cli::eval_csv(table(), input, output, errors), 1);
  EXPECT_NE(errors.str().find("shape 0.4999999 is outside the table's range [0.5, 20]"), std::string::npos)
      << errors.str();
}

// Issue #28: the served range is exact: a shape a hair outside [0.5, 20] is refused, and one a
// hair off a grid node is interpolated (not served as the node).
TEST(EvalCsv, TheShapeRangeIsExact) {
  std::stringstream input("dist,side,shape,sep\nweibull,tail,0.49999999999995,1\nweibull,tail,20.0000000000001,1\n"
                          "weibull,tail,0.5,1\nweibull,tail,20,1\n"),
      output, errors;
  EXPECT_EQ(cli::eval_csv(table(), input, output, errors), 2);
  EXPECT_NE(errors.str().find("line 2: shape 0.49999999999995 is outside the table's range [0.5, 20]"),
            std::string::npos) << errors.str();
  EXPECT_NE(errors.str().find("line 3: shape 20.0000000000001 is outside"), std::string::npos) << errors.str();
  EXPECT_EQ(lines(output.str()).size(), 3u);
}

// A scene table (here one made in memory from the default table's knots, served over [-2, -0.5])
// refuses a row outside what it serves, naming the range; the bounded side at s >= 0 is 0.
TEST(EvalCsv, RefusesASeparationOutsideWhatASceneTableServes) {
  const CurveSet& full = *table().find(Distribution::weibull, Side::bounded);
  const std::size_t index = static_cast<std::size_t>(std::find(full.shapes.begin(), full.shapes.end(), 2.0) -
                                                     full.shapes.begin());
  ASSERT_LT(index, full.shapes.size());
  CurveSet set = full;
  set.shapes = {2.0};
  set.shape_min = set.shape_max = 2.0;
  set.knots.assign(full.knots.begin() + index * full.curve_stride(), full.knots.begin() + (index + 1) * full.curve_stride());
  set.max_rel_error.assign(full.max_rel_error.begin() + index * order_count,
                           full.max_rel_error.begin() + (index + 1) * order_count);
  set.grid_tolerance = {1e-13};
  set.grid_separations = {-2.0, -0.5};
  TableData data;
  data.exact_shapes = true;
  data.sets.push_back(set);
  const Table scene(std::move(data));
  std::stringstream input("dist,side,shape,sep\nweibull,bounded,2,-1\nweibull,bounded,2,-3\nweibull,bounded,2,-0.25\n"
                          "weibull,bounded,2,0.5\nweibull,bounded,2,-2\n"),
      output, errors;
  EXPECT_EQ(cli::eval_csv(scene, input, output, errors), 2);
  EXPECT_NE(errors.str().find("line 3: sep -3 is outside the separations this table serves for weibull bounded 2: "
                              "[-2, -0.5]"),
            std::string::npos)
      << errors.str();
  EXPECT_NE(errors.str().find("line 4: sep -0.25 is outside"), std::string::npos) << errors.str();
  const std::vector<std::string> rows = lines(output.str());
  ASSERT_EQ(rows.size(), 4u) << output.str();
  EXPECT_EQ(fields(rows[1])[3], "-1");
  EXPECT_EQ(fields(rows[2])[4], "0");  // s = 0.5: out of contact, exactly 0
  EXPECT_EQ(fields(rows[3])[3], "-2");
}

TEST(EvalCsv, RefusesAnOverlongLineAndGoesOn) {
  std::string text = "\xEF\xBB\xBF" "dist,side,shape,sep\nweibull,tail,2,";
  text += std::string(cli::max_line_bytes, '1');
  text += "\nweibull,tail,2,1\n";
  std::stringstream input(text), output, errors;
  EXPECT_EQ(cli::eval_csv(table(), input, output, errors), 1);
  EXPECT_NE(errors.str().find("line 2: longer than"), std::string::npos) << errors.str();
  EXPECT_EQ(lines(output.str()).size(), 2u);
}

TEST(NumberText, ReadsAllOfTheTextAndRoundsOnce) {
  double value = -1;
  EXPECT_TRUE(read_double("1.6", value));
  EXPECT_EQ(value, 1.6);
  EXPECT_TRUE(read_double("+2.5e-3", value));
  EXPECT_EQ(value, 2.5e-3);
  EXPECT_TRUE(read_double("1e400", value));
  EXPECT_EQ(value, INFINITY);  // beyond DBL_MAX: rounds to inf (callers refuse it)
  EXPECT_TRUE(read_double("-1e-400", value));
  EXPECT_EQ(value, 0.0);
  EXPECT_TRUE(std::signbit(value));
  for (const char* bad : {"", " 1", "1 ", "1e", "0x1p3", "++1", "+-1", "1,5", "--1"})
    EXPECT_FALSE(read_double(bad, value)) << bad;
  EXPECT_FALSE(read_double(std::string_view("0.5\0junk", 8), value));
  long long whole = 0;
  EXPECT_TRUE(read_whole_number("42", 1, 100, whole));
  EXPECT_EQ(whole, 42);
  for (const char* bad : {"1e300", "1e3", "0", "101", "4.0", "010x", ""})
    EXPECT_FALSE(read_whole_number(bad, 1, 100, whole)) << bad;
  EXPECT_EQ(format_double(1.6), "1.6");
  EXPECT_EQ(format_double(0.1 + 0.2), "0.30000000000000004");
  EXPECT_EQ(format_double(-INFINITY), "-inf");
  EXPECT_EQ(quote_text(std::string_view("a\0b\n", 4)), "a\\x00b\\x0A");
}

}  // namespace
