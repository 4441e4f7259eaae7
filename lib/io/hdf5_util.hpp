// Safe use of the HDF5 C API: an owning handle for hid_t, checks that turn HDF5 failures
// into std::runtime_error naming the file, and small typed writers for attributes.
// Only .cpp files (and tests) include this header, keeping hdf5.h out of public headers.
#pragma once
#include <hdf5.h>

#include <string>
#include <vector>

namespace rfmems {

// Owns one HDF5 identifier and closes it with the matching H5?close function.
class H5Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  H5Handle() = default;
  H5Handle(hid_t id, Closer close) : id_(id), close_(close) {}
  ~H5Handle() { reset(); }
  H5Handle(H5Handle&& o) noexcept : id_(o.id_), close_(o.close_) { o.id_ = H5I_INVALID_HID; }
  H5Handle& operator=(H5Handle&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = o.id_;
      close_ = o.close_;
      o.id_ = H5I_INVALID_HID;
    }
    return *this;
  }
  H5Handle(const H5Handle&) = delete;
  H5Handle& operator=(const H5Handle&) = delete;

  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  // Closes now; returns the close status (negative on failure, e.g. a failed final flush).
  herr_t reset() {
    herr_t status = 0;
    if (id_ >= 0 && close_ != nullptr) status = close_(id_);
    id_ = H5I_INVALID_HID;
    return status;
  }

 private:
  hid_t id_ = H5I_INVALID_HID;
  Closer close_ = nullptr;
};

// Stops HDF5 from printing its error stack on stderr (we report errors ourselves).
void silence_hdf5_errors();

// The most specific message on HDF5's error stack, or "" if empty. Call right after the
// failing HDF5 function: the next call clears the stack.
std::string hdf5_error_message();

// Throw std::runtime_error("<file>: HDF5 error while <what>: <message>") on failure.
hid_t check_id(hid_t id, const std::string& file, const std::string& what);
void check_status(herr_t status, const std::string& file, const std::string& what);

// Attribute writers: an existing attribute of the same name is replaced. `file` is only for
// messages. Strings are variable-length UTF-8 (h5py reads them as str, any length).
void write_attribute(hid_t object, const std::string& name, double value, const std::string& file);
void write_attribute(hid_t object, const std::string& name, long long value,
                     const std::string& file);
void write_attribute(hid_t object, const std::string& name, const std::string& value,
                     const std::string& file);
void write_attribute(hid_t object, const std::string& name, const std::vector<std::string>& value,
                     const std::string& file);

// Writes a new dataset at `path` below `location` (intermediate groups are created) from
// contiguous row-major data of the given shape; mem_type e.g. H5T_NATIVE_DOUBLE. Returns the
// open dataset (for attributes).
H5Handle write_dataset(hid_t location, const std::string& path, hid_t mem_type, const void* data,
                       const std::vector<hsize_t>& shape, const std::string& file);

}  // namespace rfmems
