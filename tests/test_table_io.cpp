// Table files: round trip, deterministic bytes, atomic writes, and every kind of bad file
// getting a clear error.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>

#include "asperity/error.hpp"
#include "asperity/table.hpp"
#include "asperity/table_schema.hpp"
#include "generate.hpp"
#include "table_writer.hpp"

namespace {
using namespace asperity;

std::string temp_path(const std::string& name) { return std::string(ASPERITY_TEST_BINARY_DIR) + "/" + name; }

std::string read_bytes(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(file), {});
}

// A small table: two shapes of each Weibull side and the Gaussian, generated in the test.
const TableData& small_table() {
  static const TableData data = [] {
    tablegen::GenerateOptions options;
    options.shape_min = 1.5;
    options.shape_max = 1.6;
    options.shape_log_step = 1.0;
    options.check_stride = 8;
    return tablegen::generate_table(options);
  }();
  return data;
}

std::string expect_error(const std::string& path) {
  try {
    Table::open(path);
  } catch (const Error& error) {
    return error.what();
  }
  ADD_FAILURE() << "no error for " << path;
  return "";
}

TEST(TableIo, RoundTripKeepsEveryNumber) {
  const std::string path = temp_path("roundtrip.h5");
  tablegen::write_table_file(small_table(), path);
  const TableData read = read_table_file(path);
  ASSERT_EQ(read.sets.size(), small_table().sets.size());
  for (std::size_t i = 0; i < read.sets.size(); ++i) {
    EXPECT_EQ(read.sets[i].shapes, small_table().sets[i].shapes);
    EXPECT_EQ(read.sets[i].knots, small_table().sets[i].knots);
    EXPECT_EQ(read.sets[i].max_rel_error, small_table().sets[i].max_rel_error);
    EXPECT_EQ(read.sets[i].shape_min, small_table().sets[i].shape_min);
  }
  EXPECT_EQ(read.generator_options, small_table().generator_options);
}

TEST(TableIo, SameDataSameBytes) {
  tablegen::write_table_file(small_table(), temp_path("first.h5"));
  tablegen::write_table_file(small_table(), temp_path("second.h5"));
  EXPECT_EQ(read_bytes(temp_path("first.h5")), read_bytes(temp_path("second.h5")));
  // and generation itself is deterministic, whatever the thread count
  tablegen::GenerateOptions options;
  options.shape_min = options.shape_max = 2.5;
  options.check_stride = 8;
  options.threads = 1;
  const TableData one = tablegen::generate_table(options);
  options.threads = 3;
  const TableData three = tablegen::generate_table(options);
  for (std::size_t i = 0; i < one.sets.size(); ++i) EXPECT_EQ(one.sets[i].knots, three.sets[i].knots);
}

TEST(TableIo, FailedWriteLeavesTheTargetAlone) {
  const std::string path = temp_path("keep.h5");
  tablegen::write_table_file(small_table(), path);
  const std::string before = read_bytes(path);
  TableData broken = small_table();
  broken.sets[0].knots.pop_back();  // inconsistent: the writer refuses it midway
  EXPECT_THROW(tablegen::write_table_file(broken, path), Error);
  EXPECT_EQ(read_bytes(path), before);
  EXPECT_THROW(tablegen::write_table_file(small_table(), "/nonexistent-dir/table.h5"), Error);
}

TEST(TableIo, MissingFile) {
  EXPECT_NE(expect_error(temp_path("does-not-exist.h5")).find("no such file"), std::string::npos);
}

TEST(TableIo, NotHdf5) {
  const std::string path = temp_path("text.h5");
  std::ofstream(path) << "dist,side,shape,sep\n";
  EXPECT_NE(expect_error(path).find("not an HDF5 file"), std::string::npos);
}

TEST(TableIo, TruncatedFile) {
  const std::string path = temp_path("whole.h5"), cut = temp_path("truncated.h5");
  tablegen::write_table_file(small_table(), path);
  const std::string bytes = read_bytes(path);
  for (double fraction : {0.9, 0.5, 0.01}) {
    std::ofstream(cut, std::ios::binary) << bytes.substr(0, static_cast<std::size_t>(bytes.size() * fraction));
    const std::string message = expect_error(cut);
    EXPECT_NE(message.find("truncated.h5"), std::string::npos) << message;
  }
}

TEST(TableIo, ForeignHdf5AndWrongVersion) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const std::string foreign = temp_path("foreign.h5");
  hid_t file = H5Fcreate(foreign.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  H5Fclose(file);
  EXPECT_NE(expect_error(foreign).find("not an asperity table"), std::string::npos);

  const std::string old = temp_path("old-version.h5");
  tablegen::write_table_file(small_table(), old);
  file = H5Fopen(old.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  hid_t attribute = H5Aopen(file, schema::attr_schema_version, H5P_DEFAULT);
  const int other = schema::version + 1;
  H5Awrite(attribute, H5T_NATIVE_INT, &other);
  H5Aclose(attribute);
  H5Fclose(file);
  EXPECT_NE(expect_error(old).find("schema version"), std::string::npos);
}

TEST(TableIo, CorruptValuesAreRefused) {
  TableData data = small_table();
  data.sets[0].knots[5] = std::nan("");
  EXPECT_THROW(Table{data}, Error);
  data = small_table();
  std::swap(data.sets[0].shapes.front(), data.sets[0].shapes.back());
  EXPECT_THROW(Table{data}, Error);
}

TEST(TableIo, ShapesOutsideTheTableAndBadNames) {
  const Table table(small_table());
  EXPECT_THROW(table.curve(Distribution::weibull, Side::tail, 1.0), Error);
  EXPECT_THROW(table.curve(Distribution::weibull, Side::tail, std::nan("")), Error);
  EXPECT_THROW(table.curve(Distribution::weibull, Side::tail, INFINITY), Error);
  EXPECT_THROW(table.curve(Distribution::gaussian, Side::bounded, 2), Error);
  EXPECT_NO_THROW(table.curve(Distribution::weibull, Side::bounded, 1.55));
  Distribution distribution;
  Side side;
  EXPECT_FALSE(parse_distribution("Weibull", distribution));
  EXPECT_FALSE(parse_side("", side));
}

TEST(TableIo, HotPathReportsBadInputByValue) {
  const Table table(small_table());
  const Curve curve = table.curve(Distribution::weibull, Side::tail, 1.5);
  EXPECT_TRUE(std::isnan(curve.log_value(0, std::nan(""))));
  EXPECT_TRUE(std::isnan(curve.log_value(0, INFINITY)));
  EXPECT_TRUE(std::isnan(curve.log_value(0, -INFINITY)));
  EXPECT_TRUE(std::isnan(curve.log_value(-1, 1.0)));
  EXPECT_TRUE(std::isnan(curve.log_value(6, 1.0)));
  EXPECT_TRUE(std::isnan(Curve().log_value(0, 1.0)));  // an empty handle answers NaN too
  EXPECT_TRUE(std::isfinite(curve.log_value(5, 1e100)));  // ln X = -1e150: finite, the value 0
  EXPECT_EQ(curve.value(5, 1e100), 0.0);
  EXPECT_EQ(curve.log_value(5, 1e300), -INFINITY);  // -s^a itself overflows: the only double answer
}

}  // namespace
