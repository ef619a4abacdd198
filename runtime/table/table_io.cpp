// Reading a table file. The whole file is read with plain reads (regular_file.hpp: a FIFO,
// directory or device is refused before a byte is read), its integrity header checked (table_file.hpp), and only
// the checked bytes are given to HDF5, from memory. Anything in them that would make HDF5 read
// another file (an external link, external storage, ...: hdf5_confinement.hpp) is refused
// before any of it is read, and every object is opened through access lists that forbid it
// too. Then every object is checked before it is read: each attribute scalar and of its type
// class, each dataset of its exact datatype and of the dimensions the segment layout implies,
// every size bounded before anything is allocated.
// Every failure is a TableFileError naming the file, with its status.
#include <hdf5.h>

#include <cstring>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "asperity/contact_curves_data.hpp"
#include "asperity/error.hpp"
#include "asperity/table.hpp"
#include "asperity/table_file.hpp"
#include "asperity/detail/table_schema.hpp"
#include "hdf5_confinement.hpp"
#include "hdf5_handle.hpp"
#include "asperity/detail/regular_file.hpp"
#include "asperity/detail/segment_kind.hpp"

namespace asperity {
namespace {

using detail::Hdf5Handle;

// Debian's HDF5 is built without its thread-safety option: one table is read at a time.
std::mutex& hdf5_mutex() {
  static std::mutex mutex;
  return mutex;
}

[[noreturn]] void fail(TableFileStatus status, const std::string& name, const std::string& what) {
  throw TableFileError(status, "table '" + name + "': " + what);
}

// Reads one verified HDF5 file image; every method checks before it reads. Its objects are
// opened through the confined access lists (hdf5_confinement.hpp).
class Reader {
 public:
  Reader(std::string name, const detail::ConfinedAccess& access) : name_(std::move(name)), access_(&access) {}
  [[noreturn]] void invalid(const std::string& what) const { fail(TableFileStatus::invalid, name_, what); }
  // The same image, its errors naming a group: "table 'x' group 'y'".
  Reader in_group(const std::string& group) const { return Reader(name_ + "' group '" + group, *access_); }

  bool has_link(hid_t group, const char* name) const { return H5Lexists(group, name, access_->datasets.get()) > 0; }

  Hdf5Handle open_group(hid_t file, const char* name) const {
    Hdf5Handle group = detail::hdf5_group(H5Gopen2(file, name, access_->groups.get()));
    if (!group.ok()) invalid(std::string("'") + name + "' is not a group");
    return group;
  }

  std::optional<std::string> text_attribute(hid_t object, const char* name, bool required) const {
    const Hdf5Handle attribute = open_scalar_attribute(object, name, required);
    if (!attribute.ok()) return std::nullopt;
    const Hdf5Handle type = detail::hdf5_type(H5Aget_type(attribute.get()));
    if (!type.ok() || H5Tget_class(type.get()) != H5T_STRING) invalid(std::string("attribute '") + name + "' is not text");
    const H5T_cset_t charset = H5Tget_cset(type.get());  // ASCII, or UTF-8 (h5py's default)
    if (charset != H5T_CSET_ASCII && charset != H5T_CSET_UTF8)
      invalid(std::string("attribute '") + name + "' has an unknown character set");
    const Hdf5Handle memory = detail::hdf5_type(H5Tcopy(H5T_C_S1));
    if (!memory.ok() || H5Tset_cset(memory.get(), charset) < 0) invalid("HDF5 cannot make a string type");
    std::string result;
    if (H5Tis_variable_str(type.get()) > 0) {
      char* text = nullptr;
      if (H5Tset_size(memory.get(), H5T_VARIABLE) < 0 || H5Aread(attribute.get(), memory.get(), &text) < 0)
        invalid(std::string("cannot read attribute '") + name + "'");
      const std::size_t length = text ? strnlen(text, schema::max_text_bytes + 1) : 0;
      if (length <= schema::max_text_bytes) result.assign(text ? text : "", length);
      H5free_memory(text);
      if (length > schema::max_text_bytes) invalid(std::string("attribute '") + name + "' is too long");
      return result;
    }
    const std::size_t size = H5Tget_size(type.get());
    if (size == 0 || size > schema::max_text_bytes) invalid(std::string("attribute '") + name + "' is too long");
    // One byte more than stored, null-terminated: a string that fills its size keeps its last character.
    std::vector<char> buffer(size + 1, '\0');
    if (H5Tset_size(memory.get(), size + 1) < 0 || H5Tset_strpad(memory.get(), H5T_STR_NULLTERM) < 0 ||
        H5Aread(attribute.get(), memory.get(), buffer.data()) < 0)
      invalid(std::string("cannot read attribute '") + name + "'");
    return std::string(buffer.data(), strnlen(buffer.data(), size));
  }

  std::optional<long long> integer_attribute(hid_t object, const char* name, bool required) const {
    const Hdf5Handle attribute = open_scalar_attribute(object, name, required);
    if (!attribute.ok()) return std::nullopt;
    const Hdf5Handle type = detail::hdf5_type(H5Aget_type(attribute.get()));
    if (!type.ok() || H5Tget_class(type.get()) != H5T_INTEGER)
      invalid(std::string("attribute '") + name + "' is not an integer");
    long long value = 0;
    if (H5Aread(attribute.get(), H5T_NATIVE_LLONG, &value) < 0)
      invalid(std::string("cannot read attribute '") + name + "'");
    return value;
  }

  // A dataset's dimensions (rank checked), before anything is read.
  std::vector<hsize_t> dimensions(const Hdf5Handle& set, const char* name, int rank) const {
    const Hdf5Handle space = detail::hdf5_space(H5Dget_space(set.get()));
    if (!space.ok() || H5Sget_simple_extent_type(space.get()) != H5S_SIMPLE ||
        H5Sget_simple_extent_ndims(space.get()) != rank)
      invalid(std::string("dataset '") + name + "' must have " + std::to_string(rank) + " dimension" +
              (rank > 1 ? "s" : ""));
    std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
    if (H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr) != rank)
      invalid(std::string("cannot read the dimensions of dataset '") + name + "'");
    return dims;
  }

  Hdf5Handle open_dataset(hid_t group, const char* name) const {
    if (!has_link(group, name)) invalid(std::string("missing dataset '") + name + "'");
    Hdf5Handle set = detail::hdf5_dataset(H5Dopen2(group, name, access_->datasets.get()));
    if (!set.ok()) invalid(std::string("'") + name + "' is not a dataset");
    return set;
  }

  // 64-bit IEEE floats of exactly the expected dimensions.
  std::vector<double> doubles(hid_t group, const char* name, const std::vector<hsize_t>& expected) const {
    const Hdf5Handle set = open_dataset(group, name);
    check_dimensions(set, name, expected);
    const Hdf5Handle type = detail::hdf5_type(H5Dget_type(set.get()));
    if (!type.ok() || H5Tget_class(type.get()) != H5T_FLOAT ||
        !(H5Tequal(type.get(), H5T_IEEE_F64LE) > 0 || H5Tequal(type.get(), H5T_IEEE_F64BE) > 0))
      invalid(std::string("dataset '") + name + "' must hold 64-bit IEEE floats (" + describe(type.get()) + ")");
    std::vector<double> values(count_of(expected));
    if (!values.empty() && H5Dread(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
      invalid(std::string("cannot read dataset '") + name + "'");
    return values;
  }

  // Integers of exactly the expected dimensions, each in [lo, hi].
  std::vector<long long> integers(hid_t group, const char* name, const std::vector<hsize_t>& expected, long long lo,
                                  long long hi) const {
    const Hdf5Handle set = open_dataset(group, name);
    check_dimensions(set, name, expected);
    const Hdf5Handle type = detail::hdf5_type(H5Dget_type(set.get()));
    if (!type.ok() || H5Tget_class(type.get()) != H5T_INTEGER)
      invalid(std::string("dataset '") + name + "' must hold integers (" + describe(type.get()) + ")");
    std::vector<long long> values(count_of(expected));
    if (!values.empty() && H5Dread(set.get(), H5T_NATIVE_LLONG, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
      invalid(std::string("cannot read dataset '") + name + "'");
    for (long long value : values)
      if (value < lo || value > hi)
        invalid(std::string("dataset '") + name + "' holds " + std::to_string(value) + ", outside [" +
                std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return values;
  }

  // The length of a one-dimensional dataset, in [1, most].
  std::size_t length(hid_t group, const char* name, std::size_t most) const {
    const Hdf5Handle set = open_dataset(group, name);
    const hsize_t count = dimensions(set, name, 1)[0];
    if (count < 1 || count > most)
      invalid(std::string("dataset '") + name + "' has " + std::to_string(count) + " entries, expected 1 to " +
              std::to_string(most));
    return static_cast<std::size_t>(count);
  }

 private:
  Hdf5Handle open_scalar_attribute(hid_t object, const char* name, bool required) const {
    if (H5Aexists(object, name) <= 0) {
      if (required) invalid(std::string("missing attribute '") + name + "'");
      return {};
    }
    Hdf5Handle attribute = detail::hdf5_attribute(H5Aopen(object, name, H5P_DEFAULT));
    if (!attribute.ok()) invalid(std::string("cannot open attribute '") + name + "'");
    const Hdf5Handle space = detail::hdf5_space(H5Aget_space(attribute.get()));
    if (!space.ok() || H5Sget_simple_extent_type(space.get()) != H5S_SCALAR)
      invalid(std::string("attribute '") + name + "' must hold one value, not an array");
    return attribute;
  }

  void check_dimensions(const Hdf5Handle& set, const char* name, const std::vector<hsize_t>& expected) const {
    if (dimensions(set, name, static_cast<int>(expected.size())) != expected) {
      std::string text;
      for (hsize_t dim : expected) text += (text.empty() ? "" : " x ") + std::to_string(dim);
      invalid(std::string("dataset '") + name + "' must be " + text + " (from the segment layout)");
    }
  }

  static std::size_t count_of(const std::vector<hsize_t>& dims) {
    std::size_t count = 1;
    for (hsize_t dim : dims) count *= static_cast<std::size_t>(dim);  // bounded by the callers
    return count;
  }

  static std::string describe(hid_t type) {
    if (type < 0) return "unreadable type";
    const std::string bits = std::to_string(8 * H5Tget_size(type)) + "-bit ";
    switch (H5Tget_class(type)) {
      case H5T_INTEGER: return bits + "integers";
      case H5T_FLOAT: return bits + "floats";
      case H5T_STRING: return "text";
      default: return "another type";
    }
  }

  std::string name_;
  const detail::ConfinedAccess* access_;
};

// A checked table open in HDF5, and the access lists its objects are opened through.
struct OpenImage {
  detail::ConfinedAccess access;
  Hdf5Handle file;
};

// HDF5's core driver on a copy of the checked bytes (the caller holds hdf5_mutex()); the name
// only identifies the image (it must not be an existing file, and must differ between images
// open at once). Every reader opens its table here: a file that points outside itself is
// refused here, before any of it is read.
OpenImage open_image(const unsigned char* bytes, std::size_t size, const std::string& name) {
  static unsigned long images = 0;
  const std::string image_name = "/dev/null/asperity-table-image-" + std::to_string(++images);
  std::optional<detail::ConfinedAccess> access = detail::confined_access();
  if (!access) fail(TableFileStatus::invalid, name, "HDF5 cannot make its access properties");
  OpenImage image{std::move(*access), {}};
  {
    const Hdf5Handle file_access = detail::hdf5_properties(H5Pcreate(H5P_FILE_ACCESS));
    if (!file_access.ok() || H5Pset_fapl_core(file_access.get(), 1 << 20, false) < 0 ||
        H5Pset_file_image(file_access.get(), const_cast<unsigned char*>(bytes), size) < 0)
      fail(TableFileStatus::invalid, name, "HDF5 cannot take the file image");
    image.file = detail::hdf5_file(H5Fopen(image_name.c_str(), H5F_ACC_RDONLY, file_access.get()));
  }
  if (!image.file.ok()) fail(TableFileStatus::invalid, name, "its header is intact but HDF5 cannot open what follows");
  if (const std::optional<std::string> indirection =
          detail::find_indirection(image.file.get(), image.access.datasets.get()))
    fail(TableFileStatus::invalid, name,
         *indirection + ": a table is one self-contained file (its integrity header covers only its own bytes), "
                        "refused before HDF5 follows it");
  return image;
}

// The schema, its version and the table's kind, from the root attributes.
TableKind read_kind(hid_t file, const Reader& reader, const std::string& name) {
  const std::optional<std::string> schema_name = reader.text_attribute(file, schema::attr_schema, false);
  if (!schema_name) fail(TableFileStatus::other_schema, name, "an HDF5 file, but not an asperity table (no 'schema')");
  if (*schema_name != schema::name) fail(TableFileStatus::other_schema, name, "an HDF5 file of another schema");
  const long long version = *reader.integer_attribute(file, schema::attr_schema_version, true);
  if (version != schema::version)
    fail(TableFileStatus::other_version, name,
         "schema version " + std::to_string(version) + ", this runtime reads version " +
             std::to_string(schema::version) + "; regenerate the table with this tablegen");
  const std::optional<std::string> kind = reader.text_attribute(file, schema::attr_kind, false);
  if (!kind || *kind == schema::kind_integrals) return TableKind::integrals;
  if (*kind == schema::kind_contact_curves) return TableKind::contact_curves;
  reader.invalid("an asperity table of an unknown kind '" + kind->substr(0, 40) + "'");
}

[[noreturn]] void wrong_kind(const std::string& name, TableKind kind) {
  fail(TableFileStatus::other_schema, name,
       kind == TableKind::contact_curves
           ? "a table of contact curves against separation (a measured surface's: it is served by ContactCurves, "
             "asperity_contact_curves_load, and asperity contact --table FILE without a surface), not of "
             "Greenwood-Williamson integrals"
           : "a table of Greenwood-Williamson integrals, not of contact curves against separation");
}

TableData read_verified(const unsigned char* bytes, std::size_t size, const std::string& name) {
  std::lock_guard<std::mutex> lock(hdf5_mutex());
  const detail::QuietHdf5Errors quiet;
  const OpenImage image = open_image(bytes, size, name);
  const Hdf5Handle& file = image.file;
  const Reader reader(name, image.access);
  const TableKind kind = read_kind(file.get(), reader, name);
  if (kind != TableKind::integrals) wrong_kind(name, kind);

  TableData data;
  data.generator = *reader.text_attribute(file.get(), schema::attr_generator, true);
  data.generator_options = *reader.text_attribute(file.get(), schema::attr_generator_options, true);
  if (const auto exact = reader.integer_attribute(file.get(), schema::attr_exact_shapes, false)) {
    if (*exact != 0 && *exact != 1) reader.invalid("attribute 'exact_shapes' must be 0 or 1");
    data.exact_shapes = *exact == 1;
  }
  const struct { Distribution distribution; Side side; } groups[] = {
      {Distribution::weibull, Side::tail}, {Distribution::weibull, Side::bounded}, {Distribution::gaussian, Side::tail}};
  double values_in_memory = 0;
  for (const auto& group_id : groups) {
    const std::string group_name = std::string(to_string(group_id.distribution)) + "_" + to_string(group_id.side);
    if (!reader.has_link(file.get(), group_name.c_str())) continue;
    const Hdf5Handle group = reader.open_group(file.get(), group_name.c_str());
    const Reader in_group = reader.in_group(group_name);
    const hid_t g = group.get();
    CurveSet set;
    set.distribution = group_id.distribution;
    set.side = group_id.side;
    const hsize_t shapes = in_group.length(g, schema::set_shapes, schema::max_shapes);
    set.shapes = in_group.doubles(g, schema::set_shapes, {shapes});
    const std::vector<double> range = in_group.doubles(g, schema::set_shape_range, {2});
    set.shape_min = range[0];
    set.shape_max = range[1];
    const std::vector<double> orders = in_group.doubles(g, schema::set_orders, {hsize_t(order_count)});
    for (int k = 0; k < order_count; ++k)
      if (orders[k] != order_of(k)) in_group.invalid("dataset 'orders' must be 0, 0.5, 1, 1.5, 2, 2.5");
    const hsize_t segments = in_group.length(g, schema::set_segment_kind, max_segments);
    const auto kinds = in_group.integers(g, schema::set_segment_kind, {segments}, 0, detail::segment_kind_count - 1);
    const auto knots = in_group.integers(g, schema::set_segment_knots, {segments}, 2, schema::max_segment_knots);
    const std::vector<double> p0 = in_group.doubles(g, schema::set_segment_p0, {segments});
    const std::vector<double> p1 = in_group.doubles(g, schema::set_segment_p1, {segments});
    hsize_t total_knots = 0;
    for (std::size_t i = 0; i < segments; ++i) {
      set.layout.push_back({static_cast<SegmentKind>(kinds[i]), static_cast<int>(knots[i]), p0[i], p1[i]});
      total_knots += static_cast<hsize_t>(knots[i]);
    }
    // The knot data's size follows from the layout: bounded, and in proportion to the file,
    // before a byte of it is allocated (a small file cannot claim gigabytes of zeros).
    const double values = static_cast<double>(shapes) * order_count * static_cast<double>(total_knots) * 3;
    values_in_memory += values;
    if (values > static_cast<double>(schema::max_set_values) ||
        values_in_memory * sizeof(double) > schema::max_expansion * static_cast<double>(size))
      in_group.invalid("its layout implies " + std::to_string(static_cast<long long>(values)) +
                       " knot values, more than a table of " + std::to_string(size) + " bytes may hold");
    set.knots = in_group.doubles(g, schema::set_knots, {shapes, hsize_t(order_count), total_knots, 3});
    set.max_rel_error = in_group.doubles(g, schema::set_max_rel_error, {shapes, hsize_t(order_count)});
    // optional, together (scene tables): the lookup grid's tolerance and range per curve
    if (in_group.has_link(g, schema::set_grid_tolerance) || in_group.has_link(g, schema::set_grid_separations)) {
      set.grid_tolerance = in_group.doubles(g, schema::set_grid_tolerance, {shapes});
      set.grid_separations = in_group.doubles(g, schema::set_grid_separations, {shapes, 2});
    }
    set.validate("table '" + name + "'");
    data.sets.push_back(std::move(set));
  }
  if (data.sets.empty()) reader.invalid("holds no curve sets");
  return data;
}

// One float of a [1] dataset.
double scalar(const Reader& reader, hid_t group, const char* name) {
  return reader.doubles(group, name, {1})[0];
}

ContactCurvesData read_contact_curves_verified(const unsigned char* bytes, std::size_t size, const std::string& name) {
  std::lock_guard<std::mutex> lock(hdf5_mutex());
  const detail::QuietHdf5Errors quiet;
  const OpenImage image = open_image(bytes, size, name);
  const Hdf5Handle& file = image.file;
  const Reader reader(name, image.access);
  const TableKind kind = read_kind(file.get(), reader, name);
  if (kind != TableKind::contact_curves) wrong_kind(name, kind);
  ContactCurvesData data;
  data.generator = *reader.text_attribute(file.get(), schema::attr_generator, true);
  data.generator_options = *reader.text_attribute(file.get(), schema::attr_generator_options, true);
  if (!reader.has_link(file.get(), schema::group_contact_curves))
    reader.invalid(std::string("missing group '") + schema::group_contact_curves + "'");
  const Hdf5Handle group = reader.open_group(file.get(), schema::group_contact_curves);
  const Reader in_group = reader.in_group(schema::group_contact_curves);
  const hid_t g = group.get();
  data.source = *in_group.text_attribute(g, schema::attr_source, true);
  data.description = *in_group.text_attribute(g, schema::attr_description, true);
  data.separation_datum = *in_group.text_attribute(g, schema::attr_separation_datum, true);
  const hsize_t nodes = in_group.length(g, schema::set_separation, schema::max_contact_curve_nodes);
  // up to seven values a node, bounded against the file's size before they are read
  if (7.0 * static_cast<double>(nodes) * sizeof(double) > schema::max_expansion * static_cast<double>(size))
    in_group.invalid("it claims " + std::to_string(nodes) + " nodes, more than a table of " + std::to_string(size) +
                     " bytes may hold");
  data.separation = in_group.doubles(g, schema::set_separation, {nodes});
  data.pressure = in_group.doubles(g, schema::set_pressure, {nodes});
  data.stiffness = in_group.doubles(g, schema::set_stiffness, {nodes});
  data.area_fraction = in_group.doubles(g, schema::set_area_fraction, {nodes});
  const std::vector<double> bound = in_group.doubles(g, schema::set_max_rel_error, {3});
  const std::vector<double> measured = in_group.doubles(g, schema::set_measured_rel_error, {3});
  for (int i = 0; i < 3; ++i) {
    data.max_rel_error[i] = bound[i];
    data.measured_rel_error[i] = measured[i];
  }
  data.check_points = static_cast<int>(in_group.integers(g, schema::set_check_points, {1}, 0, 1 << 30)[0]);
  // how the bound was measured: absent in tables written before it (unstated, still served)
  if (const std::optional<std::string> method = in_group.text_attribute(g, schema::attr_bound_method, false))
    if (!parse_contact_bound_method(*method, data.bound_method))
      fail(TableFileStatus::other_version, name,
           std::string("its bound was measured by a method this runtime does not know ('") + schema::attr_bound_method +
               "' = '" + method->substr(0, 40) + "'): a table from a newer asperity; update asperity to serve it");
  data.safety_factor = scalar(in_group, g, schema::set_safety_factor);
  data.solver_tolerance = scalar(in_group, g, schema::set_solver_tolerance);
  data.contact_modulus = scalar(in_group, g, schema::set_contact_modulus);
  data.nominal_area = scalar(in_group, g, schema::set_nominal_area);
  if (in_group.has_link(g, schema::set_mean_summit_height))
    data.mean_summit_height = scalar(in_group, g, schema::set_mean_summit_height);
  if (in_group.has_link(g, schema::set_max_height))
    data.max_height = scalar(in_group, g, schema::set_max_height);
  const bool tensile = in_group.has_link(g, schema::set_tensile_pressure);
  if (tensile != in_group.has_link(g, schema::set_tensile_stiffness))
    in_group.invalid(std::string("'") + schema::set_tensile_pressure + "' and '" + schema::set_tensile_stiffness +
                     "' come together (both or neither)");
  if (tensile) {
    data.tensile_pressure = in_group.doubles(g, schema::set_tensile_pressure, {nodes});
    data.tensile_stiffness = in_group.doubles(g, schema::set_tensile_stiffness, {nodes});
  }
  if (in_group.has_link(g, schema::set_summit_count)) {
    data.summit_count = in_group.doubles(g, schema::set_summit_count, {nodes});
    data.summit_count_max_rel_error = scalar(in_group, g, schema::set_summit_count_max_rel_error);
  }
  if (in_group.has_link(g, schema::set_approach_separation))
    data.approach_separation = scalar(in_group, g, schema::set_approach_separation);
  data.validate("table '" + name + "'");
  return data;
}

}  // namespace

const char* to_string(TableKind kind) noexcept {
  return kind == TableKind::contact_curves ? schema::kind_contact_curves : schema::kind_integrals;
}

TableData read_table_bytes(const void* bytes, std::size_t size, const std::string& name) {
  const auto* data = static_cast<const unsigned char*>(bytes);
  if (size > schema::max_file_bytes)
    fail(TableFileStatus::invalid, name, "more bytes than a table may have (" + std::to_string(schema::max_file_bytes) + ")");
  verify_table_bytes(data, size, name);
  try {
    return read_verified(data, size, name);
  } catch (const TableFileError&) {
    throw;
  } catch (const Error& error) {  // CurveSet::validate: the contents break the schema
    throw TableFileError(TableFileStatus::invalid, error.what());
  }
}

namespace {

std::string read_file_bytes(const std::string& path) {
  try {
    return detail::read_regular_file(path, schema::max_file_bytes);
  } catch (const detail::RegularFileError& error) {
    const TableFileStatus status = error.failure() == detail::FileFailure::missing ? TableFileStatus::missing
                                   : error.failure() == detail::FileFailure::too_large ? TableFileStatus::invalid
                                                                                       : TableFileStatus::unreadable;
    fail(status, path, error.what());
  }
}

}  // namespace

TableData read_table_file(const std::string& path) {
  const std::string bytes = read_file_bytes(path);
  return read_table_bytes(bytes.data(), bytes.size(), path);
}

ContactCurvesData read_contact_curves_bytes(const void* bytes, std::size_t size, const std::string& name) {
  const auto* data = static_cast<const unsigned char*>(bytes);
  if (size > schema::max_file_bytes)
    fail(TableFileStatus::invalid, name, "more bytes than a table may have (" + std::to_string(schema::max_file_bytes) + ")");
  verify_table_bytes(data, size, name);
  try {
    return read_contact_curves_verified(data, size, name);
  } catch (const TableFileError&) {
    throw;
  } catch (const Error& error) {  // ContactCurvesData::validate: the contents break the schema
    throw TableFileError(TableFileStatus::invalid, error.what());
  }
}

ContactCurvesData read_contact_curves_file(const std::string& path) {
  const std::string bytes = read_file_bytes(path);
  return read_contact_curves_bytes(bytes.data(), bytes.size(), path);
}

TableKind read_table_kind(const std::string& path) {
  const std::string bytes = read_file_bytes(path);
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  verify_table_bytes(data, bytes.size(), path);
  std::lock_guard<std::mutex> lock(hdf5_mutex());
  const detail::QuietHdf5Errors quiet;
  const OpenImage image = open_image(data, bytes.size(), path);
  return read_kind(image.file.get(), Reader(path, image.access), path);
}

}  // namespace asperity
