// Building an ElasticityScene from a case: each boundary type is read by its own small
// function, chosen by name from a table.
#include "physics/elasticity/elasticity_scene.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <functional>
#include <map>
#include <vector>

#include "io/mesh_from_case.hpp"
#include "io/point_locator.hpp"

namespace rfmems {

std::string to_string(AnalysisType type) {
  return type == AnalysisType::Static ? "static" : "transient";
}

std::string to_string(StressMethod method) {
  return method == StressMethod::Coupled ? "coupled" : "segregated";
}

namespace {

using Kind = ElasticityBoundary::Kind;

// Linear ramp 0 -> 1 over [0, ramp], then 1 (always 1 without a ramp).
Real ramp_factor(Real t, Real ramp) { return ramp > 0 ? std::clamp(t / ramp, 0.0, 1.0) : 1.0; }

// What a boundary entry needs to know besides its own node.
struct PatchContext {
  const Mesh& mesh;
  int patch;
};

struct BoundaryEntry {
  ElasticityBoundary bc;
  Real ramp = 0;
};

Real read_ramp(const CaseNode& entry) {
  return entry.get_quantity("ramp", Dimension::Time, 0.0, Range::non_negative());
}

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

std::vector<std::string> patch_names(const Mesh& mesh) {
  std::vector<std::string> names;
  for (const Patch& p : mesh.patches()) names.push_back(p.name);
  return names;
}

LinearElastic read_material(const CaseNode& root, AnalysisType analysis, int dim) {
  const CaseNode material = root.child("material");
  LinearElastic m;
  m.E = material.get_quantity("E", Dimension::Pressure, Range::positive());
  m.nu = material.get_real("nu", Range::open(-1.0, 0.5));
  // Only inertia needs the density; a static case may leave it out.
  m.rho = analysis == AnalysisType::Transient
              ? material.get_quantity("density", Dimension::Density, Range::positive())
              : material.get_quantity("density", Dimension::Density, 0.0, Range::positive());

  const CaseNode model = root.child("model");
  static const std::map<std::string, Hypothesis> hypotheses = {
      {"plane_stress", Hypothesis::PlaneStress},
      {"plane_strain", Hypothesis::PlaneStrain},
      {"3d", Hypothesis::ThreeD},
  };
  const std::string name = model.get_choice("hypothesis", {"plane_stress", "plane_strain", "3d"});
  m.hypothesis = hypotheses.at(name);
  const int needed = m.hypothesis == Hypothesis::ThreeD ? 3 : 2;
  model.require(needed == dim, "hypothesis",
                fmt::format("needs a {}D mesh, but the mesh is {}D", needed, dim));
  return m;
}

std::vector<ElasticityBoundary> read_boundaries(const CaseNode& root, const Mesh& mesh,
                                                Real& load_time) {
  const CaseNode node = root.child("boundaries");
  const std::vector<std::string> patches = patch_names(mesh);
  const std::vector<std::string> given = node.keys();
  for (const std::string& key : given)
    if (mesh.find_patch(key) < 0)
      node.fail(key, fmt::format("the mesh has no patch '{}' (mesh patches: {})", key,
                                 fmt::join(patches, ", ")));

  std::vector<std::string> types;
  for (const auto& [name, reader] : boundary_readers()) types.push_back(name);

  std::vector<ElasticityBoundary> bcs(patches.size());
  load_time = 0;
  for (std::size_t p = 0; p < patches.size(); ++p) {
    if (!node.has(patches[p]))
      node.fail(patches[p],
                fmt::format("mesh patch '{}' has no boundary condition (given: {}; mesh "
                            "patches: {})",
                            patches[p], given.empty() ? "none" : fmt::format("{}", fmt::join(given, ", ")),
                            fmt::join(patches, ", ")));
    const CaseNode entry = node.child(patches[p]);
    const std::string type = entry.get_choice("type", types);
    BoundaryEntry b = boundary_readers().at(type)(entry, {mesh, static_cast<int>(p)});
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
                                       AnalysisType analysis) {
  ElasticityScene scene;
  scene.mesh = std::make_unique<Mesh>(mesh_from_case(root.child("mesh"), case_dir));
  const int dim = scene.mesh->dim();
  scene.material = read_material(root, analysis, dim);

  const CaseNode model = root.child("model");
  scene.stress = model.get_choice("stress", {"coupled", "segregated"}, "coupled") == "coupled"
                     ? StressMethod::Coupled
                     : StressMethod::Segregated;
  if (scene.stress == StressMethod::Segregated) {
    model.require(analysis == AnalysisType::Static, "stress",
                  "the segregated method is for static analyses only (analysis.type static)");
    scene.segregated = read_segregated(root);
  }

  // Face-gradient reconstruction: linear (the thesis's scheme), quadratic or cubic; the
  // default depends on the dimension (see ElasticityOperator).
  const std::map<std::string, int> degrees{
      {"default", 0}, {"linear", 1}, {"quadratic", 2}, {"cubic", 3}};
  const int degree = degrees.at(model.get_choice(
      "reconstruction", {"default", "linear", "quadratic", "cubic"}, "default"));

  std::vector<ElasticityBoundary> bcs = read_boundaries(root, *scene.mesh, scene.load_time);
  VectorField body_force = read_body_force(root, dim);
  scene.op = std::make_unique<ElasticityOperator>(*scene.mesh, scene.material, std::move(bcs),
                                                  std::move(body_force), degree);
  return scene;
}

}  // namespace rfmems
