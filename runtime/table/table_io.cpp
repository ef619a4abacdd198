// Reading a table file. Every failure becomes an asperity::Error naming the file and what
// is wrong: missing, not HDF5, truncated, another schema, another version, bad contents.
#include <hdf5.h>

#include <fstream>
#include <string>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/table.hpp"
#include "asperity/table_schema.hpp"

namespace asperity {
namespace {

// Closes an HDF5 identifier with the right function when it goes out of scope.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Handle() { if (id_ >= 0) close_(id_); }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  hid_t get() const { return id_; }
  bool ok() const { return id_ >= 0; }
 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

struct Reader {
  std::string path;
  [[noreturn]] void fail(const std::string& what) const { throw Error("table '" + path + "': " + what); }

  std::string string_attribute(hid_t object, const char* name) const {
    if (H5Aexists(object, name) <= 0) fail(std::string("missing attribute '") + name + "'");
    Handle attribute(H5Aopen(object, name, H5P_DEFAULT), H5Aclose);
    Handle type(H5Aget_type(attribute.get()), H5Tclose);
    if (!attribute.ok() || H5Tget_class(type.get()) != H5T_STRING) fail(std::string("attribute '") + name + "' is not a string");
    if (H5Tis_variable_str(type.get()) > 0) {
      Handle memory(H5Tcopy(H5T_C_S1), H5Tclose);
      H5Tset_size(memory.get(), H5T_VARIABLE);
      char* text = nullptr;
      if (H5Aread(attribute.get(), memory.get(), &text) < 0) fail(std::string("cannot read attribute '") + name + "'");
      std::string result = text ? text : "";
      H5free_memory(text);
      return result;
    }
    const std::size_t size = H5Tget_size(type.get());
    std::vector<char> buffer(size + 1, '\0');
    if (H5Aread(attribute.get(), type.get(), buffer.data()) < 0) fail(std::string("cannot read attribute '") + name + "'");
    return std::string(buffer.data());
  }

  long long int_attribute(hid_t object, const char* name) const {
    if (H5Aexists(object, name) <= 0) fail(std::string("missing attribute '") + name + "'");
    Handle attribute(H5Aopen(object, name, H5P_DEFAULT), H5Aclose);
    long long value = 0;
    if (!attribute.ok() || H5Aread(attribute.get(), H5T_NATIVE_LLONG, &value) < 0)
      fail(std::string("cannot read attribute '") + name + "' as an integer");
    return value;
  }

  template <class T>
  std::vector<T> dataset(hid_t group, const char* name, hid_t memory_type, std::vector<hsize_t>& dims) const {
    if (H5Lexists(group, name, H5P_DEFAULT) <= 0) fail(std::string("missing dataset '") + name + "'");
    Handle set(H5Dopen2(group, name, H5P_DEFAULT), H5Dclose);
    if (!set.ok()) fail(std::string("cannot open dataset '") + name + "'");
    Handle space(H5Dget_space(set.get()), H5Sclose);
    const int rank = H5Sget_simple_extent_ndims(space.get());
    if (rank < 1 || rank > 4) fail(std::string("dataset '") + name + "' has an unexpected rank");
    dims.assign(rank, 0);
    H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
    std::size_t count = 1;
    for (hsize_t dim : dims) count *= dim;
    if (count > (std::size_t(1) << 31)) fail(std::string("dataset '") + name + "' is implausibly large");
    std::vector<T> values(count);
    if (count && H5Dread(set.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
      fail(std::string("cannot read dataset '") + name + "' (truncated or corrupt file?)");
    return values;
  }
};

}  // namespace

TableData read_table_file(const std::string& path) {
  Reader reader{path};
  if (!std::ifstream(path).good()) reader.fail("no such file, or it cannot be read");
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors are reported by us, not printed by HDF5
  if (H5Fis_hdf5(path.c_str()) <= 0) reader.fail("not an HDF5 file (or truncated)");
  Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!file.ok()) reader.fail("HDF5 cannot open it (truncated or corrupt?)");

  if (H5Aexists(file.get(), schema::attr_schema) <= 0)
    reader.fail("an HDF5 file, but not an asperity table (no 'schema' attribute)");
  if (reader.string_attribute(file.get(), schema::attr_schema) != schema::name)
    reader.fail("an HDF5 file of another schema");
  const long long version = reader.int_attribute(file.get(), schema::attr_schema_version);
  if (version != schema::version)
    reader.fail("schema version " + std::to_string(version) + ", this runtime reads version " +
                std::to_string(schema::version) + "; regenerate the table with this tablegen");

  TableData data;
  data.generator = reader.string_attribute(file.get(), schema::attr_generator);
  data.generator_options = reader.string_attribute(file.get(), schema::attr_generator_options);
  if (H5Aexists(file.get(), schema::attr_exact_shapes) > 0)
    data.exact_shapes = reader.int_attribute(file.get(), schema::attr_exact_shapes) != 0;
  const struct { Distribution distribution; Side side; } groups[] = {
      {Distribution::weibull, Side::tail}, {Distribution::weibull, Side::bounded}, {Distribution::gaussian, Side::tail}};
  for (const auto& group_id : groups) {
    const std::string name = std::string(to_string(group_id.distribution)) + "_" + to_string(group_id.side);
    if (H5Lexists(file.get(), name.c_str(), H5P_DEFAULT) <= 0) continue;
    Handle group(H5Gopen2(file.get(), name.c_str(), H5P_DEFAULT), H5Gclose);
    if (!group.ok()) reader.fail("cannot open group '" + name + "'");
    CurveSet set;
    set.distribution = group_id.distribution;
    set.side = group_id.side;
    std::vector<hsize_t> dims;
    set.shapes = reader.dataset<double>(group.get(), schema::set_shapes, H5T_NATIVE_DOUBLE, dims);
    const auto range = reader.dataset<double>(group.get(), schema::set_shape_range, H5T_NATIVE_DOUBLE, dims);
    if (range.size() != 2) reader.fail(name + ": shape_range must hold two values");
    set.shape_min = range[0];
    set.shape_max = range[1];
    const auto kinds = reader.dataset<int>(group.get(), schema::set_segment_kind, H5T_NATIVE_INT, dims);
    const auto knot_counts = reader.dataset<int>(group.get(), schema::set_segment_knots, H5T_NATIVE_INT, dims);
    const auto p0 = reader.dataset<double>(group.get(), schema::set_segment_p0, H5T_NATIVE_DOUBLE, dims);
    const auto p1 = reader.dataset<double>(group.get(), schema::set_segment_p1, H5T_NATIVE_DOUBLE, dims);
    if (kinds.size() != knot_counts.size() || kinds.size() != p0.size() || kinds.size() != p1.size())
      reader.fail(name + ": segment datasets differ in length");
    for (std::size_t i = 0; i < kinds.size(); ++i)
      set.layout.push_back({static_cast<SegmentKind>(kinds[i]), knot_counts[i], p0[i], p1[i]});
    set.knots = reader.dataset<double>(group.get(), schema::set_knots, H5T_NATIVE_DOUBLE, dims);
    if (dims.size() != 4 || dims[0] != set.shapes.size() || dims[1] != static_cast<hsize_t>(order_count) || dims[3] != 3)
      reader.fail(name + ": knots dataset has the wrong shape");
    set.max_rel_error = reader.dataset<double>(group.get(), schema::set_max_rel_error, H5T_NATIVE_DOUBLE, dims);
    set.validate("table '" + path + "'");
    data.sets.push_back(std::move(set));
  }
  if (data.sets.empty()) reader.fail("holds no curve sets");
  return data;
}

}  // namespace asperity
