// HDF5 identifiers closed by scope, for the table reader and the table writer (tablegen) alike,
// and HDF5's error printing silenced for a scope only. Internal: not installed.
#pragma once
#include <hdf5.h>

#include <utility>

namespace asperity::detail {

// Owns one HDF5 identifier and closes it with the matching H5?close when it goes out of scope,
// also when an exception passes.
class Hdf5Handle {
 public:
  using Close = herr_t (*)(hid_t);
  Hdf5Handle() = default;
  Hdf5Handle(hid_t id, Close close) noexcept : id_(id), close_(close) {}
  Hdf5Handle(Hdf5Handle&& other) noexcept : id_(std::exchange(other.id_, H5I_INVALID_HID)), close_(other.close_) {}
  Hdf5Handle& operator=(Hdf5Handle&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, H5I_INVALID_HID);
      close_ = other.close_;
    }
    return *this;
  }
  Hdf5Handle(const Hdf5Handle&) = delete;
  Hdf5Handle& operator=(const Hdf5Handle&) = delete;
  ~Hdf5Handle() { reset(); }

  hid_t get() const noexcept { return id_; }
  bool ok() const noexcept { return id_ >= 0; }
  // Closes now and reports whether HDF5 closed it cleanly (a file's close flushes).
  bool close() noexcept {
    const bool closed = id_ < 0 || close_(id_) >= 0;
    id_ = H5I_INVALID_HID;
    return closed;
  }

 private:
  void reset() noexcept {
    if (id_ >= 0 && close_) close_(id_);
    id_ = H5I_INVALID_HID;
  }
  hid_t id_ = H5I_INVALID_HID;
  Close close_ = nullptr;
};

inline Hdf5Handle hdf5_file(hid_t id) { return {id, H5Fclose}; }
inline Hdf5Handle hdf5_group(hid_t id) { return {id, H5Gclose}; }
inline Hdf5Handle hdf5_dataset(hid_t id) { return {id, H5Dclose}; }
inline Hdf5Handle hdf5_attribute(hid_t id) { return {id, H5Aclose}; }
inline Hdf5Handle hdf5_type(hid_t id) { return {id, H5Tclose}; }
inline Hdf5Handle hdf5_space(hid_t id) { return {id, H5Sclose}; }
inline Hdf5Handle hdf5_properties(hid_t id) { return {id, H5Pclose}; }

// While one exists, HDF5 prints no error stack (we report errors ourselves); the previous
// handler comes back when it goes out of scope. H5E_BEGIN_TRY/H5E_END_TRY in RAII form, so that
// an exception thrown in between cannot leave printing off for the host program.
class QuietHdf5Errors {
 public:
  QuietHdf5Errors() noexcept {
    H5Eget_auto2(H5E_DEFAULT, &saved_function_, &saved_data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~QuietHdf5Errors() {
    H5Eclear2(H5E_DEFAULT);
    H5Eset_auto2(H5E_DEFAULT, saved_function_, saved_data_);
  }
  QuietHdf5Errors(const QuietHdf5Errors&) = delete;
  QuietHdf5Errors& operator=(const QuietHdf5Errors&) = delete;

 private:
  H5E_auto2_t saved_function_ = nullptr;
  void* saved_data_ = nullptr;
};

}  // namespace asperity::detail
