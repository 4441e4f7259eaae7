// mesh_from_case: reads the `mesh:` section and calls the structured generator, the gmsh
// runner or the MSH reader. Only validation and error wording live here.
#include "io/mesh_from_case.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <sstream>

#include "core/error.hpp"
#include "io/case_schema_yaml.hpp"
#include "io/interrupt_cleanup.hpp"
#include "io/run_limits.hpp"
#include "mesh/gmsh_reader.hpp"
#include "mesh/gmsh_runner.hpp"
#include "mesh/structured_mesh.hpp"

namespace rfmems {

namespace {

namespace fs = std::filesystem;

// Memory per unknown of a run, Jacobian, factorisation and fields together: the slope of the
// peak resident set size over the number of unknowns, measured with /usr/bin/time -v on
// rfmems-solid cases/cantilever_static (2D static continuum, 2 unknowns per cell, sparse
// Jacobian of the cubic reconstruction with ~49 non-zeros per row, KLU factorisation): at
// mesh.cells = [400, 40] (32 000 unknowns) a peak of 341 MiB, at [800, 80] (128 000 unknowns)
// 1767 MiB, so 15.6 kB per unknown; 16 KiB is used. The factorisation's fill-in grows faster
// than the unknowns, so a larger mesh needs more per unknown: the estimate is a floor.
constexpr double kBytesPerUnknown = 16 * 1024;
// Every physics has at least one unknown per cell (the gas film's pressure; a plate has 3, a
// continuum one per axis), so cells x 1 x kBytesPerUnknown is a floor of what the run needs:
// a mesh refused for it cannot run on this machine.
constexpr double kMinUnknownsPerCell = 1;

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
  double n_cells = 1;
  for (Real n : cells) {
    node.require(n >= 1 && n == std::floor(n) && n <= 1e6, "cells",
                 "every cell count must be an integer in [1, 1000000]");
    n_cells *= n;
  }
  check_memory_estimate(node, "cells", n_cells * kMinUnknownsPerCell * kBytesPerUnknown,
                        fmt::format("a mesh of {:.4g} cells", n_cells));

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

// The names a .geo file lets -setnumber set: those of its DefineConstant[ name = ... ] entries
// and of its plain assignments "name = ...;".
std::set<std::string> geo_parameter_names(const fs::path& geo) {
  std::ifstream in(geo);
  std::stringstream text;
  text << in.rdbuf();
  // Comments out: a name in "// h = 0.2 gives ..." declares nothing.
  const std::string raw = text.str();
  std::string source;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    if (raw.compare(i, 2, "//") == 0) {
      i = raw.find('\n', i);
      if (i == std::string::npos) break;
    } else if (raw.compare(i, 2, "/*") == 0) {
      i = raw.find("*/", i + 2);
      if (i == std::string::npos) break;
      ++i;
      continue;
    }
    source += raw[i];
  }
  std::set<std::string> names;
  const std::regex define(R"(DefineConstant\s*\[([^\]]*)\])");
  const std::regex entry(R"((?:^|,)\s*([A-Za-z_]\w*)\s*=)");
  const std::regex assignment(R"((?:^|;|\n)\s*([A-Za-z_]\w*)\s*=[^=])");
  for (std::sregex_iterator d(source.begin(), source.end(), define), end; d != end; ++d) {
    // Only the top level of the brackets: "h = {0.2, Name \"...\"}" names h, not Name.
    std::string list = (*d)[1].str(), top;
    int depth = 0;
    for (char c : list) {
      depth += c == '{' ? 1 : c == '}' ? -1 : 0;
      top += depth > 0 && c != '{' ? ' ' : c;
    }
    for (std::sregex_iterator e(top.begin(), top.end(), entry); e != end; ++e)
      names.insert((*e)[1].str());
  }
  for (std::sregex_iterator a(source.begin(), source.end(), assignment), end; a != end; ++a)
    names.insert((*a)[1].str());
  return names;
}

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
    // A missing .geo is reported by the gmsh runner, with the mesh file's name.
    std::error_code ec;
    const bool readable = fs::is_regular_file(path, ec);
    const std::set<std::string> declared =
        readable ? geo_parameter_names(path) : std::set<std::string>{};
    for (const std::string& name : parameters.keys()) {
      if (readable && !declared.contains(name)) {
        std::string known;
        for (const std::string& d : declared) known += (known.empty() ? "" : ", ") + d;
        parameters.fail(name, fmt::format("{} declares no parameter '{}' (it declares: {})",
                                          path.string(), name, known));
      }
      numbers[name] = parameters.get_real(name);
    }
  }
  node.require(!is_result_path(path.string()), "file",
               fmt::format("is also the result file (-o {}): the run would overwrite its mesh",
                           result_path()));

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

CaseSchema mesh_case_keys() { return embedded_case_schema("io/mesh_from_case.keys.yaml"); }

}  // namespace rfmems
