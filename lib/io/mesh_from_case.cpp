// mesh_from_case: reads the `mesh:` section and calls the structured generator, the gmsh
// runner or the MSH reader. Only validation and error wording live here.
#include "io/mesh_from_case.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>

#include "core/error.hpp"
#include "io/interrupt_cleanup.hpp"
#include "mesh/gmsh_reader.hpp"
#include "mesh/gmsh_runner.hpp"
#include "mesh/structured_mesh.hpp"

namespace rfmems {

namespace {

namespace fs = std::filesystem;

// A sequence of exactly `dim` lengths under key (positive ones if `positive`).
std::vector<Real> read_lengths(const CaseNode& node, const std::string& key, int dim,
                               bool positive) {
  const std::vector<Real> v = node.get_quantities(key, Dimension::Length);
  node.require(static_cast<int>(v.size()) == dim, key,
               fmt::format("expected {} lengths (one per axis)", dim));
  for (Real x : v) node.require(!positive || x > 0, key, "every length must be > 0");
  return v;
}

Mesh structured_mesh(const CaseNode& node, int dim) {
  BoxSpec spec;
  spec.dim = dim;
  const std::vector<Real> size = read_lengths(node, "size", dim, true);
  const std::vector<Real> lower =
      node.has("lower") ? read_lengths(node, "lower", dim, false) : std::vector<Real>(dim, 0.0);

  const std::vector<Real> cells = node.get_reals("cells");
  node.require(static_cast<int>(cells.size()) == dim, "cells",
               fmt::format("expected {} cell counts (one per axis)", dim));
  for (Real n : cells)
    node.require(n >= 1 && n == std::floor(n) && n <= 1e6, "cells",
                 "every cell count must be an integer in [1, 1000000]");

  std::vector<Real> grading(dim, 1.0);
  if (node.has("grading")) {
    grading = node.get_reals("grading");
    node.require(static_cast<int>(grading.size()) == dim, "grading",
                 fmt::format("expected {} ratios (one per axis)", dim));
    for (Real g : grading) node.require(g > 0, "grading", "every ratio must be > 0");
  }

  for (int d = 0; d < dim; ++d) {
    spec.lower[d] = lower[d];
    spec.upper[d] = lower[d] + size[d];
    spec.n[d] = static_cast<int>(cells[d]);
    spec.grading[d] = grading[d];
  }
  return make_structured_mesh(spec);
}

// A scratch directory for gmsh's output, removed (with its contents) when this goes away.
class ScratchDirectory {
 public:
  ScratchDirectory() {
    static std::atomic<int> counter{0};
    path_ = fs::temp_directory_path() /
            fmt::format("rfmems-mesh-{}-{}", static_cast<long>(::getpid()), counter++);
    fs::create_directories(path_);
    remove_on_interrupt_.emplace(path_.string(), RemoveOnInterrupt::Kind::Directory);
  }
  ~ScratchDirectory() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  ScratchDirectory(const ScratchDirectory&) = delete;
  ScratchDirectory& operator=(const ScratchDirectory&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
  std::optional<RemoveOnInterrupt> remove_on_interrupt_;  // the files in it register their own
};

Mesh gmsh_mesh(const CaseNode& node, const std::string& case_dir) {
  const std::string file = node.get_string("file");
  node.require(!file.empty(), "file", "expected a file name");
  fs::path path(file);
  if (path.is_relative() && !case_dir.empty()) path = fs::path(case_dir) / path;
  const std::string ext = path.extension().string();
  node.require(ext == ".geo" || ext == ".msh", "file", "expected a .geo or .msh file");

  const bool geo = ext == ".geo";
  const int dim = static_cast<int>(node.get_int("dim", geo ? 2 : 0, Range::closed(2, 3)));
  std::map<std::string, double> numbers;
  if (node.has("parameters")) {
    node.require(geo, "parameters", "parameters are passed to gmsh, so only for a .geo file");
    const CaseNode parameters = node.child("parameters");
    for (const std::string& name : parameters.keys())
      numbers[name] = parameters.get_real(name);
  }

  // Problems with the mesh file: keep the message (it names the mesh file) and the type, and
  // say which case key pointed at it.
  auto with_key = [&](const InputError& e) {
    return fmt::format("{}: key '{}' = '{}': {}", node.file(), node.key_path("file"), file,
                       e.what());
  };
  try {
    if (!geo) return read_gmsh_mesh(path.string(), dim);
    const ScratchDirectory scratch;
    const std::string msh = (scratch.path() / (path.stem().string() + ".msh")).string();
    const RemoveOnInterrupt remove_msh(msh, RemoveOnInterrupt::Kind::File);
    return read_gmsh_mesh(generate_gmsh_mesh(path.string(), numbers, msh, dim), dim);
  } catch (const MeshError& e) {
    throw MeshError(with_key(e));
  } catch (const InputError& e) {
    throw InputError(with_key(e));
  }
}

}  // namespace

Mesh mesh_from_case(const CaseNode& mesh_node, const std::string& case_dir) {
  const std::string type = mesh_node.get_choice("type", {"rectangle", "box", "gmsh"});
  if (type == "rectangle") return structured_mesh(mesh_node, 2);
  if (type == "box") return structured_mesh(mesh_node, 3);
  return gmsh_mesh(mesh_node, case_dir);
}

}  // namespace rfmems
