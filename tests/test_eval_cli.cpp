// The `asperity eval` contract: header, %.17g numbers, logs finite below 1e-308, -inf where
// the value is exactly 0, bad rows named by line with good rows kept.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "eval_csv.hpp"

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
  // %.17g round-trips the double exactly
  EXPECT_EQ(fields(rows[2])[3], "1.5");
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

}  // namespace
