#include "fv/least_squares_gradient.hpp"

#include <fmt/format.h>

#include "core/error.hpp"

namespace rfmems {

namespace {

struct FitPoint {
  Index face, cell;  // as in GradientNeighbour
  Vec3 d;            // offset from the cell centroid
};

// Weights g_j of the gradient part of a weighted least-squares fit with basis `n_basis`
// functions of d (the first `dim` are the linear terms). Returns false if rank-deficient.
bool fit_weights(int dim, bool quadratic, const std::vector<FitPoint>& points,
                 std::vector<Vec3>& weights) {
  const int n_lin = dim, n_quad = dim == 2 ? 3 : 6;
  const int nb = quadratic ? n_lin + n_quad : n_lin;
  const int np = static_cast<int>(points.size());
  if (np < nb) return false;
  Eigen::MatrixXd A(np, nb);
  Eigen::VectorXd w(np);
  for (int j = 0; j < np; ++j) {
    const Vec3& d = points[j].d;
    w[j] = 1.0 / d.squaredNorm();
    int col = 0;
    for (int k = 0; k < dim; ++k) A(j, col++) = d[k];
    if (quadratic)
      for (int k = 0; k < dim; ++k)
        for (int l = k; l < dim; ++l) A(j, col++) = (k == l ? 0.5 : 1.0) * d[k] * d[l];
  }
  // Scale columns so the normal matrix is well conditioned.
  Eigen::VectorXd scale = A.colwise().norm().transpose();
  if ((scale.array() <= 0).any()) return false;
  Eigen::MatrixXd As = A * scale.cwiseInverse().asDiagonal();
  Eigen::MatrixXd M = As.transpose() * w.asDiagonal() * As;
  Eigen::LDLT<Eigen::MatrixXd> ldlt(M);
  Eigen::VectorXd diag = ldlt.vectorD();
  if (ldlt.info() != Eigen::Success || diag.minCoeff() <= 1e-10 * diag.maxCoeff()) return false;
  // coefficients = S^-1 M^-1 As^T W phi: the gradient rows give g_j.
  Eigen::MatrixXd G = ldlt.solve(As.transpose() * w.asDiagonal());
  weights.assign(np, Vec3::Zero());
  for (int j = 0; j < np; ++j)
    for (int k = 0; k < dim; ++k) weights[j][k] = G(k, j) / scale[k];
  return true;
}

}  // namespace

LeastSquaresGradient::LeastSquaresGradient(const Mesh& mesh,
                                           const std::function<bool(Index)>& uses_boundary_face) {
  const int dim = mesh.dim();
  weight_sum_.assign(mesh.n_cells(), Vec3::Zero());
  // First ring of a cell: face neighbours and the boundary faces that carry values.
  auto first_ring = [&](Index c, std::vector<FitPoint>& points) {
    for (Index f : mesh.cell_faces(c)) {
      if (!mesh.is_boundary(f)) {
        Index other = mesh.face_owner(f) == c ? mesh.face_neighbour(f) : mesh.face_owner(f);
        points.push_back({f, other, Vec3::Zero()});
      } else if (uses_boundary_face(f)) {
        points.push_back({f, -1, Vec3::Zero()});
      }
    }
  };
  for (Index c = 0; c < mesh.n_cells(); ++c) {
    const Vec3& xc = mesh.cell_centroid(c);
    bool on_boundary = false;
    for (Index f : mesh.cell_faces(c)) on_boundary = on_boundary || mesh.is_boundary(f);
    std::vector<FitPoint> points;
    first_ring(c, points);
    if (on_boundary) {
      // Second ring: the first rings of the neighbour cells, without repeats.
      std::vector<FitPoint> ring2;
      for (const FitPoint& p : points)
        if (p.cell >= 0) first_ring(p.cell, ring2);
      for (const FitPoint& q : ring2) {
        if (q.cell == c) continue;
        bool seen = false;
        for (const FitPoint& p : points)
          seen = seen || (q.cell >= 0 ? p.cell == q.cell : (p.cell < 0 && p.face == q.face));
        if (!seen) points.push_back(q);
      }
    }
    for (FitPoint& p : points)
      p.d = (p.cell >= 0 ? mesh.cell_centroid(p.cell) : mesh.face_centroid(p.face)) - xc;

    std::vector<Vec3> weights;
    if (!(on_boundary && fit_weights(dim, true, points, weights))) {
      // Linear fit on the first ring (interior cells, or too few points for a quadratic).
      if (on_boundary) {
        points.clear();
        first_ring(c, points);
        for (FitPoint& p : points)
          p.d = (p.cell >= 0 ? mesh.cell_centroid(p.cell) : mesh.face_centroid(p.face)) - xc;
      }
      if (!fit_weights(dim, false, points, weights))
        throw MeshError(fmt::format("cell {} at ({:.4g}, {:.4g}, {:.4g}) has too few neighbours "
                                    "for a least-squares gradient (a layer one cell thick?)",
                                    c, xc.x(), xc.y(), xc.z()));
    }
    for (std::size_t j = 0; j < points.size(); ++j) {
      list_.push_back({points[j].face, points[j].cell, weights[j]});
      weight_sum_[c] += weights[j];
    }
    offsets_.push_back(static_cast<Index>(list_.size()));
  }
}

Real owner_interpolation_weight(const Mesh& mesh, Index f) {
  const Vec3& xp = mesh.cell_centroid(mesh.face_owner(f));
  const Vec3& xn = mesh.cell_centroid(mesh.face_neighbour(f));
  Vec3 d = xn - xp;
  return (xn - mesh.face_centroid(f)).dot(d) / d.squaredNorm();
}

}  // namespace rfmems
