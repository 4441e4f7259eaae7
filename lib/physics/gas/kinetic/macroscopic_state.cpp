#include "physics/gas/kinetic/macroscopic_state.hpp"

#include "core/error.hpp"

namespace rfmems {

MacroState moments(std::span<const Real> f_cell, const VelocityGrid& grid, const KineticGas& gas) {
  const Index n = grid.size();
  MacroState m;
  Real rho = 0;
  Vec3 momentum = Vec3::Zero();
  for (Index k = 0; k < n; ++k) {
    const Real wf = grid.w[k] * f_cell[k];
    rho += wf;
    momentum += wf * grid.c[k];
  }
  if (!(rho > 0)) throw RecoverableError("kinetic moments: non-positive density");
  m.rho = rho;
  m.u = momentum / rho;
  // Central moments in a second pass (C = c - u), which avoids the cancellation of
  // sum w c c f - rho u u when u is large against the thermal speed.
  Mat3 P = Mat3::Zero();
  Vec3 q = Vec3::Zero();
  for (Index k = 0; k < n; ++k) {
    const Real wf = grid.w[k] * f_cell[k];
    const Vec3 C = grid.c[k] - m.u;
    P.noalias() += wf * C * C.transpose();
    q += (0.5 * wf * C.squaredNorm()) * C;
  }
  m.pressure_tensor = P;
  m.p = P.trace() / 3;
  m.T = m.p / (rho * gas.R);
  m.stress = -(P - m.p * Mat3::Identity());
  m.heat_flux = q;
  return m;
}

}  // namespace rfmems
