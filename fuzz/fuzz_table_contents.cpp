// libFuzzer target: deliberately crafted tables with a valid integrity header. The input drives
// edits of a tiny valid table through HDF5's own C API (attributes replaced by arrays or other
// types, datasets of other types, ranks and sizes, chunked datasets never written, values
// changed, objects deleted); the result is sealed with a valid header and read. What this
// reaches is what a crafted file can express in well-formed HDF5: the reader's own checks,
// which must refuse it with a message or give a table whose lookups hold, in bounded memory.
// Last, the input may point the table outside itself (issue 37): an object replaced by an
// external, soft or user-defined link, a dataset by one with external storage, a virtual one or
// one filtered by a plugin, each aimed at a real file beside it. A table holding one of these
// must be refused: one that opens traps.
// (HDF5's parser on malformed bytes is outside: see docs/reliability.md.) The input's first
// choice picks the table's kind: Greenwood-Williamson integrals, or contact curves against
// separation (whose served values must then hold their promises: tiny_table.hpp's exercise).
#include <fuzzer/FuzzedDataProvider.h>
#include <hdf5.h>
#include <stdlib.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "asperity/contact_curves.hpp"
#include "asperity/contact_curves_data.hpp"
#include "asperity/table.hpp"
#include "asperity/table_file.hpp"
#include "asperity/detail/table_schema.hpp"
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

// ---- indirections: what would make HDF5 read another file ----

const std::string& elsewhere();

void remove_elsewhere() {
  std::remove((elsewhere() + "/other.h5").c_str());
  std::remove((elsewhere() + "/raw.bin").c_str());
  std::remove(elsewhere().c_str());
}

// A directory of files an indirection may point to (made once, removed at exit): "other.h5", a
// plain HDF5 copy of each base table's groups (so a link to "/contact_curves" or "/weibull_tail"
// resolves there), and "raw.bin", a megabyte of doubles for external storage.
const std::string& elsewhere() {
  static const std::string directory = [] {
    char name[] = "/tmp/fuzz-table-elsewhere-XXXXXX";
    const std::string made = mkdtemp(name) ? name : "/tmp/fuzz-table-elsewhere";
    const hid_t other = H5Fcreate((made + "/other.h5").c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    for (const bool curves : {false, true}) {
      contact_curves = curves;
      const std::vector<unsigned char>& base = base_file();
      const hid_t access = H5Pcreate(H5P_FILE_ACCESS);
      H5Pset_fapl_core(access, 1 << 16, false);
      H5Pset_file_image(access, const_cast<unsigned char*>(base.data()), base.size());
      const hid_t file = H5Fopen(curves ? "/dev/null/fuzz-base-curves" : "/dev/null/fuzz-base", H5F_ACC_RDONLY, access);
      for (const char* group : curves ? std::vector<const char*>{"contact_curves"}
                                      : std::vector<const char*>{"weibull_tail", "weibull_bounded", "gaussian_tail"})
        H5Ocopy(file, group, other, group, H5P_DEFAULT, H5P_DEFAULT);
      H5Fclose(file);
      H5Pclose(access);
    }
    contact_curves = false;
    H5Fclose(other);
    const std::vector<double> raw(1 << 17, 0.25);
    if (FILE* file = std::fopen((made + "/raw.bin").c_str(), "wb")) {
      std::fwrite(raw.data(), sizeof(double), raw.size(), file);
      std::fclose(file);
    }
    return made;
  }();
  return directory;
}

// A user-defined link class (registered in this process, so HDF5 would traverse it): opens an
// object of the same file by the path it stores.
hid_t open_by_path(const char*, hid_t group, const void* path, std::size_t, hid_t access, hid_t) {
  return H5Oopen(group, static_cast<const char*>(path), access);
}
constexpr H5L_type_t by_path_link = static_cast<H5L_type_t>(H5L_TYPE_UD_MIN + 37);

// The path an indirection names: a real file beside the table, or a relative name (resolved
// against the working directory), or one that is not there.
std::string other_path(FuzzedDataProvider& input, const char* real) {
  switch (input.ConsumeIntegralInRange<int>(0, 2)) {
    case 0: return elsewhere() + "/" + real;
    case 1: return real;
    default: return elsewhere() + "/missing";
  }
}

// A dataset of `group` replaced by one of its own dimensions whose creation `configure` sets.
bool replace_with(hid_t group, const char* name, const std::function<bool(hid_t create, hid_t space)>& configure,
                  bool write_chunk = false) {
  const hid_t old = H5Dopen2(group, name, H5P_DEFAULT);
  if (old < 0) return false;
  const hid_t space = H5Dget_space(old);
  H5Dclose(old);
  H5Ldelete(group, name, H5P_DEFAULT);
  const hssize_t points = H5Sget_simple_extent_npoints(space);
  const hid_t create = H5Pcreate(H5P_DATASET_CREATE);
  bool made = points > 0 && points <= 200000 && configure(create, space);  // bounded: a chunk is written whole
  const hid_t set = made ? H5Dcreate2(group, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, create, H5P_DEFAULT) : -1;
  made = set >= 0;
  if (made && write_chunk) {  // one chunk of the whole, written as if the filters had run
    const std::vector<double> values(static_cast<std::size_t>(points), 0.5);
    const std::vector<hsize_t> offset(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)), 0);
    made = H5Dwrite_chunk(set, H5P_DEFAULT, 0, offset.data(), values.size() * sizeof(double), values.data()) >= 0;
  }
  if (set >= 0) H5Dclose(set);
  H5Pclose(create);
  H5Sclose(space);
  return made;
}

// Points the table outside itself at `name` of `group`; whether it did.
bool indirect(hid_t file, const char* group_name, FuzzedDataProvider& input) {
  const hid_t group = H5Gopen2(file, group_name, H5P_DEFAULT);
  if (group < 0) return false;
  const bool whole_group = group_name == std::string("/") && input.ConsumeBool();
  const char* name = whole_group ? (contact_curves ? "contact_curves" : "weibull_tail") : pick_dataset(input);
  bool made = false;
  if (H5Lexists(group, name, H5P_DEFAULT) > 0) {
    const std::string parent = group_name == std::string("/") ? "" : std::string(group_name) + "/";
    const std::string path = "/" + parent + name;
    switch (input.ConsumeIntegralInRange<int>(0, 5)) {
      case 0:  // an external link to the same path in another file
        H5Ldelete(group, name, H5P_DEFAULT);
        made = H5Lcreate_external(other_path(input, "other.h5").c_str(), path.c_str(), group, name, H5P_DEFAULT,
                                  H5P_DEFAULT) >= 0;
        break;
      case 1:  // a soft link to the object, moved (or to nothing)
        made = H5Lmove(group, name, file, "/moved", H5P_DEFAULT, H5P_DEFAULT) >= 0 &&
               H5Lcreate_soft(input.ConsumeBool() ? "/moved" : "/nowhere", group, name, H5P_DEFAULT, H5P_DEFAULT) >= 0;
        break;
      case 2:  // a user-defined link to the object, moved
        made = H5Lmove(group, name, file, "/moved", H5P_DEFAULT, H5P_DEFAULT) >= 0 &&
               H5Lcreate_ud(group, name, by_path_link, "/moved", 7, H5P_DEFAULT, H5P_DEFAULT) >= 0;
        break;
      case 3:  // external storage
        made = replace_with(group, name, [&](hid_t create, hid_t) {
          return H5Pset_external(create, other_path(input, "raw.bin").c_str(), 0, H5F_UNLIMITED) >= 0;
        });
        break;
      case 4:  // a virtual dataset of the same path in another file
        made = replace_with(group, name, [&](hid_t create, hid_t space) {
          return H5Pset_virtual(create, space, other_path(input, "other.h5").c_str(), path.c_str(), space) >= 0;
        });
        break;
      default:  // a filter HDF5 would load from a plugin library
        made = replace_with(
            group, name,
            [&](hid_t create, hid_t space) {
              std::vector<hsize_t> chunk(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)));
              H5Sget_simple_extent_dims(space, chunk.data(), nullptr);
              return H5Pset_chunk(create, static_cast<int>(chunk.size()), chunk.data()) >= 0 &&
                     H5Pset_filter(create, input.ConsumeIntegralInRange<H5Z_filter_t>(256, 65535), H5Z_FLAG_OPTIONAL,
                                   0, nullptr) >= 0;
            },
            true);
        break;
    }
  }
  H5Gclose(group);
  return made;
}

// The crafted file's bytes: the base table edited, an HDF5 image, a valid header before it.
// `indirection`: whether it points outside itself (then it must be refused).
std::vector<unsigned char> craft(FuzzedDataProvider& input, bool& indirection) {
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
  // last, so that no later edit takes it out
  indirection = input.ConsumeBool() && indirect(file, pick_group(input), input);
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
  elsewhere();
  std::atexit(remove_elsewhere);
  const H5L_class_t by_path = {H5L_LINK_CLASS_T_VERS, by_path_link, "by path", nullptr, nullptr, nullptr,
                               open_by_path, nullptr, nullptr};
  H5Lregister(&by_path);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider input(data, size);
  contact_curves = input.ConsumeBool();
  adhesive = contact_curves && input.ConsumeBool();
  bool indirection = false;
  const std::vector<unsigned char> bytes = craft(input, indirection);
  if (bytes.empty()) return 0;
  try {
    if (contact_curves) {
      const asperity::ContactCurves curves(asperity::read_contact_curves_bytes(bytes.data(), bytes.size(), "crafted"));
      if (indirection) __builtin_trap();  // served what another file holds
      asperity::fuzz::exercise(curves);
    } else {
      const asperity::Table table(asperity::read_table_bytes(bytes.data(), bytes.size(), "crafted"));
      if (indirection) __builtin_trap();
      asperity::fuzz::exercise(table);
    }
  } catch (const asperity::Error& error) {
    // refused as pointing outside, not for a reason found later
    if (indirection && !std::strstr(error.what(), "a table is one self-contained file")) __builtin_trap();
  }
  return 0;
}
