// Table files: round trip, deterministic bytes, atomic writes, and every kind of bad file
// getting a clear error and its status: missing, not HDF5, truncated, damaged, old, foreign,
// and deliberately crafted files with a valid integrity header (issue 11's reproducers, built
// here with HDF5's C API).
#include <gtest/gtest.h>
#include <hdf5.h>
#include <sys/stat.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/table.hpp"
#include "asperity/table_file.hpp"
#include "asperity/detail/table_schema.hpp"
#include "asperity/generator/generate.hpp"
#include "asperity/table_writer.hpp"

namespace {
using namespace asperity;

std::string temp_path(const std::string& name) { return std::string(ASPERITY_TEST_BINARY_DIR) + "/" + name; }

std::string read_bytes(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(file), {});
}
void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

// A small table: two shapes of each Weibull side and the Gaussian, generated in the test.
const TableData& small_table() {
  static const TableData data = [] {
    generator::GenerateOptions options;
    options.shape_min = 1.5;
    options.shape_max = 1.6;
    options.shape_log_step = 1.0;
    options.check_stride = 8;
    return generator::generate_table(options);
  }();
  return data;
}

// A tiny table of the right structure (its numbers are not integrals): what the hostile files
// below are made from, in milliseconds.
TableData tiny_table() {
  TableData data;
  data.generator = "test";
  data.generator_options = "tiny";
  const struct { Distribution distribution; Side side; std::vector<double> shapes; } sets[] = {
      {Distribution::weibull, Side::tail, {1.5, 1.6}}, {Distribution::gaussian, Side::tail, {2.0}}};
  for (const auto& spec : sets) {
    CurveSet set;
    set.distribution = spec.distribution;
    set.side = spec.side;
    set.shapes = spec.shapes;
    set.shape_min = spec.shapes.front();
    set.shape_max = spec.shapes.back();
    set.layout = scale_knot_density(default_layout(spec.distribution, spec.side), 0.05);
    set.knots.assign(set.shapes.size() * set.curve_stride(), 0.25);
    set.max_rel_error.assign(set.shapes.size() * order_count, 1e-13);
    data.sets.push_back(set);
  }
  return data;
}

struct Refusal {
  TableFileStatus status;
  std::string message;
};

Refusal refusal(const std::string& path) {
  try {
    Table::open(path);
  } catch (const TableFileError& error) {
    return {error.status(), error.what()};
  } catch (const std::exception& error) {
    ADD_FAILURE() << "not a TableFileError: " << error.what();
    return {TableFileStatus::invalid, error.what()};
  }
  ADD_FAILURE() << "no error for " << path;
  return {TableFileStatus::invalid, ""};
}

#define EXPECT_REFUSED(path, expected_status, text)                                       \
  do {                                                                                    \
    const Refusal refused = refusal(path);                                                \
    EXPECT_EQ(refused.status, expected_status) << refused.message;                        \
    EXPECT_NE(refused.message.find(text), std::string::npos) << refused.message;          \
  } while (0)

// Seals a file again: a valid integrity header for whatever its bytes now are.
void reseal(const std::string& path) {
  std::string bytes = read_bytes(path);
  seal_table_bytes(reinterpret_cast<unsigned char*>(&bytes[0]), bytes.size());
  write_bytes(path, bytes);
}

// A deliberately crafted table: written, changed through HDF5's C API, and sealed again with a
// valid integrity header, so that it reaches the reader's own checks.
std::string crafted(const std::string& name, const std::function<void(hid_t file)>& edit,
                    const TableData& data = tiny_table()) {
  const std::string path = temp_path(name);
  write_table_file(data, path, true);
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  EXPECT_GE(file, 0);
  edit(file);
  EXPECT_GE(H5Fclose(file), 0);
  reseal(path);
  return path;
}

void replace_attribute(hid_t object, const char* name, hid_t type, hid_t space, const void* value) {
  if (H5Aexists(object, name) > 0) H5Adelete(object, name);
  const hid_t attribute = H5Acreate2(object, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(attribute, 0);
  EXPECT_GE(H5Awrite(attribute, type, value), 0);
  H5Aclose(attribute);
}

hid_t simple_space(std::vector<hsize_t> dims) {
  return H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr);
}

hid_t variable_string(H5T_cset_t charset) {
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, H5T_VARIABLE);
  H5Tset_cset(type, charset);
  return type;
}

// Replaces a dataset of group `group` with one of another type or shape (values converted by HDF5).
void replace_dataset(hid_t file, const char* group, const char* name, hid_t file_type,
                     const std::vector<hsize_t>& dims, const std::vector<double>& values, bool chunked = false) {
  const hid_t g = H5Gopen2(file, group, H5P_DEFAULT);
  ASSERT_GE(g, 0);
  H5Ldelete(g, name, H5P_DEFAULT);
  const hid_t space = simple_space(dims);
  const hid_t properties = H5Pcreate(H5P_DATASET_CREATE);
  if (chunked) {
    std::vector<hsize_t> chunk(dims.size(), 1);
    chunk.back() = dims.back();
    H5Pset_chunk(properties, static_cast<int>(dims.size()), chunk.data());
  }
  const hid_t set = H5Dcreate2(g, name, file_type, space, H5P_DEFAULT, properties, H5P_DEFAULT);
  ASSERT_GE(set, 0);
  if (!values.empty()) {
    EXPECT_GE(H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), 0);
  }
  H5Dclose(set);
  H5Pclose(properties);
  H5Sclose(space);
  H5Gclose(g);
}

std::vector<double> knots_of(const TableData& data) { return data.sets[0].knots; }
std::vector<hsize_t> knot_dims(const CurveSet& set) {
  return {set.shapes.size(), hsize_t(order_count), hsize_t(set.total_knots()), 3};
}

// ---- written by the writer ----

TEST(TableIo, RoundTripKeepsEveryNumber) {
  const std::string path = temp_path("roundtrip.h5");
  write_table_file(small_table(), path, true);
  const TableData read = read_table_file(path);
  ASSERT_EQ(read.sets.size(), small_table().sets.size());
  for (std::size_t i = 0; i < read.sets.size(); ++i) {
    EXPECT_EQ(read.sets[i].shapes, small_table().sets[i].shapes);
    EXPECT_EQ(read.sets[i].knots, small_table().sets[i].knots);
    EXPECT_EQ(read.sets[i].max_rel_error, small_table().sets[i].max_rel_error);
    EXPECT_EQ(read.sets[i].shape_min, small_table().sets[i].shape_min);
  }
  EXPECT_EQ(read.generator_options, small_table().generator_options);
  // the same from the bytes in memory
  const std::string bytes = read_bytes(path);
  EXPECT_EQ(read_table_bytes(bytes.data(), bytes.size(), "memory").sets[0].knots, read.sets[0].knots);
}

TEST(TableIo, SameDataSameBytes) {
  write_table_file(small_table(), temp_path("first.h5"), true);
  write_table_file(small_table(), temp_path("second.h5"), true);
  EXPECT_EQ(read_bytes(temp_path("first.h5")), read_bytes(temp_path("second.h5")));
  // and generation itself is deterministic, whatever the thread count
  generator::GenerateOptions options;
  options.shape_min = options.shape_max = 2.5;
  options.check_stride = 8;
  options.threads = 1;
  const TableData one = generator::generate_table(options);
  options.threads = 3;
  const TableData three = generator::generate_table(options);
  for (std::size_t i = 0; i < one.sets.size(); ++i) EXPECT_EQ(one.sets[i].knots, three.sets[i].knots);
}

TEST(TableIo, TheHeaderIsTheFormatOfTableSchema) {
  const std::string path = temp_path("header.h5");
  write_table_file(tiny_table(), path, true);
  const std::string bytes = read_bytes(path);
  ASSERT_GT(bytes.size(), schema::header_bytes);
  EXPECT_EQ(std::memcmp(bytes.data(), schema::header_magic, sizeof schema::header_magic), 0);
  EXPECT_EQ(static_cast<unsigned char>(bytes[schema::header_version_offset]), schema::version);
  EXPECT_EQ(bytes.compare(schema::header_bytes, 8, "\x89HDF\r\n\x1a\n"), 0);  // HDF5 after the user block
  // HDF5 itself (h5dump, h5py) reads the file as it is: the header is its user block.
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const hid_t properties = H5Fget_create_plist(file);
  hsize_t user_block = 0;
  H5Pget_userblock(properties, &user_block);
  EXPECT_EQ(user_block, schema::header_bytes);
  H5Pclose(properties);
  H5Fclose(file);
}

TEST(TableIo, FailedWriteLeavesTheTargetAlone) {
  const std::string path = temp_path("keep.h5");
  write_table_file(small_table(), path, true);
  const std::string before = read_bytes(path);
  TableData broken = small_table();
  broken.sets[0].knots.pop_back();  // inconsistent: the writer refuses it
  EXPECT_THROW(write_table_file(broken, path), Error);
  EXPECT_EQ(read_bytes(path), before);
  EXPECT_THROW(write_table_file(small_table(), "/nonexistent-dir/table.h5"), Error);
}

TEST(TableIo, TheWriterRefusesWhatTheReaderWould) {
  TableData data = tiny_table();
  data.sets[0].knots[3] = 1e7;  // beyond schema::max_knot_value
  EXPECT_THROW(table_file_bytes(data), Error);
  data = tiny_table();
  data.generator_options.assign(70000, 'x');  // a scene name over 64 KiB
  try {
    table_file_bytes(data);
    ADD_FAILURE() << "no error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("'generator_options' would hold 70000 bytes"), std::string::npos)
        << error.what();
  }
}

// ---- files that are not tables, damaged, or of another version ----

TEST(TableIo, MissingFile) {
  EXPECT_REFUSED(temp_path("does-not-exist.h5"), TableFileStatus::missing, "no such file");
}

TEST(TableIo, NotHdf5) {
  const std::string path = temp_path("text.h5");
  write_bytes(path, "dist,side,shape,sep\n");
  EXPECT_REFUSED(path, TableFileStatus::not_hdf5, "not an asperity table, nor any HDF5 file");
  write_bytes(path, "");
  EXPECT_REFUSED(path, TableFileStatus::not_hdf5, "empty");
}

TEST(TableIo, DirectoriesFifosAndDevicesAreRefusedWithoutWaiting) {
  EXPECT_REFUSED(ASPERITY_TEST_BINARY_DIR, TableFileStatus::unreadable, "a directory, not a file");
  EXPECT_REFUSED("/dev/null", TableFileStatus::unreadable, "not a regular file");
  const std::string fifo = temp_path("table.fifo");
  std::remove(fifo.c_str());
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_REFUSED(fifo, TableFileStatus::unreadable, "FIFO");  // with no writer: it hung before
  std::remove(fifo.c_str());
}

TEST(TableIo, TruncatedFile) {
  const std::string path = temp_path("whole.h5"), cut = temp_path("truncated.h5");
  write_table_file(small_table(), path, true);
  const std::string bytes = read_bytes(path);
  for (double fraction : {0.9, 0.5, 0.01, 0.0001}) {
    write_bytes(cut, bytes.substr(0, static_cast<std::size_t>(bytes.size() * fraction)));
    EXPECT_REFUSED(cut, TableFileStatus::damaged, "truncated.h5");
  }
  write_bytes(cut, bytes + "appended");
  EXPECT_REFUSED(cut, TableFileStatus::damaged, "more than its header says");
}

// One changed byte anywhere is found before HDF5 reads anything (HDF5 1.10.8 crashed on such files).
TEST(TableIo, EveryChangedByteIsFound) {
  const std::string path = temp_path("pristine.h5"), changed = temp_path("changed.h5");
  write_table_file(tiny_table(), path, true);
  const std::string bytes = read_bytes(path);
  int checked = 0;
  for (std::size_t position = 0; position < bytes.size(); position += position < 600 ? 1 : 97) {
    std::string copy = bytes;
    copy[position] = static_cast<char>(copy[position] ^ (1 << (position % 8)));
    write_bytes(changed, copy);
    const Refusal refused = refusal(changed);
    // damaged; a changed version field reads as another version
    const bool version_field = position >= schema::header_version_offset && position < schema::header_size_offset;
    EXPECT_EQ(refused.status, version_field ? TableFileStatus::other_version : TableFileStatus::damaged)
        << position << ": " << refused.message;
    ++checked;
  }
  EXPECT_GT(checked, 700);
}

TEST(TableIo, OldTablesWithoutTheHeaderAskToBeRegenerated) {
  // A version-1 table: the same HDF5 file without the integrity header in its user block.
  const std::string path = temp_path("version1.h5");
  write_table_file(tiny_table(), path, true);
  std::string bytes = read_bytes(path);
  write_bytes(path, bytes.substr(schema::header_bytes));  // no user block, as version 1 wrote them
  EXPECT_REFUSED(path, TableFileStatus::other_version, "format version 1");
  EXPECT_REFUSED(path, TableFileStatus::other_version, "regenerate it with this tablegen");
  std::fill(bytes.begin(), bytes.begin() + schema::header_bytes, '\0');  // a user block without the header
  write_bytes(path, bytes);
  EXPECT_REFUSED(path, TableFileStatus::damaged, "integrity header is missing or damaged");
  // a future format version
  write_table_file(tiny_table(), path, true);
  bytes = read_bytes(path);
  bytes[schema::header_version_offset] = static_cast<char>(schema::version + 1);
  write_bytes(path, bytes);
  EXPECT_REFUSED(path, TableFileStatus::other_version, "format version 3");
}

TEST(TableIo, ForeignHdf5AndWrongVersion) {
  const std::string foreign = temp_path("foreign.h5");
  const hid_t file = H5Fcreate(foreign.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  H5Fclose(file);
  EXPECT_REFUSED(foreign, TableFileStatus::other_schema, "not an asperity table");
  // with a valid header but no schema attribute, or another one
  const std::string no_schema = crafted("no-schema.h5", [](hid_t file) { H5Adelete(file, schema::attr_schema); });
  EXPECT_REFUSED(no_schema, TableFileStatus::other_schema, "not an asperity table");
  const std::string other = crafted("other-schema.h5", [](hid_t file) {
    const hid_t type = variable_string(H5T_CSET_ASCII), space = H5Screate(H5S_SCALAR);
    const char* text = "someone-elses-table";
    replace_attribute(file, schema::attr_schema, type, space, &text);
    H5Tclose(type);
    H5Sclose(space);
  });
  EXPECT_REFUSED(other, TableFileStatus::other_schema, "another schema");
  const std::string old = crafted("old-version.h5", [](hid_t file) {
    const hid_t space = H5Screate(H5S_SCALAR);
    const int version = 1;
    replace_attribute(file, schema::attr_schema_version, H5T_NATIVE_INT, space, &version);
    H5Sclose(space);
  });
  EXPECT_REFUSED(old, TableFileStatus::other_version, "schema version 1");
}

TEST(TableIo, ACraftedHeaderOverBytesHdf5CannotReadIsRefused) {
  std::string bytes(schema::header_bytes + 4096, '\0');
  for (std::size_t i = schema::header_bytes; i < bytes.size(); ++i) bytes[i] = static_cast<char>(i * 131 % 251);
  seal_table_bytes(reinterpret_cast<unsigned char*>(&bytes[0]), bytes.size());
  const std::string path = temp_path("sealed-noise.h5");
  write_bytes(path, bytes);
  EXPECT_REFUSED(path, TableFileStatus::invalid, "HDF5 cannot open");
}

// ---- crafted files with a valid header: the reader's own checks (issue 11's reproducers) ----

TEST(TableIo, AttributesMustBeScalarAndOfTheirType) {
  // `schema` as 2 strings (was a heap-buffer-overflow)
  EXPECT_REFUSED(crafted("schema-array.h5",
                         [](hid_t file) {
                           const hid_t type = variable_string(H5T_CSET_ASCII), space = simple_space({2});
                           const char* texts[2] = {"asperity-table", "asperity-table"};
                           replace_attribute(file, schema::attr_schema, type, space, texts);
                           H5Tclose(type);
                           H5Sclose(space);
                         }),
                 TableFileStatus::invalid, "'schema' must hold one value");
  // `schema_version` as 64 and 4096 int64s (a stack overwrite that opened silently; SIGSEGV)
  for (hsize_t count : {64, 4096}) {
    EXPECT_REFUSED(crafted("version-array.h5",
                           [count](hid_t file) {
                             const std::vector<long long> versions(count, schema::version);
                             const hid_t space = simple_space({count});
                             replace_attribute(file, schema::attr_schema_version, H5T_NATIVE_LLONG, space,
                                               versions.data());
                             H5Sclose(space);
                           }),
                   TableFileStatus::invalid, "'schema_version' must hold one value");
  }
  // 8 ASCII variable-length strings (a stack-buffer-overflow)
  EXPECT_REFUSED(crafted("generator-array.h5",
                         [](hid_t file) {
                           const hid_t type = variable_string(H5T_CSET_ASCII), space = simple_space({8});
                           const char* texts[8] = {"a", "b", "c", "d", "e", "f", "g", "h"};
                           replace_attribute(file, schema::attr_generator, type, space, texts);
                           H5Tclose(type);
                           H5Sclose(space);
                         }),
                 TableFileStatus::invalid, "'generator' must hold one value");
  // schema_version 1.9, a float: not read as 1 (nor 2.0 as 2)
  for (double version : {1.9, 2.0}) {
    EXPECT_REFUSED(crafted("version-float.h5",
                           [version](hid_t file) {
                             const hid_t space = H5Screate(H5S_SCALAR);
                             replace_attribute(file, schema::attr_schema_version, H5T_NATIVE_DOUBLE, space, &version);
                             H5Sclose(space);
                           }),
                   TableFileStatus::invalid, "'schema_version' is not an integer");
  }
  // text where a number belongs, and exact_shapes out of range
  EXPECT_REFUSED(crafted("exact-shapes.h5",
                         [](hid_t file) {
                           const hid_t space = H5Screate(H5S_SCALAR);
                           const int exact = 5;
                           replace_attribute(file, schema::attr_exact_shapes, H5T_NATIVE_INT, space, &exact);
                           H5Sclose(space);
                         }),
                 TableFileStatus::invalid, "'exact_shapes' must be 0 or 1");
}

TEST(TableIo, Utf8TextAttributesAreRead) {
  // h5py's default for str attributes: variable-length UTF-8
  const std::string path = crafted("utf8.h5", [](hid_t file) {
    const hid_t type = variable_string(H5T_CSET_UTF8), space = H5Screate(H5S_SCALAR);
    const char* generator = "tablegen \xc3\xa9t\xc3\xa9";  // "été"
    replace_attribute(file, schema::attr_generator, type, space, &generator);
    const hid_t fixed = H5Tcopy(H5T_C_S1);  // and fixed-length UTF-8, filling its size (no terminator)
    H5Tset_size(fixed, 4);
    H5Tset_cset(fixed, H5T_CSET_UTF8);
    H5Tset_strpad(fixed, H5T_STR_NULLPAD);
    replace_attribute(file, schema::attr_generator_options, fixed, space, "abcd");
    H5Tclose(fixed);
    H5Tclose(type);
    H5Sclose(space);
  });
  const TableData data = read_table_file(path);
  EXPECT_EQ(data.generator, "tablegen \xc3\xa9t\xc3\xa9");
  EXPECT_EQ(data.generator_options, "abcd");
}

TEST(TableIo, DatasetsMustHoldTheirExactType) {
  const TableData data = tiny_table();
  // knots as int64 (answers were off by 171%) and float32 (off by 1.2e-7)
  for (hid_t type : {H5T_STD_I64LE, H5T_IEEE_F32LE}) {
    EXPECT_REFUSED(crafted("knots-type.h5",
                           [&](hid_t file) {
                             replace_dataset(file, "weibull_tail", schema::set_knots, type, knot_dims(data.sets[0]),
                                             knots_of(data));
                           }),
                   TableFileStatus::invalid, "'knots' must hold 64-bit IEEE floats");
  }
  EXPECT_REFUSED(crafted("kinds-float.h5",
                         [&](hid_t file) {
                           std::vector<double> kinds;
                           for (const SegmentSpec& spec : data.sets[0].layout) kinds.push_back(int(spec.kind));
                           replace_dataset(file, "weibull_tail", schema::set_segment_kind, H5T_IEEE_F64LE,
                                           {kinds.size()}, kinds);
                         }),
                 TableFileStatus::invalid, "'segment_kind' must hold integers");
  EXPECT_REFUSED(crafted("orders.h5",
                         [&](hid_t file) {
                           replace_dataset(file, "gaussian_tail", schema::set_orders, H5T_IEEE_F64LE, {6},
                                           {0, 1, 2, 3, 4, 5});
                         }),
                 TableFileStatus::invalid, "'orders' must be 0, 0.5");
}

TEST(TableIo, SizesFollowFromTheLayoutBeforeAnythingIsAllocated) {
  const TableData data = tiny_table();
  const CurveSet& set = data.sets[0];
  // A small file claiming gigabytes: knot counts at the limit and a knots dataset of those
  // dimensions whose chunks were never written (HDF5 would fill them with zeros).
  const std::string huge = crafted("claims-gigabytes.h5", [&](hid_t file) {
    std::vector<double> counts(set.layout.size(), schema::max_segment_knots);
    replace_dataset(file, "weibull_tail", schema::set_segment_knots, H5T_STD_I32LE, {counts.size()}, counts);
    replace_dataset(file, "weibull_tail", schema::set_knots, H5T_IEEE_F64LE,
                    {set.shapes.size(), hsize_t(order_count), hsize_t(counts.size() * schema::max_segment_knots), 3}, {},
                    true);
  });
  EXPECT_LT(read_bytes(huge).size(), 100000u);
  EXPECT_REFUSED(huge, TableFileStatus::invalid, "more than a table of");
  // 1e6 knots in a segment (passed validation, took 1.3 GB and answered 9.4x wrong)
  EXPECT_REFUSED(crafted("million-knots.h5",
                         [&](hid_t file) {
                           std::vector<double> counts;
                           for (const SegmentSpec& spec : set.layout) counts.push_back(spec.knots);
                           counts.back() = 1e6;
                           replace_dataset(file, "weibull_tail", schema::set_segment_knots, H5T_STD_I32LE,
                                           {counts.size()}, counts);
                         }),
                 TableFileStatus::invalid, "'segment_knots' holds 1000000, outside [2, 65536]");
  // knots of dimensions the layout does not imply
  EXPECT_REFUSED(crafted("knots-shape.h5",
                         [&](hid_t file) {
                           std::vector<hsize_t> dims = knot_dims(set);
                           dims[2] -= 1;
                           replace_dataset(file, "weibull_tail", schema::set_knots, H5T_IEEE_F64LE, dims,
                                           std::vector<double>(dims[0] * dims[1] * dims[2] * dims[3], 0.0));
                         }),
                 TableFileStatus::invalid, "'knots' must be 2 x 6 x");
  // too many segments, shapes of the wrong rank
  EXPECT_REFUSED(crafted("shapes-rank.h5",
                         [&](hid_t file) {
                           replace_dataset(file, "weibull_tail", schema::set_shapes, H5T_IEEE_F64LE, {1, 2},
                                           set.shapes);
                         }),
                 TableFileStatus::invalid, "'shapes' must have 1 dimension");
}

TEST(TableIo, ValuesAreBounded) {
  // H = 1e7 in a knot (asperity contact took 37 s and 2.5 GB, then printed NaN)
  TableData data = tiny_table();
  std::vector<double> knots = knots_of(data);
  knots[40] = 1e7;
  EXPECT_REFUSED(crafted("huge-knot.h5",
                         [&](hid_t file) {
                           replace_dataset(file, "weibull_tail", schema::set_knots, H5T_IEEE_F64LE,
                                           knot_dims(data.sets[0]), knots);
                         }),
                 TableFileStatus::invalid, "knot data holds 1e+07");
  knots[40] = std::nan("");
  EXPECT_REFUSED(crafted("nan-knot.h5",
                         [&](hid_t file) {
                           replace_dataset(file, "weibull_tail", schema::set_knots, H5T_IEEE_F64LE,
                                           knot_dims(data.sets[0]), knots);
                         }),
                 TableFileStatus::invalid, "knot data holds nan");
  EXPECT_REFUSED(crafted("gaussian-shape.h5",
                         [&](hid_t file) {
                           replace_dataset(file, "gaussian_tail", schema::set_shapes, H5T_IEEE_F64LE, {1}, {3.0});
                         }),
                 TableFileStatus::invalid, "the Gaussian set has the one shape 2");
  EXPECT_REFUSED(crafted("tiny-shape.h5",
                         [&](hid_t file) {
                           replace_dataset(file, "weibull_tail", schema::set_shapes, H5T_IEEE_F64LE, {2},
                                           {1e-300, 1.6});
                           replace_dataset(file, "weibull_tail", schema::set_shape_range, H5T_IEEE_F64LE, {2},
                                           {1e-300, 1.6});
                         }),
                 TableFileStatus::invalid, "shapes must lie in");
}

TEST(TableIo, AGroupThatIsNotAGroup) {
  EXPECT_REFUSED(crafted("not-a-group.h5",
                         [](hid_t file) {
                           H5Ldelete(file, "gaussian_tail", H5P_DEFAULT);
                           const hid_t space = simple_space({1});
                           const hid_t set = H5Dcreate2(file, "gaussian_tail", H5T_IEEE_F64LE, space, H5P_DEFAULT,
                                                        H5P_DEFAULT, H5P_DEFAULT);
                           H5Dclose(set);
                           H5Sclose(space);
                         }),
                 TableFileStatus::invalid, "'gaussian_tail' is not a group");
}

// ---- in memory ----

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

// The reader leaves HDF5's error printing as the host program set it.
TEST(TableIo, Hdf5ErrorPrintingIsLeftAsItWas) {
  H5E_auto2_t function = nullptr;
  void* data = nullptr;
  H5Eget_auto2(H5E_DEFAULT, &function, &data);
  ASSERT_NE(function, nullptr);  // HDF5's default: print
  refusal(crafted("for-printing.h5", [](hid_t file) { H5Adelete(file, schema::attr_generator); }));
  H5E_auto2_t after = nullptr;
  H5Eget_auto2(H5E_DEFAULT, &after, &data);
  EXPECT_EQ(after, function);
}

}  // namespace
