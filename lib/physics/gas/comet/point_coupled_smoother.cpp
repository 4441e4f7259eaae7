#include "physics/gas/comet/point_coupled_smoother.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "physics/gas/comet/equilibrium_moment_derivative.hpp"

namespace rfmems {

CometCoupling comet_coupling_from_name(const std::string& name) {
  if (name == "velocity") return CometCoupling::Velocity;
  if (name == "conserved") return CometCoupling::Conserved;
  throw InputError("unknown COMET coupling '" + name + "' (velocity | conserved)");
}

const char* comet_coupling_name(CometCoupling coupling) {
  return coupling == CometCoupling::Velocity ? "velocity" : "conserved";
}

PointCoupledSmoother::PointCoupledSmoother(KineticOperator& op, CometCoupling coupling,
                                           int cell_newton_iterations)
    : op_(op),
      coupling_(coupling),
      newton_iterations_(std::max(1, cell_newton_iterations)),
      conserved_derivative_(op.gas().model, op.grid()) {
  const Index n = op.n_ordinates(), nc = op.n_owned_cells();
  outgoing_.resize(nc * n);
  for (Index c = 0; c < nc; ++c)
    op.outgoing_coefficients(c, std::span<Real>(outgoing_).subspan(c * n, n));
  in_.resize(n);
  step_.resize(n);
  dfeq_.resize(5 * n);
  velocity_system_.resize(n);
  conserved_system_.resize(n);
  // The moment rows C are constant: -w_k c_k (velocity) or -w_k psi_k (conserved).
  const VelocityGrid& grid = op.grid();
  for (Index k = 0; k < n; ++k) {
    const auto psi = conserved_basis(grid, k);
    for (int j = 0; j < 3; ++j) velocity_system_.c(j, k) = -grid.w[k] * grid.c[k][j];
    for (int j = 0; j < 5; ++j) conserved_system_.c(j, k) = -grid.w[k] * psi[j];
  }
  conserved_system_.e().setIdentity();
}

void PointCoupledSmoother::sweep(std::span<Real> f, std::span<const Real> source, bool forward) {
  const Index nc = op_.n_owned_cells();
  if (forward)
    for (Index c = 0; c < nc; ++c) solve_cell(c, f, source);
  else
    for (Index c = nc - 1; c >= 0; --c) solve_cell(c, f, source);
}

void PointCoupledSmoother::solve_cell(Index c, std::span<Real> f, std::span<const Real> source) {
  const FaceGraph& g = op_.graph();
  for (int it = 0; it < newton_iterations_; ++it) {
    // Boundary faces: incoming values from the cell's current f (lagged, thesis).
    for (Index i = g.cell_face_offsets[c]; i < g.cell_face_offsets[c + 1]; ++i)
      if (g.is_boundary(g.cell_faces[i])) op_.update_boundary_values(g.cell_faces[i], f);
    if (coupling_ == CometCoupling::Velocity)
      newton_step<3>(c, f, source, velocity_system_);
    else
      newton_step<5>(c, f, source, conserved_system_);
    const Index n = op_.n_ordinates();
    op_.update_collision(c, f.subspan(c * n, n));
    ++cell_updates_;
  }
}

template <int M>
void PointCoupledSmoother::newton_step(Index c, std::span<Real> f, std::span<const Real> source,
                                       ArrowheadSystem<M>& a) {
  const VelocityGrid& grid = op_.grid();
  const Index n = op_.n_ordinates();
  const std::span<Real> fc = f.subspan(c * n, n);
  const std::span<const Real> feq = op_.equilibrium(c);
  const Real* out = &outgoing_[c * n];
  const Real vnu = op_.graph().cell_volume[c] * op_.collision_frequency(c);
  op_.incoming_flux(c, f, in_);

  // Residual (right-hand side -R) and the diagonal.
  for (Index k = 0; k < n; ++k) {
    Real r = out[k] * fc[k] + in_[k] - vnu * (feq[k] - fc[k]);
    if (!source.empty()) r -= source[c * n + k];
    step_[k] = -r;
    a.d(k) = out[k] + vnu;
  }
  // Coupling columns B = -V nu df_eq/dX (the moment rows [C E] are set once, E = rho I for the
  // velocity coupling per cell).
  if constexpr (M == 3) {
    equilibrium_velocity_derivative(op_.coefficients(c), op_.target(c), grid, feq,
                                    std::span<Real>(dfeq_).first(3 * n));
    const std::span<Real> b = a.b_data();
    for (Index i = 0; i < 3 * n; ++i) b[i] = -vnu * dfeq_[i];
    a.e() = op_.macro(c).rho * Mat3::Identity();
  } else {
    conserved_derivative_.evaluate(feq, a.b_data(), -vnu);
  }
  typename ArrowheadSystem<M>::VecM dx;
  a.solve(step_, ArrowheadSystem<M>::VecM::Zero(), step_, dx);

  // Positivity: damp the step so that no ordinate falls below a tenth of its value.
  Real theta = 1.0;
  for (Index k = 0; k < n; ++k)
    if (fc[k] + step_[k] < 0.1 * fc[k]) theta = std::min(theta, 0.9 * fc[k] / -step_[k]);
  if (theta < 1.0) ++damped_steps_;
  for (Index k = 0; k < n; ++k) fc[k] += theta * step_[k];
}

}  // namespace rfmems
