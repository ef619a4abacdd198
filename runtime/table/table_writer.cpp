#include "asperity/table_writer.hpp"

#include <hdf5.h>

#include <cmath>
#include <string>
#include <vector>

#include "asperity/contact_curves_data.hpp"
#include "asperity/error.hpp"
#include "asperity/table_file.hpp"
#include "asperity/detail/table_schema.hpp"
#include "asperity/detail/segment_kind.hpp"
#include "hdf5_handle.hpp"
#include "asperity/output.hpp"

namespace asperity {
namespace {

using detail::Hdf5Handle;

// The root attribute `conventions`: what a table holds, in words (its segment kinds' lines from
// the kinds' one list, which is the library's, detail/segment_kind.hpp).
constexpr const char* conventions_text =
    "Greenwood-Williamson asperity integrals, see docs/model.md of the asperity project.\n"
    "Weibull summit heights phi_a(z) = a z^(a-1) exp(-z^a), z >= 0 (unit scale sigma_s);\n"
    "Gaussian phi(z) = exp(-z^2/2)/sqrt(2 pi) (unit rms summit height sigma).\n"
    "tail side:    J_n(s) = integral_{z > max(s,0)} (z - s)^n phi(z) dz, every real s.\n"
    "bounded side: K_n(s) = integral_0^{max(-s,0)} (-s - z)^n phi(z) dz; 0 for s >= 0.\n"
    "Orders n = 0, 1/2, 1, 3/2, 2, 5/2. Separation s from the Weibull origin (Gaussian: from\n"
    "the mean), in units of sigma_s (Gaussian: sigma). dX_n/ds = -n X_(n-1).\n"
    "Stored: H = ln X - offset(u) and dH/du, d2H/du2 on knots uniform in u per segment.\n"
    "Segment kinds (p0, p1 from segment_p0/p1; t = s^a, or s^2/2 for the Gaussian):\n"
    ASPERITY_SEGMENT_KIND_TEXT
    "Shapes between grid nodes: Lagrange in q = ln a - 1/a over the 12 nearest nodes, at the same s.";

[[noreturn]] void fail(const std::string& what) { throw Error("writing the table failed: " + what); }
void check(herr_t status, const std::string& what) {
  if (status < 0) fail(what);
}
Hdf5Handle checked(Hdf5Handle handle, const std::string& what) {
  if (!handle.ok()) fail(what);
  return handle;
}

void write_string_attribute(hid_t object, const char* name, const std::string& text) {
  if (text.size() > schema::max_text_bytes)
    throw Error(std::string("the table's attribute '") + name + "' would hold " + std::to_string(text.size()) +
                " bytes, more than a table's text may have (" + std::to_string(schema::max_text_bytes) + ")");
  const Hdf5Handle type = checked(detail::hdf5_type(H5Tcopy(H5T_C_S1)), name);
  check(H5Tset_size(type.get(), text.size() + 1), name);
  check(H5Tset_strpad(type.get(), H5T_STR_NULLTERM), name);
  const Hdf5Handle space = checked(detail::hdf5_space(H5Screate(H5S_SCALAR)), name);
  const Hdf5Handle attribute = checked(
      detail::hdf5_attribute(H5Acreate2(object, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT)), name);
  check(H5Awrite(attribute.get(), type.get(), text.c_str()), name);
}

void write_int_attribute(hid_t object, const char* name, int value) {
  const Hdf5Handle space = checked(detail::hdf5_space(H5Screate(H5S_SCALAR)), name);
  const Hdf5Handle attribute = checked(
      detail::hdf5_attribute(H5Acreate2(object, name, H5T_STD_I32LE, space.get(), H5P_DEFAULT, H5P_DEFAULT)), name);
  check(H5Awrite(attribute.get(), H5T_NATIVE_INT, &value), name);
}

template <class T>
void write_dataset(hid_t group, const char* name, hid_t file_type, hid_t memory_type,
                   const std::vector<hsize_t>& dims, const T* values) {
  const Hdf5Handle space =
      checked(detail::hdf5_space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr)), name);
  const Hdf5Handle properties = checked(detail::hdf5_properties(H5Pcreate(H5P_DATASET_CREATE)), name);
  check(H5Pset_obj_track_times(properties.get(), false), name);  // no timestamps: same data, same bytes
  if (dims.size() == 4) {  // the knots: one chunk per shape, byte-shuffled and deflated
    const hsize_t chunk[4] = {1, dims[1], dims[2], dims[3]};
    check(H5Pset_chunk(properties.get(), 4, chunk), name);
    check(H5Pset_shuffle(properties.get()), name);
    check(H5Pset_deflate(properties.get(), 6), name);
  }
  const Hdf5Handle set = checked(
      detail::hdf5_dataset(H5Dcreate2(group, name, file_type, space.get(), H5P_DEFAULT, properties.get(), H5P_DEFAULT)),
      name);
  check(H5Dwrite(set.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values), name);
}

void write_contents(hid_t file, const TableData& table) {
  write_string_attribute(file, schema::attr_schema, schema::name);
  write_int_attribute(file, schema::attr_schema_version, schema::version);
  write_string_attribute(file, schema::attr_generator, table.generator);
  write_string_attribute(file, schema::attr_generator_options, table.generator_options);
  write_string_attribute(file, schema::attr_conventions, conventions_text);
  if (table.exact_shapes) write_int_attribute(file, schema::attr_exact_shapes, 1);
  for (const CurveSet& set : table.sets) {
    const std::string name = std::string(to_string(set.distribution)) + "_" + to_string(set.side);
    const Hdf5Handle group_properties = checked(detail::hdf5_properties(H5Pcreate(H5P_GROUP_CREATE)), name);
    check(H5Pset_obj_track_times(group_properties.get(), false), name);
    const Hdf5Handle group = checked(
        detail::hdf5_group(H5Gcreate2(file, name.c_str(), H5P_DEFAULT, group_properties.get(), H5P_DEFAULT)), name);
    const hid_t g = group.get();
    write_string_attribute(g, schema::attr_distribution, to_string(set.distribution));
    write_string_attribute(g, schema::attr_side, to_string(set.side));
    write_string_attribute(g, schema::attr_definition,
                           set.side == Side::bounded
                               ? "K_n(s) = integral_0^max(-s,0) (-s - z)^n phi(z) dz (heights mirrored)"
                               : "J_n(s) = integral_{z > max(s,0)} (z - s)^n phi(z) dz");
    const hsize_t shapes = set.shapes.size(), segments = set.layout.size();
    write_dataset(g, schema::set_shapes, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {shapes}, set.shapes.data());
    const double range[2] = {set.shape_min, set.shape_max};
    write_dataset(g, schema::set_shape_range, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {2}, range);
    std::vector<double> orders;
    for (int k = 0; k < order_count; ++k) orders.push_back(order_of(k));
    write_dataset(g, schema::set_orders, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {hsize_t(order_count)}, orders.data());
    std::vector<int> kinds, knots;
    std::vector<double> p0, p1;
    for (const SegmentSpec& segment : set.layout) {
      kinds.push_back(static_cast<int>(segment.kind));
      knots.push_back(segment.knots);
      p0.push_back(segment.p0);
      p1.push_back(segment.p1);
    }
    write_dataset(g, schema::set_segment_kind, H5T_STD_I32LE, H5T_NATIVE_INT, {segments}, kinds.data());
    write_dataset(g, schema::set_segment_knots, H5T_STD_I32LE, H5T_NATIVE_INT, {segments}, knots.data());
    write_dataset(g, schema::set_segment_p0, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {segments}, p0.data());
    write_dataset(g, schema::set_segment_p1, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {segments}, p1.data());
    write_dataset(g, schema::set_knots, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                  {shapes, hsize_t(order_count), hsize_t(set.total_knots()), 3}, set.knots.data());
    write_dataset(g, schema::set_max_rel_error, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {shapes, hsize_t(order_count)},
                  set.max_rel_error.data());
    if (!set.grid_tolerance.empty()) {
      write_dataset(g, schema::set_grid_tolerance, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {shapes}, set.grid_tolerance.data());
      write_dataset(g, schema::set_grid_separations, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {shapes, 2},
                    set.grid_separations.data());
    }
  }
}

void write_contact_curves_contents(hid_t file, const ContactCurvesData& data) {
  write_string_attribute(file, schema::attr_schema, schema::name);
  write_int_attribute(file, schema::attr_schema_version, schema::version);
  write_string_attribute(file, schema::attr_kind, schema::kind_contact_curves);
  write_string_attribute(file, schema::attr_generator, data.generator);
  write_string_attribute(file, schema::attr_generator_options, data.generator_options);
  write_string_attribute(file, schema::attr_conventions, schema::contact_curves_definition);
  const char* name = schema::group_contact_curves;
  const Hdf5Handle group_properties = checked(detail::hdf5_properties(H5Pcreate(H5P_GROUP_CREATE)), name);
  check(H5Pset_obj_track_times(group_properties.get(), false), name);
  const Hdf5Handle group =
      checked(detail::hdf5_group(H5Gcreate2(file, name, H5P_DEFAULT, group_properties.get(), H5P_DEFAULT)), name);
  const hid_t g = group.get();
  write_string_attribute(g, schema::attr_source, data.source);
  write_string_attribute(g, schema::attr_description, data.description);
  write_string_attribute(g, schema::attr_separation_datum, data.separation_datum);
  write_string_attribute(g, schema::attr_definition, schema::contact_curves_definition);
  const hsize_t nodes = data.separation.size();
  const auto doubles = [&](const char* set, const double* values, hsize_t count) {
    write_dataset(g, set, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {count}, values);
  };
  doubles(schema::set_separation, data.separation.data(), nodes);
  doubles(schema::set_pressure, data.pressure.data(), nodes);
  doubles(schema::set_stiffness, data.stiffness.data(), nodes);
  doubles(schema::set_area_fraction, data.area_fraction.data(), nodes);
  doubles(schema::set_max_rel_error, data.max_rel_error, 3);
  doubles(schema::set_measured_rel_error, data.measured_rel_error, 3);
  write_dataset(g, schema::set_check_points, H5T_STD_I32LE, H5T_NATIVE_INT, {1}, &data.check_points);
  if (data.bound_method != ContactBoundMethod::unstated)  // absent: unstated, as in tables before it
    write_string_attribute(g, schema::attr_bound_method, to_string(data.bound_method));
  doubles(schema::set_safety_factor, &data.safety_factor, 1);
  doubles(schema::set_solver_tolerance, &data.solver_tolerance, 1);
  doubles(schema::set_contact_modulus, &data.contact_modulus, 1);
  doubles(schema::set_nominal_area, &data.nominal_area, 1);
  if (!std::isnan(data.mean_summit_height)) doubles(schema::set_mean_summit_height, &data.mean_summit_height, 1);
  if (!std::isnan(data.max_height)) doubles(schema::set_max_height, &data.max_height, 1);
  if (data.has_tension()) {
    doubles(schema::set_tensile_pressure, data.tensile_pressure.data(), nodes);
    doubles(schema::set_tensile_stiffness, data.tensile_stiffness.data(), nodes);
  }
  if (!data.summit_count.empty()) {
    doubles(schema::set_summit_count, data.summit_count.data(), nodes);
    doubles(schema::set_summit_count_max_rel_error, &data.summit_count_max_rel_error, 1);
  }
  if (data.withdrawal()) doubles(schema::set_approach_separation, &data.approach_separation, 1);
}

// The file's bytes: HDF5 in memory with the user block, `write` filling it, the header sealed.
template <class Write>
std::vector<unsigned char> sealed_file_bytes(Write write) {
  const detail::QuietHdf5Errors quiet;  // our messages say what failed
  std::vector<unsigned char> bytes;
  {
    const Hdf5Handle create = checked(detail::hdf5_properties(H5Pcreate(H5P_FILE_CREATE)), "file properties");
    check(H5Pset_obj_track_times(create.get(), false), "file properties");
    check(H5Pset_userblock(create.get(), schema::header_bytes), "the user block");
    // In memory (HDF5's core driver, no backing file): we write the bytes ourselves.
    const Hdf5Handle access = checked(detail::hdf5_properties(H5Pcreate(H5P_FILE_ACCESS)), "file properties");
    check(H5Pset_fapl_core(access.get(), 1 << 20, false), "file properties");
    static unsigned long images = 0;
    const std::string image_name = "asperity-table-being-written-" + std::to_string(++images);
    Hdf5Handle file = checked(detail::hdf5_file(H5Fcreate(image_name.c_str(), H5F_ACC_TRUNC, create.get(), access.get())),
                              "HDF5 cannot create a file in memory");
    write(file.get());
    check(H5Fflush(file.get(), H5F_SCOPE_GLOBAL), "flushing the file");
    // The image starts at the superblock (HDF5 leaves the user block out): the header goes before it.
    const ssize_t size = H5Fget_file_image(file.get(), nullptr, 0);
    if (size <= 0) fail("HDF5 gave no file image");
    bytes.assign(schema::header_bytes + static_cast<std::size_t>(size), 0);
    if (H5Fget_file_image(file.get(), bytes.data() + schema::header_bytes, static_cast<std::size_t>(size)) != size)
      fail("HDF5 gave a short file image");
    if (!file.close()) fail("closing the file");
  }
  seal_table_bytes(bytes.data(), bytes.size());
  return bytes;
}

}  // namespace

std::vector<unsigned char> table_file_bytes(const TableData& table) {
  // Everything the reader would refuse is refused here, before HDF5 is asked for anything.
  for (const CurveSet& set : table.sets) {
    set.validate("generated");
    if (set.max_rel_error.size() != set.shapes.size() * order_count)
      throw Error("generated: every curve needs its measured max_rel_error");
  }
  if (table.sets.empty()) throw Error("generated: a table needs at least one curve set");
  return sealed_file_bytes([&](hid_t file) { write_contents(file, table); });
}

void write_table_file(const TableData& table, const std::string& path, bool overwrite) {
  const std::vector<unsigned char> bytes = table_file_bytes(table);
  write_output_file(path, {reinterpret_cast<const char*>(bytes.data()), bytes.size()}, output_kinds::gw_table,
                    overwrite);
}

std::vector<unsigned char> contact_curves_file_bytes(const ContactCurvesData& data) {
  data.validate("contact curves to write");
  return sealed_file_bytes([&](hid_t file) { write_contact_curves_contents(file, data); });
}

void write_contact_curves_file(const ContactCurvesData& data, const std::string& path, bool overwrite) {
  const std::vector<unsigned char> bytes = contact_curves_file_bytes(data);
  write_output_file(path, {reinterpret_cast<const char*>(bytes.data()), bytes.size()},
                    output_kinds::contact_curves_table, overwrite);
}

// The table kinds of the output policy: a table file of ours, intact, of that kind.
namespace output_kinds {
namespace {
bool is_table_of(const std::string& path, TableKind kind) {
  try {
    return read_table_kind(path) == kind;
  } catch (const Error&) {
    return false;
  }
}
bool is_gw_table(const std::string& path) { return is_table_of(path, TableKind::integrals); }
bool is_contact_curves_table(const std::string& path) { return is_table_of(path, TableKind::contact_curves); }
}  // namespace
const OutputKind gw_table{"a table of Greenwood-Williamson integrals", is_gw_table};
const OutputKind contact_curves_table{"a contact-curves table", is_contact_curves_table};
}  // namespace output_kinds

}  // namespace asperity
