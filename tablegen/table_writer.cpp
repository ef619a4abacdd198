#include "table_writer.hpp"

#include <hdf5.h>
#include <unistd.h>

#include <cstdio>
#include <string>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/table_schema.hpp"

namespace asperity::tablegen {
namespace {

void check(herr_t status, const std::string& what) {
  if (status < 0) throw Error("writing the table failed: " + what);
}
hid_t check_id(hid_t id, const std::string& what) {
  if (id < 0) throw Error("writing the table failed: " + what);
  return id;
}

void write_string_attribute(hid_t object, const char* name, const std::string& text) {
  const hid_t type = check_id(H5Tcopy(H5T_C_S1), name);
  H5Tset_size(type, text.size() + 1);
  H5Tset_strpad(type, H5T_STR_NULLTERM);
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attribute = check_id(H5Acreate2(object, name, type, space, H5P_DEFAULT, H5P_DEFAULT), name);
  check(H5Awrite(attribute, type, text.c_str()), name);
  H5Aclose(attribute);
  H5Sclose(space);
  H5Tclose(type);
}

void write_int_attribute(hid_t object, const char* name, int value) {
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attribute = check_id(H5Acreate2(object, name, H5T_STD_I32LE, space, H5P_DEFAULT, H5P_DEFAULT), name);
  check(H5Awrite(attribute, H5T_NATIVE_INT, &value), name);
  H5Aclose(attribute);
  H5Sclose(space);
}

template <class T>
void write_dataset(hid_t group, const char* name, hid_t file_type, hid_t memory_type,
                   const std::vector<hsize_t>& dims, const T* values) {
  const hid_t space = check_id(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), name);
  const hid_t properties = H5Pcreate(H5P_DATASET_CREATE);
  H5Pset_obj_track_times(properties, false);  // no timestamps: same data, same bytes
  if (dims.size() == 4) {  // the knots: one chunk per shape, byte-shuffled and deflated
    const hsize_t chunk[4] = {1, dims[1], dims[2], dims[3]};
    H5Pset_chunk(properties, 4, chunk);
    H5Pset_shuffle(properties);
    H5Pset_deflate(properties, 6);
  }
  const hid_t set = check_id(H5Dcreate2(group, name, file_type, space, H5P_DEFAULT, properties, H5P_DEFAULT), name);
  check(H5Dwrite(set, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values), name);
  H5Dclose(set);
  H5Pclose(properties);
  H5Sclose(space);
}

void write_contents(hid_t file, const TableData& table) {
  write_string_attribute(file, schema::attr_schema, schema::name);
  write_int_attribute(file, schema::attr_schema_version, schema::version);
  write_string_attribute(file, schema::attr_generator, table.generator);
  write_string_attribute(file, schema::attr_generator_options, table.generator_options);
  write_string_attribute(file, schema::attr_conventions, schema::conventions);
  if (table.exact_shapes) write_int_attribute(file, schema::attr_exact_shapes, 1);
  for (const CurveSet& set : table.sets) {
    set.validate("generated");
    const std::string name = std::string(to_string(set.distribution)) + "_" + to_string(set.side);
    const hid_t group_properties = H5Pcreate(H5P_GROUP_CREATE);
    H5Pset_obj_track_times(group_properties, false);
    const hid_t group = check_id(H5Gcreate2(file, name.c_str(), H5P_DEFAULT, group_properties, H5P_DEFAULT), name);
    write_string_attribute(group, schema::attr_distribution, to_string(set.distribution));
    write_string_attribute(group, schema::attr_side, to_string(set.side));
    write_string_attribute(group, schema::attr_definition,
                           set.side == Side::bounded
                               ? "K_n(s) = integral_0^max(-s,0) (-s - z)^n phi(z) dz (heights mirrored)"
                               : "J_n(s) = integral_{z > max(s,0)} (z - s)^n phi(z) dz");
    const hsize_t shapes = set.shapes.size(), segments = set.layout.size();
    write_dataset(group, schema::set_shapes, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {shapes}, set.shapes.data());
    const double range[2] = {set.shape_min, set.shape_max};
    write_dataset(group, schema::set_shape_range, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {2}, range);
    std::vector<double> orders;
    for (int k = 0; k < order_count; ++k) orders.push_back(order_of(k));
    write_dataset(group, schema::set_orders, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {hsize_t(order_count)}, orders.data());
    std::vector<int> kinds, knots;
    std::vector<double> p0, p1;
    for (const SegmentSpec& segment : set.layout) {
      kinds.push_back(static_cast<int>(segment.kind));
      knots.push_back(segment.knots);
      p0.push_back(segment.p0);
      p1.push_back(segment.p1);
    }
    write_dataset(group, schema::set_segment_kind, H5T_STD_I32LE, H5T_NATIVE_INT, {segments}, kinds.data());
    write_dataset(group, schema::set_segment_knots, H5T_STD_I32LE, H5T_NATIVE_INT, {segments}, knots.data());
    write_dataset(group, schema::set_segment_p0, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {segments}, p0.data());
    write_dataset(group, schema::set_segment_p1, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {segments}, p1.data());
    write_dataset(group, schema::set_knots, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                  {shapes, hsize_t(order_count), hsize_t(set.total_knots()), 3}, set.knots.data());
    write_dataset(group, schema::set_max_rel_error, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                  {shapes, hsize_t(order_count)}, set.max_rel_error.data());
    H5Gclose(group);
    H5Pclose(group_properties);
  }
}

}  // namespace

void write_table_file(const TableData& table, const std::string& path) {
  const std::string temporary = path + ".tmp." + std::to_string(getpid());
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t create = H5Pcreate(H5P_FILE_CREATE);
  H5Pset_obj_track_times(create, false);
  const hid_t file = H5Fcreate(temporary.c_str(), H5F_ACC_TRUNC, create, H5P_DEFAULT);
  H5Pclose(create);
  if (file < 0) throw Error("cannot create '" + temporary + "' (does the directory exist and is it writable?)");
  try {
    write_contents(file, table);
  } catch (...) {
    H5Fclose(file);
    std::remove(temporary.c_str());
    throw;
  }
  if (H5Fclose(file) < 0) {
    std::remove(temporary.c_str());
    throw Error("closing '" + temporary + "' failed");
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    throw Error("cannot rename the finished table to '" + path + "'");
  }
}

}  // namespace asperity::tablegen
