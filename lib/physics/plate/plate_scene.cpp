// Building a PlateScene from a case: each boundary type is read by its own small function,
// chosen by name from a table (as the elasticity scene does).
#include "physics/plate/plate_scene.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>

#include "io/mesh_from_case.hpp"
#include "io/probes.hpp"
#include "physics/structure/case_conditions.hpp"
#include "physics/structure/residual_stress.hpp"

namespace rfmems {

namespace {

using Kind = PlateBoundary::Kind;

struct BoundaryEntry {
  PlateBoundary bc;
  Real ramp = 0;
};

// Optional ramp of a prescribed (w, beta_x, beta_y) or (Q.n, (M n)_x, (M n)_y).
BoundaryEntry ramped(Kind kind, const Vec3& value, const CaseNode& entry) {
  BoundaryEntry b;
  b.bc.kind = kind;
  b.ramp = read_ramp(entry);
  b.bc.value = [value, ramp = b.ramp](const Vec3&, Real t) -> Vec3 {
    return ramp_factor(t, ramp) * value;
  };
  return b;
}

// A pair of components, e.g. beta: [0, 0] or moment: [0 N, 0 N].
Vec3 read_pair(const CaseNode& entry, const std::string& key, Dimension d) {
  if (!entry.has(key)) return Vec3::Zero();
  const Vec3 v = entry.get_vec3_quantity(key, d);
  entry.require(entry.child(key).size() == 2, key, "expected 2 components (x, y)");
  return v;
}

// w [m] and beta [rad]: displacement (w required) and simple supports (w = 0 by default).
BoundaryEntry read_kinematic(Kind kind, const CaseNode& entry, bool w_required) {
  const Real w = w_required ? entry.get_quantity("w", Dimension::Length)
                            : entry.get_quantity("w", Dimension::Length, 0.0);
  const Vec3 beta = read_pair(entry, "beta", Dimension::Dimensionless);
  return ramped(kind, Vec3(w, beta.x(), beta.y()), entry);
}

// Shear force Q.n [N/m] and moment M n [N m/m = N] per unit edge length acting on the plate.
BoundaryEntry read_load(const CaseNode& entry) {
  const Real shear = entry.get_quantity("shear", Dimension::ForcePerLength, 0.0);
  const Vec3 moment = read_pair(entry, "moment", Dimension::Force);
  return ramped(Kind::Load, Vec3(shear, moment.x(), moment.y()), entry);
}

using BoundaryReader = std::function<BoundaryEntry(const CaseNode&)>;

const std::map<std::string, BoundaryReader>& boundary_readers() {
  static const std::map<std::string, BoundaryReader> readers = {
      {"clamped",
       [](const CaseNode&) {
         return BoundaryEntry{{Kind::Clamped, {}}, 0.0};
       }},
      {"free",
       [](const CaseNode&) {
         return BoundaryEntry{{Kind::Free, {}}, 0.0};
       }},
      {"simply_supported",
       [](const CaseNode& e) { return read_kinematic(Kind::SimplySupportedHard, e, false); }},
      {"simply_supported_soft",
       [](const CaseNode& e) { return read_kinematic(Kind::SimplySupportedSoft, e, false); }},
      {"displacement",
       [](const CaseNode& e) { return read_kinematic(Kind::Displacement, e, true); }},
      {"load", read_load},
  };
  return readers;
}

PlateSection read_section(const CaseNode& root, AnalysisType analysis) {
  const CaseNode material = root.child("material");
  const CaseNode model = root.child("model");
  PlateSection s;
  s.E = material.get_quantity("E", Dimension::Pressure, Range::positive());
  s.nu = material.get_real("nu", Range::open(-1.0, 0.5));
  s.rho = analysis != AnalysisType::Static
              ? material.get_quantity("density", Dimension::Density, Range::positive())
              : material.get_quantity("density", Dimension::Density, 0.0, Range::positive());
  s.thickness = model.get_quantity("thickness", Dimension::Length, Range::positive());
  s.shear_factor = model.get_real("shear_correction", 5.0 / 6.0, Range{0.0, 1.0, true, false});
  s.residual_stress = read_residual_stress(material, 2, 2);
  return s;
}

// Uniform pressure along +z, optionally ramped.
ScalarField read_pressure(const CaseNode& root, Real& load_time) {
  if (!root.has("pressure")) return {};
  const CaseNode node = root.child("pressure");
  const Real q = node.get_quantity("value", Dimension::Pressure);
  const Real ramp = read_ramp(node);
  load_time = std::max(load_time, ramp);
  return [q, ramp](const Vec3&, Real t) { return ramp_factor(t, ramp) * q; };
}

void add_point_loads(const CaseNode& root, const Mesh& mesh, PlateOperator& op, Real& load_time) {
  if (!root.has("point_loads")) return;
  const CaseNode list = root.child("point_loads");
  const CasePointFinder finder(mesh);
  for (std::size_t i = 0; i < list.size(); ++i) {
    const CaseNode item = list.item(i);
    const Index cell = finder.find(item, "at", fmt::format("point load {}", i + 1)).second;
    const Vec3 moment = read_pair(item, "moment", Dimension::Moment);
    const Vec3 load(item.get_quantity("force", Dimension::Force, 0.0), moment.x(), moment.y());
    const Real ramp = read_ramp(item);
    load_time = std::max(load_time, ramp);
    op.add_point_load(cell, [load, ramp](Real t) -> Vec3 { return ramp_factor(t, ramp) * load; });
  }
}

}  // namespace

PlateScene build_plate_scene(const CaseNode& root, const std::string& case_dir,
                             AnalysisType analysis, bool geometric_nonlinearity) {
  PlateScene scene;
  scene.mesh = std::make_unique<Mesh>(mesh_from_case(root.child("mesh"), case_dir));
  const CaseNode model = root.child("model");
  model.require(scene.mesh->dim() == 2, "structure",
                "a plate needs a 2D mesh of its mid-surface, but the mesh is 3D");
  scene.section = read_section(root, analysis);
  const std::map<std::string, int> degrees{{"linear", 1}, {"quadratic", 2}, {"cubic", 3}};
  const int degree =
      degrees.at(model.get_choice("reconstruction", {"linear", "quadratic", "cubic"}, "cubic"));

  std::vector<std::string> types;
  for (const auto& [name, reader] : boundary_readers()) types.push_back(name);
  std::vector<PlateBoundary> bcs;
  for (const CaseNode& entry : patch_entries(root.child("boundaries"), *scene.mesh)) {
    BoundaryEntry b = boundary_readers().at(entry.get_choice("type", types))(entry);
    // The von Karman plate's in-plane condition on an edge that holds w: immovable (u = 0) or
    // free (N n = 0).
    if (entry.has("in_plane")) {
      entry.require(geometric_nonlinearity, "in_plane",
                    "is for the von Karman plate (model.geometric_nonlinearity: true)");
      entry.require(b.bc.prescribes_deflection(), "in_plane",
                    "is for an edge that holds the deflection (free and loaded edges carry no "
                    "membrane force already)");
    }
    b.bc.in_plane_free = entry.get_choice("in_plane", {"immovable", "free"}, "immovable") == "free";
    bcs.push_back(std::move(b.bc));
    scene.load_time = std::max(scene.load_time, b.ramp);
  }
  // Edges that hold no deflection, or no in-plane displacement, hold no in-plane stress either.
  require_released_edges_free(
      root.child("material"), scene.section.residual_stress, *scene.mesh,
      [&](int p) { return !bcs[p].prescribes_deflection() || bcs[p].in_plane_free; });
  ScalarField pressure = read_pressure(root, scene.load_time);
  scene.op = std::make_unique<PlateOperator>(*scene.mesh, scene.section, std::move(bcs),
                                             std::move(pressure), degree);
  add_point_loads(root, *scene.mesh, *scene.op, scene.load_time);
  if (geometric_nonlinearity) scene.von_karman = std::make_unique<VonKarmanPlate>(*scene.op);
  return scene;
}

void PlateScene::write_fields(ResultWriter& writer, int index, Real t, std::span<const Real> y,
                              std::span<const Real> v) const {
  const Index nc = mesh->n_cells();
  std::vector<double> deflection(3 * nc, 0.0), rotation(3 * nc, 0.0), moment(3 * nc),
      shear(3 * nc, 0.0);
  const std::vector<Mat3> gradients = op->rotation_gradients(t, y);
  const std::vector<Vec3> q = op->shear_forces(t, y);
  for (Index c = 0; c < nc; ++c) {
    if (von_karman) {
      deflection[3 * c] = y[von_karman->in_plane_index(c, 0)];
      deflection[3 * c + 1] = y[von_karman->in_plane_index(c, 1)];
    }
    deflection[3 * c + 2] = y[3 * c + PlateOperator::kW];
    rotation[3 * c] = y[3 * c + PlateOperator::kBetaX];
    rotation[3 * c + 1] = y[3 * c + PlateOperator::kBetaY];
    const Mat3 M = op->moment(gradients[c]);
    moment[3 * c] = M(0, 0);
    moment[3 * c + 1] = M(1, 1);
    moment[3 * c + 2] = M(0, 1);
    shear[3 * c] = q[c].x();
    shear[3 * c + 1] = q[c].y();
  }
  if (von_karman)
    writer.write_cell_field_at(index, t, "deflection", deflection, 3, {"u", "v", "w"});
  else
    writer.write_cell_field_at(index, t, "deflection", deflection, 3, {"0", "0", "w"});
  writer.write_cell_field_at(index, t, "rotation", rotation, 3, {"beta_x", "beta_y", "0"});
  if (!v.empty()) {
    std::vector<double> velocity(3 * nc, 0.0);
    for (Index c = 0; c < nc; ++c) velocity[3 * c + 2] = v[3 * c + PlateOperator::kW];
    writer.write_cell_field_at(index, t, "velocity", velocity, 3, {"0", "0", "dw/dt"});
  }
  writer.write_cell_field_at(index, t, "moment", moment, 3, {"Mxx", "Myy", "Mxy"});
  writer.write_cell_field_at(index, t, "shear_force", shear, 3, {"Qx", "Qy", "0"});
  if (von_karman) {
    std::vector<double> membrane(3 * nc);
    const std::vector<Mat3> N = von_karman->membrane_forces(t, y);
    for (Index c = 0; c < nc; ++c) {
      membrane[3 * c] = N[c](0, 0);
      membrane[3 * c + 1] = N[c](1, 1);
      membrane[3 * c + 2] = N[c](0, 1);
    }
    writer.write_cell_field_at(index, t, "membrane_force", membrane, 3, {"Nxx", "Nyy", "Nxy"});
  }
}

std::vector<Vec3> PlateScene::probe_values(const std::vector<Probe>& probes, Real t,
                                           std::span<const Real> y) const {
  std::vector<Vec3> values;
  for (const Probe& p : probes) {
    const Vec3& xc = mesh->cell_centroid(p.cell);
    const Vec3 beta_c(y[3 * p.cell + PlateOperator::kBetaX], y[3 * p.cell + PlateOperator::kBetaY],
                      0);
    const Vec3 beta = beta_c + op->rotation_gradient_at(p.cell, xc, t, y) * (p.at - xc);
    values.emplace_back(op->deflection_at(p.cell, p.at, t, y), beta.x(), beta.y());
  }
  return values;
}

namespace {

// The gap quadrature of a cell, with the deflection at its points from the plate's own
// reconstruction of w (PlateOperator::deflection_weights; cubic by default). Quadrilaterals:
// Simpson's rule in each direction of the bilinear map x(xi, eta) of its nodes (3 x 3
// Gauss-Lobatto points: corners, edge midpoints, centre; weights (1, 4, 1)/3 on [-1, 1], times
// det J / area). Triangles: the 7-point rule on the corners (area fractions 1/20), edge
// midpoints (2/15) and centroid (9/20), exact for cubics (Zienkiewicz & Taylor, The Finite
// Element Method, vol. 1, Table 9.2). Why: near the last contact the electrostatic pressure
// eps0 V^2 / (2 g_e^2) (g_e ~ 88 nm) and the contact penalty act over a few um where the gap
// varies within a cell by more than g_e (the free long edges curl towards the electrode:
// w_y = nu w_xx y, anticlastic), so one point at the centroid senses the contact half a cell
// inside the edge, an O(h) error in the touching point and the pull-out (docs/pull-in.md,
// "Contact and pull-out"). With points on the cell's edges and corners the smallest gap of the
// reconstructed surface is a quadrature point, and the pressure integral is of order 4. Other
// cell shapes keep the one-point rule (empty: the cell's own w).
std::vector<GapPoint> cell_gap_points(const Mesh& mesh, const PlateOperator& op, Index c) {
  const auto nodes = mesh.cell_nodes(c);
  std::vector<GapPoint> points;
  auto add = [&](Real area_fraction, const Vec3& p) {
    GapPoint g{area_fraction, 0.0, {}};
    g.offset = op.deflection_weights(c, p, 0.0, g.terms);
    points.push_back(std::move(g));
  };
  if (nodes.size() == 3) {
    const Vec3 &a = mesh.nodes()[nodes[0]], &b = mesh.nodes()[nodes[1]],
               &d = mesh.nodes()[nodes[2]];
    for (const Vec3& corner : {a, b, d}) add(1.0 / 20, corner);
    for (const Vec3& midpoint : {Vec3(0.5 * (a + b)), Vec3(0.5 * (b + d)), Vec3(0.5 * (d + a))})
      add(2.0 / 15, midpoint);
    add(9.0 / 20, (a + b + d) / 3);
    return points;
  }
  if (nodes.size() != 4) return {};
  std::array<Vec3, 4> x;
  for (int i = 0; i < 4; ++i) x[i] = mesh.nodes()[nodes[i]];
  const std::array<Real, 3> s{-1, 0, 1}, w{1.0 / 3, 4.0 / 3, 1.0 / 3};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const Real xi = s[i], eta = s[j];
      const std::array<Real, 4> n{(1 - xi) * (1 - eta) / 4, (1 + xi) * (1 - eta) / 4,
                                  (1 + xi) * (1 + eta) / 4, (1 - xi) * (1 + eta) / 4};
      Vec3 p = Vec3::Zero(), d_xi = Vec3::Zero(), d_eta = Vec3::Zero();
      const std::array<Real, 4> n_xi{-(1 - eta) / 4, (1 - eta) / 4, (1 + eta) / 4, -(1 + eta) / 4};
      const std::array<Real, 4> n_eta{-(1 - xi) / 4, -(1 + xi) / 4, (1 + xi) / 4, (1 - xi) / 4};
      for (int k = 0; k < 4; ++k) {
        p += n[k] * x[k];
        d_xi += n_xi[k] * x[k];
        d_eta += n_eta[k] * x[k];
      }
      const Real det = std::abs(d_xi.x() * d_eta.y() - d_xi.y() * d_eta.x());
      add(w[i] * w[j] * det / mesh.cell_volume(c), p);
    }
  return points;
}

}  // namespace

std::vector<GapElement> plate_gap_elements(const Mesh& mesh, const PlateOperator& op) {
  std::vector<GapElement> elements;
  for (Index c = 0; c < mesh.n_owned_cells(); ++c) {
    GapElement e{3 * c + PlateOperator::kW,
                 mesh.cell_volume(c),
                 Vec3::Constant(std::numeric_limits<Real>::infinity()),
                 Vec3::Constant(-std::numeric_limits<Real>::infinity()),
                 {}};
    for (Index node : mesh.cell_nodes(c)) {
      e.lo = e.lo.cwiseMin(mesh.nodes()[node]);
      e.hi = e.hi.cwiseMax(mesh.nodes()[node]);
    }
    e.points = cell_gap_points(mesh, op, c);
    elements.push_back(e);
  }
  return elements;
}

std::vector<GapElement> PlateScene::gap_elements(const std::string&) const {
  return plate_gap_elements(*mesh, *op);
}

}  // namespace rfmems
