#include "physics/gas/kinetic/kinetic_reference.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "physics/gas/kinetic/kinetic_case.hpp"

namespace rfmems {
namespace {

// The mean of the diffuse walls' velocities (the frame the relative motions are taken in).
Vec3 mean_wall_velocity(const KineticScene& scene) {
  Vec3 sum = Vec3::Zero();
  int n = 0;
  for (const auto& [name, bc] : scene.conditions)
    if (bc.kind == KineticBoundaryKind::DiffuseWall) {
      sum += bc.velocity;
      ++n;
    }
  return n > 0 ? Vec3(sum / n) : Vec3::Zero();
}

}  // namespace

KineticReference kinetic_reference(const KineticScene& scene) {
  const KineticGas& gas = scene.op->gas();
  KineticReference r;
  r.temperature = scene.initial.T;
  r.density = scene.initial.rho;
  r.pressure = gas.pressure(r.density, r.temperature);
  r.viscosity = gas.viscosity(r.temperature);
  r.thermal_speed = gas.thermal_speed(r.temperature);
  r.reference_length = scene.reference_length;
  r.rarefaction_parameter = r.pressure * r.reference_length / (r.viscosity * r.thermal_speed);
  r.knudsen = std::sqrt(std::numbers::pi) / (2 * r.rarefaction_parameter);
  Real t_lo = 1e300, t_hi = -1e300;
  for (const auto& [name_a, a] : scene.conditions) {
    if (a.kind != KineticBoundaryKind::DiffuseWall) continue;
    t_lo = std::min(t_lo, a.temperature);
    t_hi = std::max(t_hi, a.temperature);
    for (const auto& [name_b, b] : scene.conditions)
      if (b.kind == KineticBoundaryKind::DiffuseWall)
        r.wall_speed = std::max(r.wall_speed, (a.velocity - b.velocity).norm());
  }
  if (t_hi > t_lo) r.temperature_difference = t_hi - t_lo;
  r.body_force = scene.body_force.norm();
  r.pressure_gradient = -r.density * r.body_force * r.reference_length / r.pressure;
  return r;
}

Real normalised_flow_rate(const KineticReference& reference, Real mass_flow, Real area) {
  const Real H = reference.reference_length;
  const Real integral = mass_flow / reference.density * H / area;  // int u dy
  return -2 / (reference.pressure_gradient * H * reference.thermal_speed) * integral;
}

WallAnswer wall_answer(const KineticScene& scene, const KineticReference& reference,
                       const std::string& name, const Vec3& force, Real heat_flow, Real area,
                       const Vec3& area_vector) {
  WallAnswer w;
  w.area = area;
  if (!(area > 0)) return w;
  w.heat_flux = heat_flow / area;
  const auto it = scene.conditions.find(name);
  if (it == scene.conditions.end() || it->second.kind != KineticBoundaryKind::DiffuseWall) return w;
  const Real p0 = reference.pressure, v0 = reference.thermal_speed;
  if (reference.temperature_difference > 0)
    w.normalised_heat_flux =
        w.heat_flux / (p0 * v0 * reference.temperature_difference / reference.temperature);
  // The wall's velocity relative to the others, without its normal part.
  const Vec3 n = area_vector.norm() > 0 ? Vec3(area_vector.normalized()) : Vec3::Zero();
  Vec3 relative = it->second.velocity - mean_wall_velocity(scene);
  relative -= relative.dot(n) * n;
  // A tangential motion below round-off of U does not define a direction.
  if (reference.wall_speed > 0 && relative.norm() > 1e-12 * reference.wall_speed) {
    const Vec3 e = relative.normalized();
    w.shear_stress = -(force / area).dot(e);
    w.normalised_shear = *w.shear_stress * v0 / (p0 * reference.wall_speed);
  }
  return w;
}

}  // namespace rfmems
