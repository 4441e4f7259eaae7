#include "physics/gas/comet/point_coupled_smoother.hpp"

#include <algorithm>
#include <cmath>

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
    else if (!conserved_derivative_.kernel().valid())
      newton_step<5>(c, f, source, conserved_system_);
    else if (op_.gas().model == CollisionModel::Bgk)
      conserved_tensor_step<5>(c, f, source);
    else
      conserved_tensor_step<10>(c, f, source);
    const Index n = op_.n_ordinates();
    op_.update_collision(c, f.subspan(c * n, n));
    ++cell_updates_;
  }
}

PointCoupledSmoother::CellTerms PointCoupledSmoother::cell_terms(Index c, std::span<Real> f) {
  const Index n = op_.n_ordinates();
  op_.incoming_flux(c, f, in_);
  return {f.subspan(c * n, n), op_.equilibrium(c), &outgoing_[c * n],
          op_.graph().cell_volume[c] * op_.collision_frequency(c),
          time_coefficient_ * op_.graph().cell_volume[c]};
}

template <int M>
void PointCoupledSmoother::newton_step(Index c, std::span<Real> f, std::span<const Real> source,
                                       ArrowheadSystem<M>& a) {
  const VelocityGrid& grid = op_.grid();
  const Index n = op_.n_ordinates();
  const auto [fc, feq, out, vnu, bv] = cell_terms(c, f);

  // Residual (right-hand side -R) and the diagonal.
  for (Index k = 0; k < n; ++k) {
    Real r = (out[k] + bv) * fc[k] + in_[k] - vnu * (feq[k] - fc[k]);
    if (!source.empty()) r -= source[c * n + k];
    step_[k] = -r;
    a.d(k) = out[k] + bv + vnu;
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
  apply_step(fc);
}

template <int P>
void PointCoupledSmoother::conserved_tensor_step(Index c, std::span<Real> f,
                                                 std::span<const Real> source) {
  using Vec5 = Eigen::Matrix<Real, 5, 1>;
  using Mat5 = Eigen::Matrix<Real, 5, 5>;
  const EquilibriumTensorKernel& kernel = conserved_derivative_.kernel();
  const Index n = op_.n_ordinates();
  const auto [fc, feq, out, vnu, bv] = cell_terms(c, f);

  // G and J of f_eq: stored by the equilibrium's Newton when they are those of its
  // coefficients (then f_eq holds exactly their values), else summed here.
  const EquilibriumCoefficients& a = op_.coefficients(c);
  Eigen::Matrix<Real, P, 1> G;
  Eigen::Matrix<Real, P, P> J;
  if (a.size == P && a.has_moments && a.moments_at == a.a) {
    G = Eigen::Map<const Eigen::Matrix<Real, P, 1>>(a.moments.data());
    J = Eigen::Map<const Eigen::Matrix<Real, P, P>>(a.jacobian.data());
  } else {
    kernel.basis_moments<P>(feq.data(), G, &J);
  }
  const Eigen::Matrix<Real, P, 5> Y = EquilibriumMomentDerivative::basis_coefficients<P>(G, J);

  // y = D^-1 (-r), u = D^-1 f_eq (dfeq_ as scratch).
  Real* y = step_.data();
  Real* u = dfeq_.data();
  for (Index k = 0; k < n; ++k) {
    Real r = (out[k] + bv) * fc[k] + in_[k] - vnu * (feq[k] - fc[k]);
    if (!source.empty()) r -= source[c * n + k];
    const Real inv_d = 1.0 / (out[k] + bv + vnu);
    y[k] = -r * inv_d;
    u[k] = feq[k] * inv_d;
  }
  Vec5 g;
  kernel.basis_moments<5>(y, g, nullptr);
  Eigen::Matrix<Real, 5, P> H;
  kernel.conserved_product_moments<P>(u, H);
  const Mat5 S = Mat5::Identity() - vnu * (H * Y);
  const Eigen::FullPivLU<Mat5> lu(S);
  if (!std::isfinite(S.sum()) || !lu.isInvertible())
    throw SolverError("COMET point solve: singular Schur complement");
  const Vec5 dU = lu.solve(g);
  const Eigen::Matrix<Real, P, 1> z = vnu * (Y * dU);
  Real* correction = dfeq_.data() + n;
  kernel.basis_combination<P, 1>(u, z, correction);
  for (Index k = 0; k < n; ++k) y[k] += correction[k];
  apply_step(fc);
}

void PointCoupledSmoother::apply_step(std::span<Real> fc) {
  const Index n = op_.n_ordinates();
  // Positivity: damp the step so that no ordinate falls below a tenth of its value (ordinates
  // already <= 0, possible with the second-order correction, are not damped).
  Real theta = 1.0;
  for (Index k = 0; k < n; ++k)
    if (fc[k] > 0 && fc[k] + step_[k] < 0.1 * fc[k])
      theta = std::min(theta, 0.9 * fc[k] / -step_[k]);
  if (theta < 1.0) ++damped_steps_;
  for (Index k = 0; k < n; ++k) fc[k] += theta * step_[k];
}

}  // namespace rfmems
