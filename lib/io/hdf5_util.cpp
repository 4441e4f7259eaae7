// HDF5 helpers declared in hdf5_util.hpp.
#include "io/hdf5_util.hpp"

#include <stdexcept>

namespace rfmems {

namespace {

herr_t keep_first(unsigned n, const H5E_error2_t* err, void* data) {
  auto* out = static_cast<std::string*>(data);
  if (n == 0 && err != nullptr && err->desc != nullptr) *out = err->desc;
  return 0;
}

// A new string type: variable-length, UTF-8.
H5Handle vlen_utf8_type(const std::string& file) {
  H5Handle type(check_id(H5Tcopy(H5T_C_S1), file, "creating a string type"), H5Tclose);
  check_status(H5Tset_size(type.get(), H5T_VARIABLE), file, "creating a string type");
  check_status(H5Tset_cset(type.get(), H5T_CSET_UTF8), file, "creating a string type");
  return type;
}

// Creates attribute `name` on object (replacing one of that name) and writes data to it.
void put_attribute(hid_t object, const std::string& name, hid_t file_type, hid_t mem_type,
                   hid_t space, const void* data, const std::string& file) {
  const std::string what = "writing attribute '" + name + "'";
  const htri_t exists = H5Aexists(object, name.c_str());
  check_status(exists < 0 ? -1 : 0, file, what);
  if (exists > 0) check_status(H5Adelete(object, name.c_str()), file, what);
  H5Handle attr(
      check_id(H5Acreate2(object, name.c_str(), file_type, space, H5P_DEFAULT, H5P_DEFAULT), file,
               what),
      H5Aclose);
  check_status(H5Awrite(attr.get(), mem_type, data), file, what);
}

}  // namespace

void silence_hdf5_errors() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

std::string hdf5_error_message() {
  std::string message;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, keep_first, &message);  // upward: most specific first
  return message;
}

hid_t check_id(hid_t id, const std::string& file, const std::string& what) {
  if (id < 0) {
    const std::string detail = hdf5_error_message();
    throw std::runtime_error(file + ": HDF5 error while " + what +
                             (detail.empty() ? "" : ": " + detail));
  }
  return id;
}

void check_status(herr_t status, const std::string& file, const std::string& what) {
  if (status < 0) {
    const std::string detail = hdf5_error_message();
    throw std::runtime_error(file + ": HDF5 error while " + what +
                             (detail.empty() ? "" : ": " + detail));
  }
}

void write_attribute(hid_t object, const std::string& name, double value, const std::string& file) {
  H5Handle space(check_id(H5Screate(H5S_SCALAR), file, "creating a dataspace"), H5Sclose);
  put_attribute(object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, space.get(), &value, file);
}

void write_attribute(hid_t object, const std::string& name, long long value,
                     const std::string& file) {
  H5Handle space(check_id(H5Screate(H5S_SCALAR), file, "creating a dataspace"), H5Sclose);
  put_attribute(object, name, H5T_STD_I64LE, H5T_NATIVE_LLONG, space.get(), &value, file);
}

void write_attribute(hid_t object, const std::string& name, const std::string& value,
                     const std::string& file) {
  H5Handle space(check_id(H5Screate(H5S_SCALAR), file, "creating a dataspace"), H5Sclose);
  const H5Handle type = vlen_utf8_type(file);
  const char* text = value.c_str();
  put_attribute(object, name, type.get(), type.get(), space.get(), &text, file);
}

void write_attribute(hid_t object, const std::string& name, const std::vector<std::string>& value,
                     const std::string& file) {
  const hsize_t n = value.size();
  H5Handle space(check_id(H5Screate_simple(1, &n, nullptr), file, "creating a dataspace"),
                 H5Sclose);
  const H5Handle type = vlen_utf8_type(file);
  std::vector<const char*> texts;
  for (const auto& s : value) texts.push_back(s.c_str());
  put_attribute(object, name, type.get(), type.get(), space.get(), texts.data(), file);
}

H5Handle write_dataset(hid_t location, const std::string& path, hid_t mem_type, const void* data,
                       const std::vector<hsize_t>& shape, const std::string& file) {
  const std::string what = "writing dataset '" + path + "'";
  H5Handle space(
      check_id(H5Screate_simple(static_cast<int>(shape.size()), shape.data(), nullptr), file, what),
      H5Sclose);
  H5Handle link_props(check_id(H5Pcreate(H5P_LINK_CREATE), file, what), H5Pclose);
  check_status(H5Pset_create_intermediate_group(link_props.get(), 1), file, what);
  // Stored little-endian whatever the machine, like the rest of the file.
  const hid_t file_type = H5Tequal(mem_type, H5T_NATIVE_DOUBLE) > 0  ? H5T_IEEE_F64LE
                          : H5Tequal(mem_type, H5T_NATIVE_INT64) > 0 ? H5T_STD_I64LE
                                                                     : mem_type;
  H5Handle set(check_id(H5Dcreate2(location, path.c_str(), file_type, space.get(), link_props.get(),
                                   H5P_DEFAULT, H5P_DEFAULT),
                        file, what),
               H5Dclose);
  hsize_t count = 1;
  for (const hsize_t n : shape) count *= n;
  if (count > 0)  // an empty vector's data() may be null, which H5Dwrite rejects
    check_status(H5Dwrite(set.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), file, what);
  return set;
}

}  // namespace rfmems
