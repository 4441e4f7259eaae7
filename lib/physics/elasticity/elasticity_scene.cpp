// Building an ElasticityScene from a case: each boundary type is read by its own small
// function, chosen by name from a table.
#include "physics/elasticity/elasticity_scene.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <map>
#include <vector>

#include "core/error.hpp"
#include "io/mesh_from_case.hpp"
#include "io/point_locator.hpp"
#include "physics/structure/case_conditions.hpp"
#include "physics/structure/residual_stress.hpp"
#include "physics/structure/structural_analysis.hpp"

namespace rfmems {

std::string to_string(StressMethod method) {
  return method == StressMethod::Coupled ? "coupled" : "segregated";
}

namespace {

using Kind = ElasticityBoundary::Kind;

// What a boundary entry needs to know besides its own node.
struct PatchContext {
  const Mesh& mesh;
  int patch;
};

struct BoundaryEntry {
  ElasticityBoundary bc;
  Real ramp = 0;
};

// A `value` vector with one entry per mesh dimension.
Vec3 read_vector(const CaseNode& entry, Dimension d, int dim) {
  const Vec3 v = entry.get_vec3_quantity("value", d);
  entry.require(static_cast<int>(entry.child("value").size()) == dim, "value",
                fmt::format("expected {} components (the mesh is {}D)", dim, dim));
  return v;
}

VectorField ramped_constant(const Vec3& value, Real ramp) {
  return [value, ramp](const Vec3&, Real t) -> Vec3 { return ramp_factor(t, ramp) * value; };
}

BoundaryEntry read_fixed(const CaseNode& entry, const PatchContext& ctx) {
  BoundaryEntry b;
  b.bc.kind = Kind::Fixed;
  if (entry.has("value")) {
    b.ramp = read_ramp(entry);
    b.bc.value = ramped_constant(read_vector(entry, Dimension::Length, ctx.mesh.dim()), b.ramp);
  }
  return b;
}

BoundaryEntry read_traction(const CaseNode& entry, const PatchContext& ctx) {
  BoundaryEntry b;
  b.bc.kind = Kind::Traction;
  b.ramp = read_ramp(entry);
  b.bc.value = ramped_constant(read_vector(entry, Dimension::Pressure, ctx.mesh.dim()), b.ramp);
  return b;
}

BoundaryEntry read_free(const CaseNode&, const PatchContext&) {
  return {{Kind::Traction, {}}, 0.0};
}

BoundaryEntry read_symmetry(const CaseNode&, const PatchContext&) {
  return {{Kind::Symmetry, {}}, 0.0};
}

// Pressure p: the traction -p n with n the outward unit normal of the face. The operator
// evaluates a traction at a face centroid, so the normal is that of the face whose centroid
// is nearest to the point asked about (exactly that face for the centroids themselves).
BoundaryEntry read_pressure(const CaseNode& entry, const PatchContext& ctx) {
  const Real p = entry.get_quantity("value", Dimension::Pressure);
  BoundaryEntry b;
  b.bc.kind = Kind::Traction;
  b.ramp = read_ramp(entry);
  const Patch& patch = ctx.mesh.patches()[ctx.patch];
  std::vector<Vec3> centroids, normals;
  for (Index f = patch.first_face; f < patch.first_face + patch.n_faces; ++f) {
    centroids.push_back(ctx.mesh.face_centroid(f));
    normals.push_back(ctx.mesh.face_area(f).normalized());
  }
  if (centroids.empty()) return b;  // an empty patch carries no load
  auto locator = std::make_shared<const PointLocator>(std::move(centroids), ctx.mesh.dim());
  b.bc.value = [locator, normals = std::move(normals), p, ramp = b.ramp](const Vec3& x,
                                                                         Real t) -> Vec3 {
    return -ramp_factor(t, ramp) * p * normals[locator->nearest(x)];
  };
  return b;
}

using BoundaryReader = std::function<BoundaryEntry(const CaseNode&, const PatchContext&)>;

const std::map<std::string, BoundaryReader>& boundary_readers() {
  static const std::map<std::string, BoundaryReader> readers = {
      {"fixed", read_fixed},       {"traction", read_traction}, {"free", read_free},
      {"symmetry", read_symmetry}, {"pressure", read_pressure},
  };
  return readers;
}

LinearElastic read_material(const CaseNode& root, AnalysisType analysis, int dim,
                            const std::string& structure_choice) {
  const CaseNode material = root.child("material");
  LinearElastic m;
  m.E = material.get_quantity("E", Dimension::Pressure, Range::positive());
  m.nu = material.get_real("nu", Range::open(-1.0, 0.5));
  // Only inertia needs the density; a static case may leave it out.
  m.rho = analysis != AnalysisType::Static
              ? material.get_quantity("density", Dimension::Density, Range::positive())
              : material.get_quantity("density", Dimension::Density, 0.0, Range::positive());

  const CaseNode model = root.child("model");
  static const std::map<std::string, Hypothesis> hypotheses = {
      {"plane_stress", Hypothesis::PlaneStress},
      {"plane_strain", Hypothesis::PlaneStrain},
      {"3d", Hypothesis::ThreeD},
  };
  // structure plane (2D meshes) or solid3d (3D); the hypothesis defaults from it.
  const std::string structure =
      structure_choice.empty() ? (dim == 3 ? "solid3d" : "plane") : structure_choice;
  const std::string name = model.get_choice("hypothesis", {"plane_stress", "plane_strain", "3d"},
                                            structure == "solid3d" ? "3d" : "plane_stress");
  m.hypothesis = hypotheses.at(name);
  const int needed = m.hypothesis == Hypothesis::ThreeD ? 3 : 2;
  model.require(needed == dim, "hypothesis",
                fmt::format("needs a {}D mesh, but the mesh is {}D", needed, dim));
  model.require((name == "3d") == (structure == "solid3d"), "hypothesis",
                fmt::format("'{}' does not fit model.structure '{}'", name, structure));
  // The film's plane is normal to the last axis: x in a plane section, x and y in 3D.
  m.residual_stress = read_residual_stress(material, dim, dim - 1);
  return m;
}

std::vector<ElasticityBoundary> read_boundaries(const CaseNode& root, const Mesh& mesh,
                                                Real& load_time) {
  std::vector<std::string> types;
  for (const auto& [name, reader] : boundary_readers()) types.push_back(name);
  const std::vector<CaseNode> entries = patch_entries(root.child("boundaries"), mesh);
  std::vector<ElasticityBoundary> bcs(entries.size());
  load_time = 0;
  for (std::size_t p = 0; p < entries.size(); ++p) {
    const std::string type = entries[p].get_choice("type", types);
    BoundaryEntry b = boundary_readers().at(type)(entries[p], {mesh, static_cast<int>(p)});
    bcs[p] = std::move(b.bc);
    load_time = std::max(load_time, b.ramp);
  }
  return bcs;
}

VectorField read_body_force(const CaseNode& root, int dim) {
  if (!root.has("body_force")) return {};
  const Vec3 b = root.get_vec3("body_force");
  root.require(static_cast<int>(root.child("body_force").size()) == dim, "body_force",
               fmt::format("expected {} components in N/m^3 (the mesh is {}D)", dim, dim));
  if (b.isZero()) return {};
  return [b](const Vec3&, Real) -> Vec3 { return b; };
}

SegregatedOptions read_segregated(const CaseNode& root) {
  SegregatedOptions options;
  const CaseNode node = root.child_or_empty("solver").child_or_empty("segregated");
  const std::string kappa = node.get_choice("diffusivity", {"mu", "2mu+lambda"}, "2mu+lambda");
  options.diffusivity = kappa == "mu" ? SegregatedOptions::Diffusivity::Mu
                                      : SegregatedOptions::Diffusivity::TwoMuPlusLambda;
  options.relaxation = node.get_real("relaxation", 1.0, Range{0.0, 1.0, true, false});
  return options;
}

}  // namespace

ElasticityScene build_elasticity_scene(const CaseNode& root, const std::string& case_dir,
                                       AnalysisType analysis, const std::string& structure,
                                       bool geometric_nonlinearity) {
  ElasticityScene scene;
  scene.mesh = std::make_unique<Mesh>(mesh_from_case(root.child("mesh"), case_dir));
  const int dim = scene.mesh->dim();
  scene.material = read_material(root, analysis, dim, structure);

  const CaseNode model = root.child("model");
  scene.stress = model.get_choice("stress", {"coupled", "segregated"}, "coupled") == "coupled"
                     ? StressMethod::Coupled
                     : StressMethod::Segregated;
  if (scene.stress == StressMethod::Segregated) {
    model.require(analysis == AnalysisType::Static, "stress",
                  "the segregated method is for static analyses only (analysis.type static)");
    scene.segregated = read_segregated(root);
    model.require(!geometric_nonlinearity, "stress",
                  "the segregated method is for small deformations (model.geometric_nonlinearity "
                  "is true)");
  }

  // Face-gradient reconstruction: linear (the thesis's scheme), quadratic or cubic; the
  // default depends on the dimension (see ElasticityOperator).
  const std::map<std::string, int> degrees{
      {"default", 0}, {"linear", 1}, {"quadratic", 2}, {"cubic", 3}};
  const int degree = degrees.at(
      model.get_choice("reconstruction", {"default", "linear", "quadratic", "cubic"}, "default"));

  std::vector<ElasticityBoundary> bcs = read_boundaries(root, *scene.mesh, scene.load_time);
  if (geometric_nonlinearity)
    for (const CaseNode& entry : patch_entries(root.child("boundaries"), *scene.mesh))
      entry.require(entry.get_string("type") != "pressure", "type",
                    "a pressure follows the deformed surface, and the large-deformation model "
                    "(model.geometric_nonlinearity) has dead loads only: use a traction");
  require_released_edges_free(
      root.child("material"), scene.material.residual_stress, *scene.mesh,
      [&](int p) { return bcs[p].kind == ElasticityBoundary::Kind::Traction; });
  VectorField body_force = read_body_force(root, dim);
  scene.op = std::make_unique<ElasticityOperator>(*scene.mesh, scene.material, std::move(bcs),
                                                  std::move(body_force), degree);
  // Grid damping: the damping ratio at the grid's highest frequency of the Kelvin-Voigt
  // damping that keeps the stiffness's growing grid-scale modes decaying (ElasticityOperator::
  // grid_damping_time; docs/immersed_switch.md, "Grid damping"). 0: undamped.
  scene.op->set_geometric_nonlinearity(geometric_nonlinearity);
  scene.op->set_damping_time(scene.op->grid_damping_time(
      model.get_real("grid_damping", kGridDamping, Range::closed(0.0, 1.0))));
  return scene;
}

// ---- StructuralModel -----------------------------------------------------------------------

std::string ElasticityScene::kind() const {
  switch (material.hypothesis) {
    case Hypothesis::PlaneStress:
      return "plane_stress";
    case Hypothesis::PlaneStrain:
      return "plane_strain";
    case Hypothesis::ThreeD:
      return "3d";
  }
  return "?";
}

bool ElasticityScene::solve_static_otherwise(Real t, const AnalysisSettings& settings,
                                             std::vector<Real>& y, AnalysisStats& stats) {
  if (stress != StressMethod::Segregated) return false;
  SegregatedOptions options = segregated;
  options.relative_tolerance = settings.tolerance;
  options.max_outer_iterations = static_cast<int>(settings.max_iterations);
  stats.segregated = solve_segregated(*op, t, y, options);
  if (!stats.segregated.converged)
    throw SolverError(fmt::format(
        "segregated solver: no convergence after {} outer iterations (residual {:.3e} -> "
        "{:.3e}, wanted a reduction to {:g}); raise solver.max_iterations or lower "
        "solver.segregated.relaxation",
        stats.segregated.outer_iterations, stats.segregated.initial_residual,
        stats.segregated.final_residual, settings.tolerance));
  return true;
}

namespace {

// n_cells x 3 rows from the interleaved (cell * dim + k) unknowns; z = 0 in 2D.
std::vector<double> as_vectors(std::span<const Real> u, Index n_cells, int dim) {
  std::vector<double> out(static_cast<std::size_t>(3 * n_cells), 0.0);
  for (Index c = 0; c < n_cells; ++c)
    for (int k = 0; k < dim; ++k) out[3 * c + k] = u[c * dim + k];
  return out;
}

}  // namespace

void ElasticityScene::write_fields(ResultWriter& writer, int index, Real t, std::span<const Real> u,
                                   std::span<const Real> v) const {
  const Index nc = mesh->n_cells();
  const int dim = mesh->dim();
  writer.write_cell_field_at(index, t, "displacement", as_vectors(u, nc, dim), 3,
                             {"ux", "uy", "uz"});
  if (!v.empty())
    writer.write_cell_field_at(index, t, "velocity", as_vectors(v, nc, dim), 3, {"vx", "vy", "vz"});
  const std::vector<Mat3> gradients = op->cell_gradients(t, u);
  std::vector<double> stress(static_cast<std::size_t>(6 * nc));
  for (Index c = 0; c < nc; ++c) {
    const Mat3 s = material.residual_stress + material.stress(gradients[c]);
    const double voigt[6] = {s(0, 0), s(1, 1), s(2, 2), s(1, 2), s(0, 2), s(0, 1)};
    std::copy(voigt, voigt + 6, stress.begin() + 6 * c);
  }
  writer.write_cell_field_at(index, t, "stress", stress, 6, {"xx", "yy", "zz", "yz", "xz", "xy"});
}

std::vector<Vec3> ElasticityScene::probe_values(const std::vector<Probe>& probes, Real t,
                                                std::span<const Real> u) const {
  std::vector<Vec3> values;
  if (probes.empty()) return values;
  const std::vector<Mat3> gradients = op->cell_gradients(t, u);
  for (const Probe& p : probes) values.push_back(op->displacement_at(p.cell, p.at, u, gradients));
  return values;
}

std::vector<GapElement> ElasticityScene::gap_elements(const std::string& patch_name) const {
  const int p = mesh->find_patch(patch_name);
  if (p < 0)
    throw InputError(fmt::format("the mesh has no patch '{}' facing the electrode", patch_name));
  const Patch& patch = mesh->patches()[p];
  const int dim = mesh->dim();
  std::vector<GapElement> elements;
  for (Index f = patch.first_face; f < patch.first_face + patch.n_faces; ++f) {
    const Index owner = mesh->face_owner(f);
    if (owner >= mesh->n_owned_cells()) continue;
    GapElement e{owner * dim + (dim - 1),
                 mesh->face_area(f).norm(),
                 Vec3::Constant(std::numeric_limits<Real>::infinity()),
                 Vec3::Constant(-std::numeric_limits<Real>::infinity()),
                 {}};
    for (Index node : mesh->face_nodes(f)) {
      e.lo = e.lo.cwiseMin(mesh->nodes()[node]);
      e.hi = e.hi.cwiseMax(mesh->nodes()[node]);
    }
    elements.push_back(e);
  }
  return elements;
}

}  // namespace rfmems
