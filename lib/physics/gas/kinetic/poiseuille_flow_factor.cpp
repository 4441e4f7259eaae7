#include "physics/gas/kinetic/poiseuille_flow_factor.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "core/error.hpp"
#include "io/case_schema_yaml.hpp"
#include "parallel/communicator.hpp"
#include "physics/gas/kinetic/kinetic_case.hpp"
#include "physics/gas/kinetic/kinetic_reference.hpp"
#include "physics/gas/kinetic/kinetic_results.hpp"

namespace rfmems {

namespace {

// BGK's viscous slip coefficient (Loyalka, Petrellis & Storvick, Phys. Fluids 18 (1975) 1094):
// only the starting guess uses it.
constexpr Real kViscousSlip = 1.0162;

}  // namespace

std::vector<FlowFactorPoint> read_flow_factor_points(const CaseNode& flow_factor) {
  const CaseNode points = flow_factor.child("points");
  points.require(points.size() > 0, "points", "expected at least one point");
  std::vector<FlowFactorPoint> out;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const CaseNode p = points.item(i);
    FlowFactorPoint point;
    point.knudsen = p.get_real("knudsen", Range::positive());
    point.cells = static_cast<int>(p.get_int("cells", Range::closed(2, 100000)));
    const std::vector<Real> n = p.get_reals("velocity_points");
    if (n.size() != 3) p.fail("velocity_points", "expected 3 numbers [N1, N2, N3]");
    for (int d = 0; d < 3; ++d) {
      if (!(n[d] >= 2 && n[d] == std::floor(n[d])))
        p.fail("velocity_points", "each must be an integer >= 2");
      point.velocity_points[d] = static_cast<int>(n[d]);
    }
    out.push_back(point);
  }
  return out;
}

std::vector<std::string> flow_factor_overrides(const FlowFactorPoint& point) {
  const auto& n = point.velocity_points;
  return {fmt::format("initial.knudsen={:.17g}", point.knudsen),
          fmt::format("mesh.cells=[1, {}]", point.cells),
          fmt::format("velocity_grid.points=[{}, {}, {}]", n[0], n[1], n[2])};
}

FlowFactorResult compute_flow_factor(const std::string& case_path,
                                     const std::vector<std::string>& overrides,
                                     const FlowFactorPoint& point) {
  std::vector<std::string> all = overrides;
  for (std::string& s : flow_factor_overrides(point)) all.push_back(std::move(s));
  const CaseFile file = CaseFile::load(case_path, all);
  const std::string dir = std::filesystem::path(case_path).parent_path().string();
  KineticScene scene = build_kinetic_scene(file.root(), dir);
  KineticOperator& op = *scene.op;
  const KineticReference ref = kinetic_reference(scene);
  if (!(ref.body_force > 0))
    throw InputError(
        fmt::format("{}: the flow factor needs a body-force-driven channel "
                    "(body_force.acceleration along x, periodic sides)",
                    case_path));

  // The slip-flow start between the walls at y0, the mesh's lowest y, and y0 + H (H the
  // reference length: the mesh may be the half channel below a symmetry plane).
  Real y0 = std::numeric_limits<Real>::infinity();
  for (const Vec3& x : scene.mesh->nodes()) y0 = std::min(y0, x.y());
  const Real H = ref.reference_length, y1 = y0 + H, delta = ref.rarefaction_parameter;
  const Vec3 direction = scene.body_force / scene.body_force.norm();
  const Real scale = ref.density * ref.body_force / (2 * ref.viscosity);
  std::vector<Real> f(op.size());
  op.initialize(f, [&](const Vec3& x) {
    GasState s = scene.initial;
    s.u += scale * ((x.y() - y0) * (y1 - x.y()) + kViscousSlip * H / delta * H) * direction;
    return s;
  });

  const KineticSolveResult result =
      kinetic_solvers().at(scene.solver.type)(op, f, scene.solver, [](int, Real) { return true; });
  if (!result.converged)
    throw SolverError(fmt::format(
        "flow factor at Kn = {:g}: no convergence after {} sweeps (residual ratio {:.3e}){}",
        point.knudsen, result.iterations, result.residual_ratio,
        result.stop_reason.empty() ? "" : ": " + result.stop_reason));
  op.update_collision(f);
  const Json summary = kinetic_summary(scene, result, f);
  if (!summary.contains("flow_rate"))
    throw InputError(
        fmt::format("{}: no periodic patch the body force drives the gas out of", case_path));

  FlowFactorResult r;
  r.point = point;
  r.rarefaction_parameter = delta;
  r.flow_rate = summary["flow_rate"]["normalised_flow_rate"].get<double>();
  r.flow_factor = 6 * r.flow_rate / delta;
  r.sweeps = result.iterations;
  r.residual_ratio = result.residual_ratio;
  r.seconds = result.seconds;
  return r;
}

std::string flow_factor_csv(const std::vector<FlowFactorResult>& results,
                            const std::vector<std::string>& header) {
  std::string out;
  for (const std::string& line : header) out += "# " + line + "\n";
  out +=
      "knudsen,delta,flow_rate,flow_factor,cells,velocity_points,sweeps,residual_ratio,seconds\n";
  for (const FlowFactorResult& r : results) {
    const auto& n = r.point.velocity_points;
    out += fmt::format("{:.6g},{:.8g},{:.8g},{:.8g},{},{}x{}x{},{},{:.2e},{:.2f}\n",
                       r.point.knudsen, r.rarefaction_parameter, r.flow_rate, r.flow_factor,
                       r.point.cells, n[0], n[1], n[2], r.sweeps, r.residual_ratio, r.seconds);
  }
  return out;
}

CaseSchema flow_factor_case_keys() {
  return embedded_case_schema("physics/gas/kinetic/poiseuille_flow_factor.keys.yaml");
}

}  // namespace rfmems
