#include "physics/gas/kinetic/second_order_transport.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace rfmems {

TransportOrder transport_order_from_name(const std::string& name) {
  if (name == "first_order") return TransportOrder::FirstOrder;
  if (name == "second_order") return TransportOrder::SecondOrder;
  throw InputError("transport '" + name + "' is not first_order or second_order");
}

const char* transport_order_name(TransportOrder order) {
  return order == TransportOrder::SecondOrder ? "second_order" : "first_order";
}

SlopeLimiter slope_limiter_from_name(const std::string& name) {
  if (name == "venkatakrishnan") return SlopeLimiter::Venkatakrishnan;
  if (name == "barth_jespersen") return SlopeLimiter::BarthJespersen;
  if (name == "none") return SlopeLimiter::None;
  throw InputError("limiter '" + name + "' is not venkatakrishnan, barth_jespersen or none");
}

const char* slope_limiter_name(SlopeLimiter limiter) {
  switch (limiter) {
    case SlopeLimiter::Venkatakrishnan:
      return "venkatakrishnan";
    case SlopeLimiter::BarthJespersen:
      return "barth_jespersen";
    case SlopeLimiter::None:
      return "none";
  }
  return "?";
}

Real limiter_factor(SlopeLimiter limiter, Real d, Real lower, Real upper, Real e2) {
  if (limiter == SlopeLimiter::None || d == 0) return 1.0;
  const Real D = d > 0 ? upper : lower;
  if (limiter == SlopeLimiter::BarthJespersen) return std::min(1.0, D / d);
  // Venkatakrishnan's smooth min(1, D/d), divided through by d (D and d share a sign).
  const Real D2 = D * D;
  return (D2 + e2 + 2 * d * D) / (D2 + 2 * d * d + d * D + e2);
}

LinearReconstruction::LinearReconstruction(const FaceGraph& g, const Communicator& comm)
    : graph_(g), dim_(g.dim) {
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  for (const Vec3& x : g.face_centroid) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  length_ = 0;
  for (int d = 0; d < 3; ++d) length_ = std::max(length_, comm.max(hi[d]) - comm.min(lo[d]));
  weights_.assign(g.cell_faces.size(), Vec3::Zero());
  offsets_.assign(g.cell_faces.size(), Vec3::Zero());
  cell_size_.resize(g.n_cells());
  for (Index c = 0; c < g.n_cells(); ++c) {
    cell_size_[c] = std::pow(g.cell_volume[c], 1.0 / dim_);
    Mat3 M = Mat3::Zero();
    for (Index i = g.cell_face_offsets[c]; i < g.cell_face_offsets[c + 1]; ++i) {
      const Index face = g.cell_faces[i];
      offsets_[i] = g.face_centroid[face] - g.cell_centroid[c];
      if (g.is_boundary(face)) continue;
      const Index j = g.face_owner[face] == c ? g.face_neighbour[face] : g.face_owner[face];
      Vec3 d = g.cell_centroid[j] - g.cell_centroid[c];
      if (dim_ == 2) d.z() = 0;
      const Real w = 1.0 / d.squaredNorm();
      M += w * d * d.transpose();
      weights_[i] = w * d;
    }
    // Minimum-norm least squares: the pseudo-inverse of the normal matrix on the directions the
    // stencil spans. A stencil that spans all dim directions gets the full LS gradient; one
    // that spans fewer (a one-column mesh, a cell with one neighbour) gets the gradient along
    // the directions it sees and none across them, where the data carry no variation to
    // reconstruct. So a one-column mesh stays second order along its column.
    const Eigen::SelfAdjointEigenSolver<Mat3> eigen(M);
    const Real largest = eigen.eigenvalues().cwiseAbs().maxCoeff();
    Mat3 inverse = Mat3::Zero();
    for (int k = 0; k < 3; ++k) {
      const Real lambda = eigen.eigenvalues()[k];
      if (lambda > 1e-12 * largest)
        inverse += eigen.eigenvectors().col(k) * eigen.eigenvectors().col(k).transpose() / lambda;
    }
    for (Index i = g.cell_face_offsets[c]; i < g.cell_face_offsets[c + 1]; ++i)
      weights_[i] = inverse * weights_[i];
  }
}

void LinearReconstruction::limited_slopes(std::span<const Real> f, Index n,
                                          const TransportScheme& scheme,
                                          bool limit_on_boundary_faces,
                                          std::span<Real> slopes) const {
  for (Index c = 0; c < graph_.n_owned_cells; ++c)
    cell_slopes(c, f, n, scheme, limit_on_boundary_faces, slopes.subspan(c * n * dim_, n * dim_));
}

void LinearReconstruction::cell_slopes(Index c, std::span<const Real> f, Index n,
                                       const TransportScheme& scheme, bool limit_on_boundary_faces,
                                       std::span<Real> out) const {
  const FaceGraph& g = graph_;
  const int D = dim_;
  const Real* fc = f.data() + c * n;
  std::fill(out.begin(), out.end(), 0.0);
  std::vector<Real>& lo = scratch_lo_;
  std::vector<Real>& hi = scratch_hi_;
  std::vector<Real>& phi = scratch_phi_;
  lo.assign(fc, fc + n);
  hi.assign(fc, fc + n);
  for (Index i = g.cell_face_offsets[c]; i < g.cell_face_offsets[c + 1]; ++i) {
    const Index face = g.cell_faces[i];
    if (g.is_boundary(face)) continue;
    const Index j = g.face_owner[face] == c ? g.face_neighbour[face] : g.face_owner[face];
    const Real* fj = f.data() + j * n;
    const Vec3& w = weights_[i];
    for (Index k = 0; k < n; ++k) {
      const Real diff = fj[k] - fc[k];
      for (int d = 0; d < D; ++d) out[k * D + d] += w[d] * diff;
      lo[k] = std::min(lo[k], fj[k]);
      hi[k] = std::max(hi[k], fj[k]);
    }
  }
  if (scheme.limiter == SlopeLimiter::None) return;
  phi.assign(n, 1.0);
  const Real h = scheme.venkatakrishnan_k * cell_size_[c] / length_;
  const Real scale = scheme.limiter == SlopeLimiter::Venkatakrishnan ? h * h * h : 0.0;
  for (Index i = g.cell_face_offsets[c]; i < g.cell_face_offsets[c + 1]; ++i) {
    if (g.is_boundary(g.cell_faces[i]) && !limit_on_boundary_faces) continue;
    const Vec3& x = offsets_[i];
    for (Index k = 0; k < n; ++k) {
      Real delta = 0;
      for (int d = 0; d < D; ++d) delta += out[k * D + d] * x[d];
      const Real m = std::max(std::abs(lo[k]), std::abs(hi[k]));
      phi[k] = std::min(phi[k], limiter_factor(scheme.limiter, delta, lo[k] - fc[k], hi[k] - fc[k],
                                               scale * m * m));
    }
  }
  for (Index k = 0; k < n; ++k)
    for (int d = 0; d < D; ++d) out[k * D + d] *= phi[k];
}

}  // namespace rfmems
