// Checkpoint files: HDF5 layout and atomic replacement (see the header).
#include "io/checkpoint.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/hdf5_util.hpp"

namespace rfmems {

namespace {

constexpr long long kFormatVersion = 1;
constexpr const char* kFormat = "rfmems-checkpoint";

H5Handle file_access(const std::string& path) {
  H5Handle access(check_id(H5Pcreate(H5P_FILE_ACCESS), path, "opening the file"), H5Pclose);
  check_status(H5Pset_fclose_degree(access.get(), H5F_CLOSE_STRONG), path, "opening the file");
#if H5_VERSION_GE(1, 10, 7)
  check_status(H5Pset_file_locking(access.get(), false, true), path, "opening the file");
#endif
  return access;
}

void write_vector(hid_t location, const std::string& name, const std::vector<double>& v,
                  const std::string& file) {
  write_dataset(location, name, H5T_NATIVE_DOUBLE, v.data(), {v.size()}, file);
}

// --- reading (every failure is "not a readable checkpoint": InputError naming the file) ---

[[noreturn]] void malformed(const std::string& path, const std::string& what) {
  throw InputError(fmt::format("{}: not a readable rfmems checkpoint: {}", path, what));
}

double read_double_attribute(hid_t object, const std::string& name, const std::string& path) {
  if (H5Aexists(object, name.c_str()) <= 0) malformed(path, "no attribute '" + name + "'");
  H5Handle a(H5Aopen(object, name.c_str(), H5P_DEFAULT), H5Aclose);
  double value = 0;
  if (!a.valid() || H5Aread(a.get(), H5T_NATIVE_DOUBLE, &value) < 0)
    malformed(path, "attribute '" + name + "' is not a number");
  return value;
}

std::string read_string_attribute(hid_t object, const std::string& name, const std::string& path) {
  if (H5Aexists(object, name.c_str()) <= 0) malformed(path, "no attribute '" + name + "'");
  H5Handle a(H5Aopen(object, name.c_str(), H5P_DEFAULT), H5Aclose);
  H5Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), H5T_VARIABLE);
  H5Tset_cset(type.get(), H5T_CSET_UTF8);
  char* text = nullptr;
  if (!a.valid() || H5Aread(a.get(), type.get(), &text) < 0 || text == nullptr)
    malformed(path, "attribute '" + name + "' is not a string");
  std::string value(text);
  H5free_memory(text);
  return value;
}

std::vector<double> read_vector(hid_t location, const std::string& name, const std::string& path) {
  H5Handle set(H5Dopen2(location, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (!set.valid()) malformed(path, "no dataset '" + name + "'");
  H5Handle space(H5Dget_space(set.get()), H5Sclose);
  if (!space.valid() || H5Sget_simple_extent_ndims(space.get()) != 1)
    malformed(path, "dataset '" + name + "' is not a vector");
  hsize_t n = 0;
  H5Sget_simple_extent_dims(space.get(), &n, nullptr);
  std::vector<double> v(n);
  if (n > 0 && H5Dread(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) < 0)
    malformed(path, "dataset '" + name + "' cannot be read");
  return v;
}

struct VisitContext {
  std::vector<std::string> datasets;
};

herr_t collect_datasets(hid_t, const char* name, const H5O_info_t* info, void* data) {
  if (info->type == H5O_TYPE_DATASET) static_cast<VisitContext*>(data)->datasets.emplace_back(name);
  return 0;
}

}  // namespace

void write_checkpoint(const std::string& path, const Checkpoint& cp) {
  silence_hdf5_errors();
  create_parent_directory(path);
  const std::string temp = temp_path_for(path);
  try {
    {
      const H5Handle access = file_access(path);
      H5Handle file(check_id(H5Fcreate(temp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get()),
                             path, "creating " + temp),
                    H5Fclose);
      const hid_t f = file.get();
      write_attribute(f, "format", std::string(kFormat), path);
      write_attribute(f, "format_version", kFormatVersion, path);
      write_attribute(f, "time", cp.time, path);
      write_attribute(f, "settings_hash", cp.settings_hash, path);
      write_vector(f, "state", cp.state, path);
      write_vector(f, "state_dot", cp.state_dot, path);
      H5Handle numbers(check_id(H5Gcreate2(f, "numbers", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                                path, "creating group 'numbers'"),
                       H5Gclose);
      for (const auto& [name, value] : cp.numbers)
        write_attribute(numbers.get(), name, value, path);
      H5Handle arrays(check_id(H5Gcreate2(f, "arrays", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), path,
                               "creating group 'arrays'"),
                      H5Gclose);
      for (const auto& [name, values] : cp.arrays) write_vector(arrays.get(), name, values, path);
      arrays.reset();
      numbers.reset();
      // A failed close (the final flush) must not be renamed into place.
      check_status(file.reset(), path, "closing " + temp);
    }
    rename_file(temp, path);
  } catch (...) {
    std::remove(temp.c_str());
    throw;
  }
}

Checkpoint read_checkpoint(const std::string& path) {
  silence_hdf5_errors();
  if (!std::filesystem::is_regular_file(path))
    throw InputError(fmt::format("{}: checkpoint file not found", path));
  if (H5Fis_hdf5(path.c_str()) <= 0) malformed(path, "not an HDF5 file");
  const H5Handle access = file_access(path);
  H5Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, access.get()), H5Fclose);
  if (!file.valid()) malformed(path, "cannot open it");
  const hid_t f = file.get();
  if (read_string_attribute(f, "format", path) != kFormat)
    malformed(path, "format is not '" + std::string(kFormat) + "'");
  const double version = read_double_attribute(f, "format_version", path);
  if (version != kFormatVersion)
    malformed(path,
              fmt::format("format version {} (this build reads {})", version, kFormatVersion));

  Checkpoint cp;
  cp.time = read_double_attribute(f, "time", path);
  cp.settings_hash = read_string_attribute(f, "settings_hash", path);
  cp.state = read_vector(f, "state", path);
  cp.state_dot = read_vector(f, "state_dot", path);
  if (cp.state.size() != cp.state_dot.size()) malformed(path, "state and state_dot differ in size");

  H5Handle numbers(H5Gopen2(f, "numbers", H5P_DEFAULT), H5Gclose);
  if (!numbers.valid()) malformed(path, "no group 'numbers'");
  H5O_info_t info;
  if (H5Oget_info2(numbers.get(), &info, H5O_INFO_NUM_ATTRS) < 0)
    malformed(path, "group 'numbers'");
  for (hsize_t k = 0; k < info.num_attrs; ++k) {
    const ssize_t length = H5Aget_name_by_idx(numbers.get(), ".", H5_INDEX_NAME, H5_ITER_INC, k,
                                              nullptr, 0, H5P_DEFAULT);
    if (length < 0) malformed(path, "group 'numbers'");
    std::string name(static_cast<std::size_t>(length) + 1, '\0');
    H5Aget_name_by_idx(numbers.get(), ".", H5_INDEX_NAME, H5_ITER_INC, k, name.data(), name.size(),
                       H5P_DEFAULT);
    name.resize(static_cast<std::size_t>(length));
    cp.numbers[name] = read_double_attribute(numbers.get(), name, path);
  }

  H5Handle arrays(H5Gopen2(f, "arrays", H5P_DEFAULT), H5Gclose);
  if (!arrays.valid()) malformed(path, "no group 'arrays'");
  VisitContext context;
  if (H5Ovisit2(arrays.get(), H5_INDEX_NAME, H5_ITER_INC, collect_datasets, &context,
                H5O_INFO_BASIC) < 0)
    malformed(path, "group 'arrays' cannot be listed");
  for (const std::string& name : context.datasets)
    cp.arrays[name] = read_vector(arrays.get(), name, path);
  return cp;
}

std::string settings_hash(std::string_view text) {
  std::uint64_t h = 14695981039346656037ull;  // FNV-1a 64 offset basis
  for (const unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ull;  // FNV prime
  }
  return fmt::format("{:016x}", h);
}

std::string case_settings_hash(const CaseFile& file, const std::string& section,
                               const std::string& key) {
  YAML::Node root = YAML::Load(file.effective_text());
  if (root[section] && root[section].IsMap()) root[section].remove(key);
  YAML::Emitter out;
  out << root;
  return settings_hash(out.c_str());
}

std::string checkpoint_path_for(const std::string& result) {
  const std::string stem = result.ends_with(".h5") ? result.substr(0, result.size() - 3) : result;
  return stem + ".checkpoint.h5";
}

}  // namespace rfmems
