// ResultWriter: HDF5 layout of result files and their atomic completion (see the header).
#include "io/result_writer.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <filesystem>
#include <optional>
#include <set>
#include <stdexcept>

#include "io/atomic_file.hpp"
#include "io/build_info.hpp"
#include "io/hdf5_util.hpp"
#include "io/quantity_units.hpp"
#include "io/xdmf.hpp"

namespace rfmems {

namespace {

constexpr long long kFormatVersion = 1;

// XDMF cell type ids (the node order of Gmsh/VTK linear cells is XDMF's too).
long long xdmf_type(CellShape shape) {
  switch (shape) {
    case CellShape::Polygon:
      return 3;
    case CellShape::Triangle:
      return 4;
    case CellShape::Quad:
      return 5;
    case CellShape::Tetra:
      return 6;
    case CellShape::Pyramid:
      return 7;
    case CellShape::Prism:
      return 8;
    case CellShape::Hexa:
      return 9;
  }
  throw std::logic_error("xdmf_type: unknown cell shape");
}

H5Handle create_group(hid_t location, const std::string& name, const std::string& file) {
  return H5Handle(
      check_id(H5Gcreate2(location, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), file,
               "creating group '" + name + "'"),
      H5Gclose);
}

// An HDF5 object name must not contain '/' (it would nest) nor be "." or empty.
bool plain_name(const std::string& s) {
  return !s.empty() && s != "." && s.find('/') == std::string::npos;
}

}  // namespace

struct ResultWriter::Impl {
  std::string path, xdmf_path, temp_path;
  H5Handle file, metadata;
  Index n_cells = 0, n_nodes = 0, topology_length = 0;
  std::map<int, XdmfStep> steps;      // by step index
  std::set<std::string> time_series;  // "<group>/<name>" written so far
  bool created = false;               // the temporary exists and is ours to delete
  bool finished = false;

  ~Impl() {
    if (finished || !created) return;
    metadata.reset();
    file.reset();
    std::remove(temp_path.c_str());
  }

  [[noreturn]] void misuse(const std::string& what) const {
    throw std::invalid_argument(path + ": " + what);
  }
};

ResultWriter::ResultWriter(const std::string& path, const Mesh& mesh)
    : impl_(std::make_unique<Impl>()) {
  Impl& w = *impl_;
  w.path = path;
  w.xdmf_path = ResultWriter::sidecar_path(path);
  w.temp_path = temp_path_for(path);
  silence_hdf5_errors();
  create_parent_directory(path);
  // A result left by an earlier run must not pass for this run's if this one fails.
  std::remove(w.path.c_str());
  std::remove(w.xdmf_path.c_str());

  H5Handle access(check_id(H5Pcreate(H5P_FILE_ACCESS), path, "creating the file"), H5Pclose);
  // Closing the file closes anything still open in it, so a close cannot fail on a leak.
  check_status(H5Pset_fclose_degree(access.get(), H5F_CLOSE_STRONG), path, "creating the file");
#if H5_VERSION_GE(1, 10, 7)
  // Only this process touches the temporary; locking would just fail on NFS and Lustre.
  check_status(H5Pset_file_locking(access.get(), false, true), path, "creating the file");
#endif
  w.file =
      H5Handle(check_id(H5Fcreate(w.temp_path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get()),
                        path, "creating " + w.temp_path),
               H5Fclose);
  w.created = true;
  const hid_t f = w.file.get();
  write_attribute(f, "format", std::string("rfmems-result"), path);
  write_attribute(f, "format_version", kFormatVersion, path);

  // Mesh.
  w.n_cells = mesh.n_owned_cells();
  w.n_nodes = mesh.n_nodes();
  std::vector<double> nodes;
  nodes.reserve(static_cast<std::size_t>(3 * w.n_nodes));
  for (const Vec3& x : mesh.nodes()) nodes.insert(nodes.end(), {x.x(), x.y(), x.z()});
  std::vector<long long> topology;
  std::vector<double> centroids, volumes;
  for (Index c = 0; c < w.n_cells; ++c) {
    const auto cell_nodes = mesh.cell_nodes(c);
    topology.push_back(xdmf_type(mesh.cell_shape(c)));
    if (mesh.cell_shape(c) == CellShape::Polygon)
      topology.push_back(static_cast<long long>(cell_nodes.size()));
    topology.insert(topology.end(), cell_nodes.begin(), cell_nodes.end());
    const Vec3& x = mesh.cell_centroid(c);
    centroids.insert(centroids.end(), {x.x(), x.y(), x.z()});
    volumes.push_back(mesh.cell_volume(c));
  }
  w.topology_length = static_cast<Index>(topology.size());
  const auto n = static_cast<hsize_t>(w.n_nodes), nc = static_cast<hsize_t>(w.n_cells);
  const H5Handle mesh_group = create_group(f, "mesh", path);
  write_dataset(mesh_group.get(), "nodes", H5T_NATIVE_DOUBLE, nodes.data(), {n, 3}, path);
  write_dataset(mesh_group.get(), "topology", H5T_NATIVE_LLONG, topology.data(), {topology.size()},
                path);
  write_dataset(mesh_group.get(), "cell_centroids", H5T_NATIVE_DOUBLE, centroids.data(), {nc, 3},
                path);
  write_dataset(mesh_group.get(), "cell_volumes", H5T_NATIVE_DOUBLE, volumes.data(), {nc}, path);
  write_attribute(mesh_group.get(), "dim", static_cast<long long>(mesh.dim()), path);
  write_attribute(mesh_group.get(), "n_cells", static_cast<long long>(w.n_cells), path);
  write_attribute(mesh_group.get(), "n_nodes", static_cast<long long>(w.n_nodes), path);

  create_group(f, "fields", path);
  w.metadata = create_group(f, "metadata", path);
  write_attribute(w.metadata.get(), "git_hash", std::string(git_hash()), path);
}

ResultWriter::~ResultWriter() = default;  // Impl deletes the temporary if unfinished

void ResultWriter::write_cell_field_at(int step_index, double time, const std::string& name,
                                       const std::vector<double>& values, int n_components,
                                       const std::vector<std::string>& component_names) {
  Impl& w = *impl_;
  if (w.finished) w.misuse("write_cell_field_at after finish()");
  if (!plain_name(name)) w.misuse(fmt::format("invalid field name '{}'", name));
  if (n_components != 1 && n_components != 3 && n_components != 6 && n_components != 9)
    w.misuse(fmt::format("field '{}' has {} components (need 1, 3, 6 or 9)", name, n_components));
  if (step_index < 0) w.misuse(fmt::format("field '{}': negative step index {}", name, step_index));
  if (!component_names.empty() && component_names.size() != static_cast<std::size_t>(n_components))
    w.misuse(fmt::format("field '{}': {} component names for {} components", name,
                         component_names.size(), n_components));
  const std::size_t needed =
      static_cast<std::size_t>(w.n_cells) * static_cast<std::size_t>(n_components);
  if (values.size() < needed || values.size() % static_cast<std::size_t>(n_components) != 0)
    w.misuse(fmt::format("field '{}' has {} values, expected {} ({} cells × {})", name,
                         values.size(), needed, w.n_cells, n_components));

  const std::optional<std::string> units = units_of(name);
  if (!units) w.misuse(fmt::format("field '{}' has no units (io/quantity_units.cpp)", name));

  const std::string group = fmt::format("fields/{:06d}", step_index);
  const std::string dataset = group + "/" + name;
  auto [it, new_step] = w.steps.try_emplace(step_index, XdmfStep{time, {}});
  XdmfStep& step = it->second;
  if (step.time != time)
    w.misuse(fmt::format("field '{}' at step {} with time {}, but the step has time {}", name,
                         step_index, time, step.time));
  for (const auto& f : step.fields)
    if (f.name == name)
      w.misuse(fmt::format("field '{}' written twice at step {}", name, step_index));

  const H5Handle set =
      write_dataset(w.file.get(), dataset, H5T_NATIVE_DOUBLE, values.data(),
                    {static_cast<hsize_t>(w.n_cells), static_cast<hsize_t>(n_components)}, w.path);
  write_attribute(set.get(), "time", time, w.path);
  write_attribute(set.get(), "units", *units, w.path);
  if (!component_names.empty()) write_attribute(set.get(), "components", component_names, w.path);
  if (new_step) {
    H5Handle g(
        check_id(H5Gopen2(w.file.get(), group.c_str(), H5P_DEFAULT), w.path, "opening " + group),
        H5Gclose);
    write_attribute(g.get(), "time", time, w.path);
    write_attribute(g.get(), "step", static_cast<long long>(step_index), w.path);
  }
  step.fields.push_back({name, "/" + dataset, n_components});
}

void ResultWriter::write_time_series(const std::string& group, const std::string& name,
                                     const std::vector<double>& t,
                                     const std::vector<std::vector<double>>& values,
                                     const std::vector<std::string>& component_names,
                                     const std::string& abscissa,
                                     const std::vector<std::string>& component_units) {
  Impl& w = *impl_;
  if (w.finished) w.misuse("write_time_series after finish()");
  std::string g = group;
  while (g.starts_with('/')) g.erase(0, 1);
  while (g.ends_with('/')) g.pop_back();
  if (g.empty() || g == "mesh" || g == "fields" || g == "metadata" ||
      g.find("//") != std::string::npos)
    w.misuse(fmt::format("invalid time series group '{}'", group));
  if (!plain_name(name)) w.misuse(fmt::format("invalid time series name '{}'", name));
  const std::string base = g + "/" + name;
  if (!w.time_series.insert(base).second)
    w.misuse(fmt::format("time series '{}' written twice", base));
  if (values.size() != t.size())
    w.misuse(
        fmt::format("time series '{}' has {} times but {} samples", base, t.size(), values.size()));
  const std::size_t n_comp = values.empty() ? 0 : values.front().size();
  std::vector<double> flat;
  flat.reserve(n_comp * values.size());
  for (const auto& row : values) {
    if (row.size() != n_comp)
      w.misuse(fmt::format("time series '{}': samples of {} and {} components", base, n_comp,
                           row.size()));
    flat.insert(flat.end(), row.begin(), row.end());
  }
  if (!component_names.empty() && component_names.size() != n_comp)
    w.misuse(fmt::format("time series '{}': {} component names for {} components", base,
                         component_names.size(), n_comp));

  if (!plain_name(abscissa) || abscissa == "values")
    w.misuse(fmt::format("invalid abscissa name '{}'", abscissa));
  const H5Handle x = write_dataset(w.file.get(), base + "/" + abscissa, H5T_NATIVE_DOUBLE, t.data(),
                                   {t.size()}, w.path);
  if (const auto units = units_of(abscissa)) write_attribute(x.get(), "units", *units, w.path);
  const H5Handle set = write_dataset(w.file.get(), base + "/values", H5T_NATIVE_DOUBLE, flat.data(),
                                     {t.size(), n_comp}, w.path);
  if (!component_names.empty()) write_attribute(set.get(), "components", component_names, w.path);
  // Units per component, given or by name ("" where neither says).
  std::vector<std::string> units = component_units;
  if (units.empty())
    for (const std::string& c : component_names) units.push_back(units_of(c).value_or(""));
  if (!units.empty() && units.size() != n_comp)
    w.misuse(
        fmt::format("time series '{}': {} units for {} components", base, units.size(), n_comp));
  if (!units.empty()) write_attribute(set.get(), "units", units, w.path);
}

void ResultWriter::write_metadata(const std::map<std::string, std::string>& strings,
                                  const std::map<std::string, double>& numbers) {
  Impl& w = *impl_;
  if (w.finished) w.misuse("write_metadata after finish()");
  for (const auto& [key, value] : strings) write_attribute(w.metadata.get(), key, value, w.path);
  for (const auto& [key, value] : numbers) write_attribute(w.metadata.get(), key, value, w.path);
}

void ResultWriter::finish() {
  Impl& w = *impl_;
  if (w.finished) return;
  std::vector<double> times;
  std::vector<long long> step_ids;
  std::vector<XdmfStep> steps;
  for (const auto& [index, step] : w.steps) {
    step_ids.push_back(index);
    times.push_back(step.time);
    steps.push_back(step);
  }
  write_dataset(w.file.get(), "fields/times", H5T_NATIVE_DOUBLE, times.data(), {times.size()},
                w.path);
  write_dataset(w.file.get(), "fields/steps", H5T_NATIVE_LLONG, step_ids.data(), {step_ids.size()},
                w.path);
  w.metadata.reset();
  check_status(w.file.reset(), w.path, "closing the file");

  const XdmfMesh mesh{std::filesystem::path(w.path).filename().string(), w.n_cells, w.n_nodes,
                      w.topology_length};
  write_file_atomic(w.xdmf_path, xdmf_text(mesh, steps));
  try {
    rename_file(w.temp_path, w.path);
  } catch (...) {
    std::remove(w.xdmf_path.c_str());  // no sidecar without its data
    throw;
  }
  w.finished = true;
}

const std::string& ResultWriter::path() const { return impl_->path; }
const std::string& ResultWriter::xdmf_path() const { return impl_->xdmf_path; }

std::string ResultWriter::sidecar_path(const std::string& path) {
  for (const char* ext : {".h5", ".hdf5"}) {
    const std::string e = ext;
    if (path.size() > e.size() && path.ends_with(e))
      return path.substr(0, path.size() - e.size()) + ".xdmf";
  }
  return path + ".xdmf";
}
bool ResultWriter::finished() const { return impl_->finished; }

}  // namespace rfmems
