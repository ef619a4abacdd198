// Tables are self-contained (issue 37): every byte a table serves is under its integrity header.
// Each test crafts, with HDF5's C API, a table with a valid header whose HDF5 structure points
// outside the file (an external link, external storage, a virtual dataset, a soft or
// user-defined link, a filter from a plugin library), and checks that it is refused with the
// object named, before HDF5 follows the pointer: the other file's values are never served, and
// a FIFO at the other file's path does not hang the reader (each such open runs in a child
// process that SIGALRM ends after 10 s).
#include <gtest/gtest.h>
#include <hdf5.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#include "asperity/contact_curves.hpp"
#include "asperity/contact_curves_data.hpp"
#include "asperity/table.hpp"
#include "asperity/table_file.hpp"
#include "asperity/detail/table_schema.hpp"
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
void write_bytes(const std::string& path, const std::vector<unsigned char>& bytes) {
  write_bytes(path, std::string(bytes.begin(), bytes.end()));
}

// A tiny table of Greenwood-Williamson integrals (its numbers are not integrals, only bounded).
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

// A tiny contact-curves table: five nodes, pressures 1e6 to 1e8 Pa.
ContactCurvesData tiny_contact_curves() {
  ContactCurvesData data;
  data.generator = "test";
  data.generator_options = "tiny";
  data.source = "exact-contact";
  data.description = "tiny";
  data.separation_datum = "the mean plane";
  data.separation = {1e-7, 2e-7, 3e-7, 4e-7, 5e-7};
  data.pressure = {1e8, 3e7, 1e7, 3e6, 1e6};
  data.stiffness = {1e15, 3e14, 1e14, 3e13, 1e13};
  data.area_fraction = {0.1, 0.04, 0.01, 0.004, 0.001};
  for (int i = 0; i < 3; ++i) {
    data.measured_rel_error[i] = 0.01;
    data.max_rel_error[i] = 0.02;
  }
  data.check_points = 4;
  data.safety_factor = 2;
  data.solver_tolerance = 1e-8;
  data.contact_modulus = 1e11;
  data.nominal_area = 1e-10;
  return data;
}
// What the other file holds instead: every pressure 1000 times as high.
std::vector<double> other_pressures() {
  std::vector<double> pressures = tiny_contact_curves().pressure;
  for (double& p : pressures) p *= 1000;
  return pressures;
}

// Edits a table through HDF5's C API and seals it again: a valid integrity header over the
// edited bytes, so that the file reaches the reader's own checks.
void edit(const std::string& path, const std::function<void(hid_t file)>& change) {
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(file, 0) << path;
  change(file);
  ASSERT_GE(H5Fclose(file), 0);
  std::string bytes = read_bytes(path);
  seal_table_bytes(reinterpret_cast<unsigned char*>(&bytes[0]), bytes.size());
  write_bytes(path, bytes);
}

std::string table_file(const std::string& name) {
  const std::string path = temp_path(name);
  write_bytes(path, table_file_bytes(tiny_table()));
  return path;
}
std::string contact_curves_file(const std::string& name) {
  const std::string path = temp_path(name);
  write_bytes(path, contact_curves_file_bytes(tiny_contact_curves()));
  return path;
}

// A plain HDF5 file (no header: HDF5 reads it directly) holding a copy of the table's `group`.
void copy_group_to(const std::string& table, const char* group, const std::string& other) {
  const hid_t from = H5Fopen(table.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t to = H5Fcreate(other.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(from, 0);
  ASSERT_GE(to, 0);
  EXPECT_GE(H5Ocopy(from, group, to, group, H5P_DEFAULT, H5P_DEFAULT), 0);
  H5Fclose(from);
  H5Fclose(to);
}

void write_doubles(hid_t location, const char* name, const std::vector<double>& values) {
  const hid_t set = H5Dopen2(location, name, H5P_DEFAULT);
  ASSERT_GE(set, 0) << name;
  EXPECT_GE(H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), 0);
  H5Dclose(set);
}

// The table's group replaced by an external link to `group` of file `other`.
void link_group_to(hid_t file, const char* group, const std::string& other) {
  ASSERT_GE(H5Ldelete(file, group, H5P_DEFAULT), 0);
  ASSERT_GE(H5Lcreate_external(other.c_str(), (std::string("/") + group).c_str(), file, group, H5P_DEFAULT,
                               H5P_DEFAULT),
            0);
}

// "contact_curves/pressure" replaced by a dataset of the same size whose properties `configure` sets.
void replace_pressure(hid_t file, const std::function<void(hid_t create)>& configure, bool write = true) {
  const hid_t group = H5Gopen2(file, schema::group_contact_curves, H5P_DEFAULT);
  ASSERT_GE(group, 0);
  ASSERT_GE(H5Ldelete(group, schema::set_pressure, H5P_DEFAULT), 0);
  const hsize_t nodes = tiny_contact_curves().pressure.size();
  const hid_t space = H5Screate_simple(1, &nodes, nullptr);
  const hid_t create = H5Pcreate(H5P_DATASET_CREATE);
  configure(create);
  const hid_t set = H5Dcreate2(group, schema::set_pressure, H5T_IEEE_F64LE, space, H5P_DEFAULT, create, H5P_DEFAULT);
  EXPECT_GE(set, 0);
  if (write) {
    EXPECT_GE(H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, other_pressures().data()), 0);
  }
  H5Dclose(set);
  H5Pclose(create);
  H5Sclose(space);
  H5Gclose(group);
}

// A file whose "/pressure" holds other_pressures(): the source of a virtual dataset.
void write_pressure_source(const std::string& other) {
  const hid_t file = H5Fcreate(other.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  const hsize_t nodes = other_pressures().size();
  const hid_t space = H5Screate_simple(1, &nodes, nullptr);
  const hid_t set = H5Dcreate2(file, "pressure", H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  EXPECT_GE(H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, other_pressures().data()), 0);
  H5Dclose(set);
  H5Sclose(space);
  H5Fclose(file);
}

void map_pressure_from(hid_t create, const std::string& other) {
  const hsize_t nodes = other_pressures().size();
  const hid_t space = H5Screate_simple(1, &nodes, nullptr);
  EXPECT_GE(H5Pset_virtual(create, space, other.c_str(), "/pressure", space), 0);
  H5Sclose(space);
}

// The error an open gives; what was served when it opened.
template <typename Open>
std::string refusal(Open open) {
  try {
    open();
  } catch (const TableFileError& error) {
    EXPECT_EQ(error.status(), TableFileStatus::invalid) << error.what();
    return error.what();
  } catch (const std::exception& error) {
    return std::string("not a TableFileError: ") + error.what();
  }
  return "no error";
}

std::string gw_refusal(const std::string& path) {
  return refusal([&] {
    const Table table = Table::open(path);
    ADD_FAILURE() << path << " opened: the first knot served is " << table.data().sets[0].knots[0];
  });
}
std::string curves_refusal(const std::string& path) {
  return refusal([&] {
    const ContactCurves curves = ContactCurves::open(path);
    ADD_FAILURE() << path << " opened: the pressure served at the first node is " << curves.pressure(1e-7);
  });
}

// (`text` evaluated once: it may be an open)
#define EXPECT_HAS(text, part)                                     \
  do {                                                             \
    const std::string said = (text);                               \
    EXPECT_NE(said.find(part), std::string::npos) << said;         \
  } while (0)

// Runs `open` in a child process that SIGALRM ends after 10 s: the refusal's message, or "hung".
std::string refusal_within_10_seconds(const std::function<std::string()>& open) {
  int channel[2];
  if (pipe(channel) != 0) return "no pipe";
  const pid_t child = fork();
  if (child == 0) {
    close(channel[0]);
    alarm(10);
    const std::string message = open();
    const ssize_t written = write(channel[1], message.data(), message.size());
    _exit(written == static_cast<ssize_t>(message.size()) ? 0 : 1);
  }
  close(channel[1]);
  std::string message;
  char buffer[512];
  for (ssize_t count; (count = read(channel[0], buffer, sizeof buffer)) > 0;) message.append(buffer, count);
  close(channel[0]);
  int status = 0;
  waitpid(child, &status, 0);
  if (WIFSIGNALED(status)) return "hung: ended by signal " + std::to_string(WTERMSIG(status));
  return message;
}

// The file at `path` replaced by a FIFO that no one writes (opening it for reading blocks).
void make_fifo(const std::string& path) {
  std::remove(path.c_str());
  ASSERT_EQ(mkfifo(path.c_str(), 0600), 0) << path;
}

// ---- external links ----

TEST(TableIndirections, AGroupThatIsAnExternalLinkIsRefused) {
  const std::string path = table_file("indirection-gw-external-link.h5");
  const std::string other = temp_path("indirection-gw-external-link-target.h5");
  copy_group_to(path, "weibull_tail", other);
  const hid_t linked = H5Fopen(other.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  const hid_t group = H5Gopen2(linked, "weibull_tail", H5P_DEFAULT);
  write_doubles(group, schema::set_knots, std::vector<double>(tiny_table().sets[0].knots.size(), 0.5));
  H5Gclose(group);
  H5Fclose(linked);
  edit(path, [&](hid_t file) { link_group_to(file, "weibull_tail", other); });
  const std::string message = gw_refusal(path);
  EXPECT_HAS(message, "'weibull_tail' is an external link to object '/weibull_tail' of file '" + other + "'");
  EXPECT_HAS(message, "indirection-gw-external-link.h5");
}

// Also the fixture of the command's test (tests/CMakeLists.txt: cli_contact_table_external_link).
TEST(TableIndirections, ContactCurvesThatAreAnExternalLinkAreRefused) {
  const std::string path = contact_curves_file("indirection-external-link.h5");
  const std::string other = temp_path("indirection-external-link-target.h5");
  copy_group_to(path, schema::group_contact_curves, other);
  const hid_t linked = H5Fopen(other.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  const hid_t group = H5Gopen2(linked, schema::group_contact_curves, H5P_DEFAULT);
  write_doubles(group, schema::set_pressure, other_pressures());
  H5Gclose(group);
  H5Fclose(linked);
  edit(path, [&](hid_t file) { link_group_to(file, schema::group_contact_curves, other); });
  const std::string message = curves_refusal(path);
  EXPECT_HAS(message, "'contact_curves' is an external link to object '/contact_curves'");
  EXPECT_HAS(message, "a table never points into another file");
  // the kind is read through the same check
  EXPECT_HAS(refusal([&] { read_table_kind(path); }), "'contact_curves' is an external link");
}

// ---- datasets whose values are in other files ----

TEST(TableIndirections, ADatasetWithExternalStorageIsRefused) {
  const std::string path = contact_curves_file("indirection-external-storage.h5");
  const std::string other = temp_path("indirection-external-storage.bin");
  std::remove(other.c_str());
  edit(path, [&](hid_t file) {
    replace_pressure(file, [&](hid_t create) { H5Pset_external(create, other.c_str(), 0, H5F_UNLIMITED); });
  });
  EXPECT_GT(read_bytes(other).size(), 0u);  // HDF5 wrote the values there
  const std::string message = curves_refusal(path);
  EXPECT_HAS(message, "'contact_curves/pressure' is a dataset with external storage");
  EXPECT_HAS(message, other);
}

TEST(TableIndirections, AVirtualDatasetIsRefused) {
  const std::string path = contact_curves_file("indirection-virtual.h5");
  const std::string other = temp_path("indirection-virtual-source.h5");
  write_pressure_source(other);
  edit(path, [&](hid_t file) {
    replace_pressure(file, [&](hid_t create) { map_pressure_from(create, other); }, false);
  });
  EXPECT_HAS(curves_refusal(path), "'contact_curves/pressure' is a virtual dataset");
}

// An unregistered filter, its chunk written as if filtered: reading it makes HDF5 search its
// plugin directories and load shared libraries from them.
void filter_pressure_by_plugin(hid_t file) {
  replace_pressure(
      file,
      [](hid_t create) {
        const hsize_t chunk = 5;
        H5Pset_chunk(create, 1, &chunk);
        H5Pset_filter(create, 32004, H5Z_FLAG_OPTIONAL, 0, nullptr);  // LZ4's registered number
      },
      false);
  const hid_t set = H5Dopen2(file, "contact_curves/pressure", H5P_DEFAULT);
  const std::vector<double> pressures = other_pressures();
  const hsize_t offset = 0;
  EXPECT_GE(H5Dwrite_chunk(set, H5P_DEFAULT, 0, &offset, pressures.size() * sizeof(double), pressures.data()), 0);
  H5Dclose(set);
}

TEST(TableIndirections, AFilterFromAPluginIsRefused) {
  const std::string path = contact_curves_file("indirection-plugin-filter.h5");
  edit(path, filter_pressure_by_plugin);
  EXPECT_HAS(curves_refusal(path), "'contact_curves/pressure' is a dataset compressed by filter 32004");
}

// ---- links inside the file: tables hold none ----

TEST(TableIndirections, SoftLinksAreRefused) {
  const std::string path = table_file("indirection-soft-link.h5");
  edit(path, [](hid_t file) {
    ASSERT_GE(H5Lmove(file, "weibull_tail", file, "hidden", H5P_DEFAULT, H5P_DEFAULT), 0);
    ASSERT_GE(H5Lcreate_soft("/hidden", file, "weibull_tail", H5P_DEFAULT, H5P_DEFAULT), 0);
  });
  EXPECT_HAS(gw_refusal(path), "'weibull_tail' is a soft link to '/hidden' (a table holds none)");
  const std::string dangling = table_file("indirection-dangling-soft-link.h5");
  edit(dangling, [](hid_t file) {
    ASSERT_GE(H5Ldelete(file, "gaussian_tail/knots", H5P_DEFAULT), 0);
    ASSERT_GE(H5Lcreate_soft("/nowhere/knots", file, "gaussian_tail/knots", H5P_DEFAULT, H5P_DEFAULT), 0);
  });
  EXPECT_HAS(gw_refusal(dangling), "'gaussian_tail/knots' is a soft link to '/nowhere/knots'");
}

// A user-defined link class that opens an object of the same file by its path: registered in
// this process, so HDF5 would traverse it.
hid_t open_by_path(const char*, hid_t group, const void* path, std::size_t, hid_t access, hid_t) {
  return H5Oopen(group, static_cast<const char*>(path), access);
}

TEST(TableIndirections, UserDefinedLinksAreRefused) {
  const auto type = static_cast<H5L_type_t>(H5L_TYPE_UD_MIN + 37);
  const H5L_class_t by_path = {H5L_LINK_CLASS_T_VERS, type, "by path", nullptr, nullptr, nullptr, open_by_path,
                               nullptr, nullptr};
  ASSERT_GE(H5Lregister(&by_path), 0);
  const std::string path = table_file("indirection-user-defined-link.h5");
  edit(path, [&](hid_t file) {
    ASSERT_GE(H5Lmove(file, "weibull_tail", file, "hidden", H5P_DEFAULT, H5P_DEFAULT), 0);
    ASSERT_GE(H5Lcreate_ud(file, "weibull_tail", type, "/hidden", 8, H5P_DEFAULT, H5P_DEFAULT), 0);
  });
  EXPECT_HAS(gw_refusal(path), "'weibull_tail' is a user-defined link (class 101)");
  H5Lunregister(type);
}

// ---- a FIFO where the other file was: refused, not waited on ----

TEST(TableIndirections, AFifoAtTheOtherPathDoesNotHang) {
  // an external link
  const std::string linked = contact_curves_file("indirection-fifo-link.h5");
  const std::string link_target = temp_path("indirection-fifo-link-target.h5");
  copy_group_to(linked, schema::group_contact_curves, link_target);
  edit(linked, [&](hid_t file) { link_group_to(file, schema::group_contact_curves, link_target); });
  make_fifo(link_target);
  EXPECT_HAS(refusal_within_10_seconds([&] { return curves_refusal(linked); }), "'contact_curves' is an external link");
  EXPECT_HAS(refusal_within_10_seconds([&] { return refusal([&] { read_table_kind(linked); }); }),
             "'contact_curves' is an external link");
  // external storage
  const std::string stored = contact_curves_file("indirection-fifo-storage.h5");
  const std::string storage = temp_path("indirection-fifo-storage.bin");
  std::remove(storage.c_str());
  edit(stored, [&](hid_t file) {
    replace_pressure(file, [&](hid_t create) { H5Pset_external(create, storage.c_str(), 0, H5F_UNLIMITED); });
  });
  make_fifo(storage);
  EXPECT_HAS(refusal_within_10_seconds([&] { return curves_refusal(stored); }),
             "'contact_curves/pressure' is a dataset with external storage");
  // a virtual dataset's source
  const std::string mapped = contact_curves_file("indirection-fifo-virtual.h5");
  const std::string source = temp_path("indirection-fifo-virtual-source.h5");
  write_pressure_source(source);
  edit(mapped, [&](hid_t file) {
    replace_pressure(file, [&](hid_t create) { map_pressure_from(create, source); }, false);
  });
  make_fifo(source);
  EXPECT_HAS(refusal_within_10_seconds([&] { return curves_refusal(mapped); }),
             "'contact_curves/pressure' is a virtual dataset");
  // a filter's plugin: a FIFO named as a library in a plugin directory
  const std::string filtered = contact_curves_file("indirection-fifo-plugin.h5");
  edit(filtered, filter_pressure_by_plugin);
  const std::string plugins = temp_path("indirection-plugins");
  mkdir(plugins.c_str(), 0700);
  make_fifo(plugins + "/libfifo.so");
  EXPECT_HAS(refusal_within_10_seconds([&] {
               H5PLprepend(plugins.c_str());  // in the child only
               return curves_refusal(filtered);
             }),
             "'contact_curves/pressure' is a dataset compressed by filter 32004");
  for (const std::string& fifo : {link_target, storage, source, plugins + "/libfifo.so"}) std::remove(fifo.c_str());
}

// The walk's work is bounded: a small file of many empty groups is refused at the limit.
TEST(TableIndirections, MoreLinksThanATableHoldsAreRefused) {
  const std::string path = table_file("indirection-many-links.h5");
  edit(path, [](hid_t file) {
    const hid_t group = H5Gcreate2(file, "many", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    for (int i = 0; i < 10000; ++i)
      H5Gclose(H5Gcreate2(group, std::to_string(i).c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    H5Gclose(group);
  });
  EXPECT_HAS(gw_refusal(path), "is link 10001, more than a table holds (10000)");
}

// ---- what is refused, is refused whatever reads it ----

TEST(TableIndirections, TheBytesReaderRefusesThemToo) {
  const std::string path = table_file("indirection-bytes.h5");
  edit(path, [](hid_t file) {
    ASSERT_GE(H5Lmove(file, "gaussian_tail", file, "hidden", H5P_DEFAULT, H5P_DEFAULT), 0);
    ASSERT_GE(H5Lcreate_soft("/hidden", file, "gaussian_tail", H5P_DEFAULT, H5P_DEFAULT), 0);
  });
  const std::string bytes = read_bytes(path);
  EXPECT_HAS(refusal([&] { read_table_bytes(bytes.data(), bytes.size(), "memory"); }),
             "table 'memory': 'gaussian_tail' is a soft link");
  // and a table without any of them still opens
  EXPECT_NO_THROW(Table::open(table_file("indirection-none.h5")));
  EXPECT_NO_THROW(ContactCurves::open(contact_curves_file("indirection-none-curves.h5")));
}

}  // namespace
