#include "physics/gas/kinetic/kinetic_validity.hpp"

#include <algorithm>
#include <cmath>

#include "parallel/communicator.hpp"
#include "parallel/distributed_mesh.hpp"
#include "physics/gas/kinetic/kinetic_case.hpp"

namespace rfmems {

ValidityReport kinetic_scene_validity(const KineticScene &scene, const Communicator &comm) {
  const KineticOperator &op = *scene.op;
  SceneDescription s;
  auto &k = s.kinetic;
  k.present = true;
  Real rho_lo = 1e300, rho_hi = 0, t_lo = 1e300, t_hi = 0;
  for (Index c = 0; c < op.n_owned_cells(); ++c) {
    const MacroState &m = op.macro(c);
    rho_lo = std::min(rho_lo, m.rho);
    rho_hi = std::max(rho_hi, m.rho);
    t_lo = std::min(t_lo, m.T);
    t_hi = std::max(t_hi, m.T);
  }
  k.density_min = comm.min(rho_lo);
  k.density_max = comm.max(rho_hi);
  k.temperature_min = comm.min(t_lo);
  k.temperature_max = comm.max(t_hi);
  k.viscosity_min = op.gas().viscosity(k.temperature_min);
  k.viscosity_max = op.gas().viscosity(k.temperature_max);
  k.gas_constant = op.gas().R;
  k.length = scene.reference_length;
  // The smallest half-width of a truncated rule; a Gauss-Hermite rule covers the whole line.
  k.velocity_extent = 0;
  for (int d = 0; d < 3; ++d)
    if (std::isfinite(op.grid().extent[d]))
      k.velocity_extent = k.velocity_extent > 0 ? std::min(k.velocity_extent, op.grid().extent[d])
                                                : op.grid().extent[d];
  // h: the largest over the owned cells of the cell's smallest extent, volume / largest face
  // (a rectangle's shorter side): the resolution across a film or a Couette flow's shear, so
  // a quasi-1D mesh (one wide column) is judged by its rows.
  Real h = 0;
  const Mesh &mesh = scene.distributed ? scene.distributed->local.mesh : *scene.mesh;
  for (Index c = 0; c < mesh.n_owned_cells(); ++c) {
    Real largest_face = 0;
    for (Index f : mesh.cell_faces(c))
      largest_face = std::max(largest_face, mesh.face_area(f).norm());
    if (largest_face > 0) h = std::max(h, mesh.cell_volume(c) / largest_face);
  }
  k.cell_size = comm.max(h);
  k.cell_size_key = "mesh.cells";
  k.first_order = scene.solver.transport.order == TransportOrder::FirstOrder;
  k.wall_temperature = scene.initial.T;  // the grid's thermal speed is the initial state's
  for (const KineticBoundary &b : op.boundaries())
    if (b.kind == KineticBoundaryKind::DiffuseWall || b.kind == KineticBoundaryKind::Pressure) {
      // Both send in a Maxwellian at their temperature (a pressure boundary at rest).
      if (b.kind == KineticBoundaryKind::DiffuseWall)
        k.wall_speed = std::max(k.wall_speed, b.velocity.cwiseAbs().maxCoeff());
      k.wall_temperature = std::max(k.wall_temperature, b.temperature);
    }
  return check_scene_validity(s);
}

}  // namespace rfmems
