// A table is one self-contained file: every byte it serves is under its integrity header's
// SHA-256. HDF5 can make a file point outside itself: external and user-defined links, soft
// links, datasets stored in external files, virtual datasets mapped from other files, filters
// HDF5 loads from plugin libraries. It would follow such a pointer and read another file,
// unchecked (a crafted table served another file's pressures, and hung on a FIFO there: issue
// 37). Tables hold none of these, so the first one found is refused, named, before anything of
// the file is read: the walk below uses only calls that do not follow links. HDF5's own access
// properties are set to refuse them too (a second line). Internal: included by table_io.cpp.
#pragma once
#include <hdf5.h>

#include <optional>
#include <string>
#include <vector>

#include "asperity/number_text.hpp"
#include "hdf5_handle.hpp"

namespace asperity::detail {

// Where HDF5 would look for relative names of other files: nowhere (/dev/null is no directory).
inline constexpr const char* nowhere_prefix = "/dev/null/";

// The access property lists every open of a table's objects goes through.
struct ConfinedAccess {
  Hdf5Handle groups;    // group access (links as below)
  Hdf5Handle datasets;  // dataset access, which is also the link access for H5Lexists
};

// HDF5 asks before it follows an external link: never.
inline herr_t deny_external_link(const char*, const char*, const char*, const char*, unsigned*, hid_t, void*) {
  return -1;
}

inline bool confine_links(hid_t access) {
  return H5Pset_nlinks(access, 1) >= 0 && H5Pset_elink_cb(access, deny_external_link, nullptr) >= 0 &&
         H5Pset_elink_prefix(access, nowhere_prefix) >= 0;
}

// Access lists under which HDF5 follows no soft chain, no external link, and finds no external
// or virtual file by a relative name; nothing if HDF5 cannot make them.
inline std::optional<ConfinedAccess> confined_access() {
  ConfinedAccess access{hdf5_properties(H5Pcreate(H5P_GROUP_ACCESS)), hdf5_properties(H5Pcreate(H5P_DATASET_ACCESS))};
  if (!access.groups.ok() || !access.datasets.ok() || !confine_links(access.groups.get()) ||
      !confine_links(access.datasets.get()) || H5Pset_efile_prefix(access.datasets.get(), nowhere_prefix) < 0 ||
      H5Pset_virtual_prefix(access.datasets.get(), nowhere_prefix) < 0)
    return std::nullopt;
  return access;
}

// A name or path from the file, fit for a message: the library's one rule for outside text
// (number_text.hpp), cut after 120 bytes.
inline std::string printable(const char* text) { return text ? terminal_text(quote_text(text, 120)) : std::string(); }

// The filters HDF5 has built in; for any other it would search plugin directories and load
// shared libraries from them (dlopen) when the data are read.
inline bool built_in_filter(H5Z_filter_t id) {
  return id == H5Z_FILTER_DEFLATE || id == H5Z_FILTER_SHUFFLE || id == H5Z_FILTER_FLETCHER32 ||
         id == H5Z_FILTER_SZIP || id == H5Z_FILTER_NBIT || id == H5Z_FILTER_SCALEOFFSET;
}

// What makes reading the dataset read another file (its storage, its mapping, its filters), or nothing.
inline std::optional<std::string> dataset_indirection(hid_t set) {
  const Hdf5Handle create = hdf5_properties(H5Dget_create_plist(set));
  if (!create.ok()) return "a dataset whose storage HDF5 cannot describe";
  const H5D_layout_t layout = H5Pget_layout(create.get());
  if (layout == H5D_VIRTUAL) return "a virtual dataset (its values are mapped from other files)";
  if (layout < 0) return "a dataset of an unknown layout";
  const int external = H5Pget_external_count(create.get());
  if (external > 0) {
    std::vector<char> name(4096, '\0');
    off_t offset = 0;
    hsize_t size = 0;
    const bool named = H5Pget_external(create.get(), 0, name.size() - 1, name.data(), &offset, &size) >= 0;
    return "a dataset with external storage (its values are in " + std::to_string(external) + " other file" +
           (external > 1 ? "s" : "") + (named ? ", the first '" + printable(name.data()) + "'" : std::string()) + ")";
  }
  if (external < 0) return "a dataset whose external storage HDF5 cannot count";
  const int filters = H5Pget_nfilters(create.get());
  if (filters < 0) return "a dataset whose filters HDF5 cannot list";
  for (int i = 0; i < filters; ++i) {
    unsigned flags = 0;
    std::size_t values = 0;
    // no filter_config: asking for it makes HDF5 look the filter up
    const H5Z_filter_t id = H5Pget_filter2(create.get(), static_cast<unsigned>(i), &flags, &values, nullptr, 0,
                                           nullptr, nullptr);
    if (!built_in_filter(id))
      return "a dataset compressed by filter " + std::to_string(id) +
             ", not one of HDF5's own (HDF5 would load it from a plugin library)";
  }
  return std::nullopt;
}

// Links a table may hold: the walk's work is bounded whatever the file (tables hold a few dozen).
inline constexpr long max_table_links = 10000;

struct IndirectionWalk {
  hid_t dataset_access;
  std::optional<std::string> found;  // the first object that points outside the file, described
  long links = 0;
};

// What a soft or external link points to, from its stored value (reading it follows nothing).
inline std::string link_target(hid_t group, const char* name, const H5L_info_t& info, hid_t access) {
  if (info.u.val_size == 0 || info.u.val_size > (1u << 16)) return "";
  std::vector<char> value(info.u.val_size + 1, '\0');
  if (H5Lget_val(group, name, value.data(), info.u.val_size, access) < 0) return "";
  if (info.type == H5L_TYPE_SOFT) return " to '" + printable(value.data()) + "'";
  unsigned flags = 0;
  const char* file = nullptr;
  const char* object = nullptr;
  if (H5Lunpack_elink_val(value.data(), info.u.val_size, &flags, &file, &object) < 0) return "";
  return " to object '" + printable(object) + "' of file '" + printable(file) + "'";
}

// H5Lvisit's callback, for each link below the root (`name` a path from it), parents before
// their members: only hard links, only to groups and to datasets that stay in the file.
inline herr_t visit_link(hid_t root, const char* name, const H5L_info_t* info, void* data) {
  IndirectionWalk& walk = *static_cast<IndirectionWalk*>(data);
  const auto refuse = [&](const std::string& what) {
    walk.found = "'" + printable(name) + "' is " + what;
    return 1;  // stops the walk
  };
  if (++walk.links > max_table_links)
    return refuse("link " + std::to_string(walk.links) + ", more than a table holds (" +
                  std::to_string(max_table_links) + ")");
  switch (info->type) {
    case H5L_TYPE_HARD: break;
    case H5L_TYPE_SOFT:
      return refuse("a soft link" + link_target(root, name, *info, walk.dataset_access) + " (a table holds none)");
    case H5L_TYPE_EXTERNAL:
      return refuse("an external link" + link_target(root, name, *info, walk.dataset_access) +
                    " (a table never points into another file)");
    default: return refuse("a user-defined link (class " + std::to_string(info->type) + ")");
  }
  // The path is of hard links only (its parents were visited first): opening it follows nothing.
  const Hdf5Handle object{H5Oopen(root, name, walk.dataset_access), H5Oclose};
  if (!object.ok()) return refuse("an object HDF5 cannot open");
  const H5I_type_t type = H5Iget_type(object.get());
  if (type == H5I_GROUP) return 0;
  if (type != H5I_DATASET) return refuse("neither a group nor a dataset (a table holds only those)");
  if (const std::optional<std::string> what = dataset_indirection(object.get())) return refuse(*what);
  return 0;
}

// The first object of the file that would make HDF5 read another file, described ("'weibull_tail'
// is an external link to ..."), or nothing.
inline std::optional<std::string> find_indirection(hid_t file, hid_t dataset_access) {
  IndirectionWalk walk{dataset_access, std::nullopt, 0};
  const herr_t walked = H5Lvisit(file, H5_INDEX_NAME, H5_ITER_INC, visit_link, &walk);
  if (walk.found) return walk.found;
  if (walked < 0) return std::string("a file whose links HDF5 cannot walk");
  return std::nullopt;
}

}  // namespace asperity::detail
