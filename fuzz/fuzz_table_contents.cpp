// libFuzzer target: deliberately crafted tables with a valid integrity header. The input drives
// edits of a tiny valid table through HDF5's own C API (attributes replaced by arrays or other
// types, datasets of other types, ranks and sizes, chunked datasets never written, values
// changed, objects deleted); the result is sealed with a valid header and read. What this
// reaches is what a crafted file can express in well-formed HDF5: the reader's own checks,
// which must refuse it with a message or give a table whose lookups hold, in bounded memory.
// (HDF5's parser on malformed bytes is outside: see docs/reliability.md.) The input's first
// choice picks the table's kind: Greenwood-Williamson integrals, or contact curves against
// separation (whose served values must then hold their promises: tiny_table.hpp's exercise).
#include <fuzzer/FuzzedDataProvider.h>
#include <hdf5.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "asperity/contact_curves.hpp"
#include "asperity/contact_curves_data.hpp"
#include "asperity/table.hpp"
#include "asperity/table_file.hpp"
#include "asperity/table_schema.hpp"
#include "asperity/table_writer.hpp"
#include "tiny_table.hpp"

namespace {

bool contact_curves = false;  // the kind of the input being crafted
bool adhesive = false;        // contact curves with a tensile part and a summit count

const std::vector<unsigned char>& base_file() {
  static const std::vector<unsigned char> bytes = asperity::table_file_bytes(asperity::fuzz::tiny_table());
  static const std::vector<unsigned char> curves =
      asperity::contact_curves_file_bytes(asperity::fuzz::tiny_contact_curves());
  static const std::vector<unsigned char> adhesive_curves =
      asperity::contact_curves_file_bytes(asperity::fuzz::tiny_adhesive_contact_curves());
  return contact_curves ? (adhesive ? adhesive_curves : curves) : bytes;
}

const char* const integral_groups[] = {"/", "weibull_tail", "weibull_bounded", "gaussian_tail"};
const char* const integral_attributes[] = {"schema", "schema_version", "generator", "generator_options", "exact_shapes",
                                           "conventions", "distribution", "kind"};
const char* const integral_datasets[] = {"shapes", "shape_range", "orders", "segment_kind", "segment_knots",
                                         "segment_p0", "segment_p1", "knots", "max_rel_error"};
const char* const curves_groups[] = {"/", "contact_curves"};
const char* const curves_attributes[] = {"schema", "schema_version", "generator", "generator_options", "kind",
                                         "source", "description", "separation_datum", "definition"};
const char* const curves_datasets[] = {"separation", "pressure", "stiffness", "area_fraction", "max_rel_error",
                                       "measured_rel_error", "check_points", "safety_factor", "solver_tolerance",
                                       "contact_modulus", "nominal_area", "mean_summit_height", "max_height",
                                       asperity::schema::set_tensile_pressure, asperity::schema::set_tensile_stiffness,
                                       asperity::schema::set_summit_count,
                                       asperity::schema::set_summit_count_max_rel_error};

const char* pick_group(FuzzedDataProvider& input) {
  return contact_curves ? input.PickValueInArray(curves_groups) : input.PickValueInArray(integral_groups);
}
const char* pick_attribute(FuzzedDataProvider& input) {
  return contact_curves ? input.PickValueInArray(curves_attributes) : input.PickValueInArray(integral_attributes);
}
const char* pick_dataset(FuzzedDataProvider& input) {
  return contact_curves ? input.PickValueInArray(curves_datasets) : input.PickValueInArray(integral_datasets);
}
const hid_t* const types[] = {&H5T_IEEE_F64LE, &H5T_IEEE_F64BE, &H5T_IEEE_F32LE, &H5T_STD_I32LE,
                              &H5T_STD_I64LE, &H5T_STD_U64LE,  &H5T_STD_I8LE,   &H5T_STD_U8LE};

double interesting_double(FuzzedDataProvider& input) {
  switch (input.ConsumeIntegralInRange<int>(0, 7)) {
    case 0: return 0;
    case 1: return 1e7;
    case 2: return -1e300;
    case 3: return std::numeric_limits<double>::quiet_NaN();
    case 4: return std::numeric_limits<double>::infinity();
    case 5: return static_cast<double>(input.ConsumeIntegralInRange<int>(-10, 70000));
    case 6: return input.ConsumeFloatingPointInRange<double>(-2, 2);
    default: return input.ConsumeFloatingPoint<double>();
  }
}

void replace_attribute(hid_t object, FuzzedDataProvider& input) {
  const char* name = pick_attribute(input);
  if (H5Aexists(object, name) > 0) H5Adelete(object, name);
  const bool scalar = input.ConsumeBool();
  const hsize_t count = scalar ? 1 : input.ConsumeIntegralInRange<hsize_t>(0, 5000);
  const hid_t space = scalar ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &count, nullptr);
  const int kind = input.ConsumeIntegralInRange<int>(0, 3);
  hid_t type = -1;
  std::vector<char> buffer;
  std::vector<const char*> pointers;
  std::string text = input.ConsumeRandomLengthString(200);
  if (kind == 0 || kind == 1) {  // numbers
    type = H5Tcopy(kind == 0 ? H5T_NATIVE_LLONG : H5T_NATIVE_DOUBLE);
    buffer.resize(count * 8);
    const double value = interesting_double(input);
    for (hsize_t i = 0; i < count; ++i) {
      if (kind == 0) {
        const long long integer = value >= -1e18 && value <= 1e18 ? static_cast<long long>(value) : 2;
        std::memcpy(&buffer[i * 8], &integer, 8);
      } else {
        std::memcpy(&buffer[i * 8], &value, 8);
      }
    }
  } else if (kind == 2) {  // fixed-length text
    type = H5Tcopy(H5T_C_S1);
    const std::size_t size = std::max<std::size_t>(1, text.size());
    H5Tset_size(type, size);
    H5Tset_cset(type, input.ConsumeBool() ? H5T_CSET_UTF8 : H5T_CSET_ASCII);
    H5Tset_strpad(type, input.ConsumeBool() ? H5T_STR_NULLPAD : H5T_STR_NULLTERM);
    buffer.assign(count * size, 'x');
    for (hsize_t i = 0; i < count; ++i) std::copy(text.begin(), text.end(), buffer.begin() + i * size);
  } else {  // variable-length text
    type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, H5T_VARIABLE);
    H5Tset_cset(type, input.ConsumeBool() ? H5T_CSET_UTF8 : H5T_CSET_ASCII);
    pointers.assign(count, text.c_str());
  }
  const hid_t attribute = H5Acreate2(object, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
  if (attribute >= 0) {
    if (count > 0) H5Awrite(attribute, type, kind == 3 ? static_cast<const void*>(pointers.data()) : buffer.data());
    H5Aclose(attribute);
  }
  H5Tclose(type);
  H5Sclose(space);
}

void replace_dataset(hid_t group, FuzzedDataProvider& input) {
  const char* name = pick_dataset(input);
  std::vector<hsize_t> dims;
  if (H5Lexists(group, name, H5P_DEFAULT) > 0) {  // start from its dimensions, then change some
    const hid_t set = H5Dopen2(group, name, H5P_DEFAULT);
    if (set >= 0) {
      const hid_t space = H5Dget_space(set);
      const int rank = H5Sget_simple_extent_ndims(space);
      if (rank > 0 && rank <= 4) {
        dims.resize(static_cast<std::size_t>(rank));
        H5Sget_simple_extent_dims(space, dims.data(), nullptr);
      }
      H5Sclose(space);
      H5Dclose(set);
    }
    H5Ldelete(group, name, H5P_DEFAULT);
  }
  if (dims.empty() || input.ConsumeBool()) dims.assign(input.ConsumeIntegralInRange<std::size_t>(1, 4), 1);
  for (hsize_t& dim : dims)
    if (input.ConsumeIntegralInRange<int>(0, 3) == 0) dim = input.ConsumeIntegralInRange<hsize_t>(0, 70000);
  double elements = 1;
  for (hsize_t dim : dims) elements *= static_cast<double>(dim);
  const hid_t type = *input.PickValueInArray(types);
  const hid_t space = H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr);
  const hid_t properties = H5Pcreate(H5P_DATASET_CREATE);
  const bool written = elements <= 20000;
  if (!written && elements > 0) {  // large: chunked and never written (a small file claiming much)
    std::vector<hsize_t> chunk(dims.size(), 1);
    chunk.back() = std::min<hsize_t>(dims.back(), 1024);
    H5Pset_chunk(properties, static_cast<int>(chunk.size()), chunk.data());
  }
  const hid_t set = H5Dcreate2(group, name, type, space, H5P_DEFAULT, properties, H5P_DEFAULT);
  if (set >= 0 && written && elements > 0) {
    std::vector<double> values(static_cast<std::size_t>(elements));
    const double first = interesting_double(input), step = input.ConsumeFloatingPointInRange<double>(-1, 1);
    for (std::size_t i = 0; i < values.size(); ++i) values[i] = first + step * static_cast<double>(i);
    H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
  }
  if (set >= 0) H5Dclose(set);
  H5Pclose(properties);
  H5Sclose(space);
}

void change_value(hid_t group, FuzzedDataProvider& input) {
  const char* name = pick_dataset(input);
  if (H5Lexists(group, name, H5P_DEFAULT) <= 0) return;
  const hid_t set = H5Dopen2(group, name, H5P_DEFAULT);
  if (set < 0) return;
  const hid_t space = H5Dget_space(set);
  const hssize_t count = H5Sget_simple_extent_npoints(space);
  if (count > 0 && count <= 200000) {
    std::vector<double> values(static_cast<std::size_t>(count));
    if (H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0) {
      const int changes = input.ConsumeIntegralInRange<int>(1, 4);
      for (int i = 0; i < changes; ++i)
        values[input.ConsumeIntegralInRange<std::size_t>(0, values.size() - 1)] =
            input.ConsumeBool() ? interesting_double(input)
                                : values[input.ConsumeIntegralInRange<std::size_t>(0, values.size() - 1)] *
                                      input.ConsumeFloatingPointInRange<double>(-3, 3);
      H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    }
  }
  H5Sclose(space);
  H5Dclose(set);
}

void delete_object(hid_t group, FuzzedDataProvider& input) {
  if (input.ConsumeBool()) {
    const char* name = pick_attribute(input);
    if (H5Aexists(group, name) > 0) H5Adelete(group, name);
  } else {
    const char* name = pick_dataset(input);
    if (H5Lexists(group, name, H5P_DEFAULT) > 0) H5Ldelete(group, name, H5P_DEFAULT);
  }
}

// The crafted file's bytes: the base table edited, an HDF5 image, a valid header before it.
std::vector<unsigned char> craft(FuzzedDataProvider& input) {
  static unsigned long serial = 0;
  const std::vector<unsigned char>& base = base_file();
  const hid_t access = H5Pcreate(H5P_FILE_ACCESS);
  H5Pset_fapl_core(access, 1 << 16, false);
  H5Pset_file_image(access, const_cast<unsigned char*>(base.data()), base.size());
  const std::string name = "/dev/null/fuzz-" + std::to_string(++serial);
  const hid_t file = H5Fopen(name.c_str(), H5F_ACC_RDWR, access);
  H5Pclose(access);
  std::vector<unsigned char> bytes;
  if (file < 0) return bytes;
  const int edits = input.ConsumeIntegralInRange<int>(1, 4);
  for (int i = 0; i < edits && input.remaining_bytes() > 0; ++i) {
    const char* group_name = pick_group(input);
    const hid_t group = H5Oopen(file, group_name, H5P_DEFAULT);
    if (group < 0) continue;
    switch (input.ConsumeIntegralInRange<int>(0, 3)) {
      case 0: replace_attribute(group, input); break;
      case 1: replace_dataset(group, input); break;
      case 2: change_value(group, input); break;
      default: delete_object(group, input); break;
    }
    H5Oclose(group);
  }
  H5Fflush(file, H5F_SCOPE_GLOBAL);
  const ssize_t size = H5Fget_file_image(file, nullptr, 0);
  if (size > 0) {
    bytes.assign(asperity::schema::header_bytes + static_cast<std::size_t>(size), 0);
    H5Fget_file_image(file, bytes.data() + asperity::schema::header_bytes, static_cast<std::size_t>(size));
    asperity::seal_table_bytes(bytes.data(), bytes.size());
  }
  H5Fclose(file);
  return bytes;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // the harness's own edits fail often, quietly
  base_file();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider input(data, size);
  contact_curves = input.ConsumeBool();
  adhesive = contact_curves && input.ConsumeBool();
  const std::vector<unsigned char> bytes = craft(input);
  if (bytes.empty()) return 0;
  try {
    if (contact_curves) {
      const asperity::ContactCurves curves(asperity::read_contact_curves_bytes(bytes.data(), bytes.size(), "crafted"));
      asperity::fuzz::exercise(curves);
    } else {
      const asperity::Table table(asperity::read_table_bytes(bytes.data(), bytes.size(), "crafted"));
      asperity::fuzz::exercise(table);
    }
  } catch (const asperity::Error&) {
  }
  return 0;
}
