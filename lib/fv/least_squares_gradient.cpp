#include "fv/least_squares_gradient.hpp"

#include <fmt/format.h>

#include "core/error.hpp"

namespace rfmems {

LeastSquaresGradient::LeastSquaresGradient(const Mesh& mesh,
                                           const std::function<bool(Index)>& uses_boundary_face) {
  const int dim = mesh.dim();
  weight_sum_.assign(mesh.n_cells(), Vec3::Zero());
  for (Index c = 0; c < mesh.n_cells(); ++c) {
    const Vec3& xc = mesh.cell_centroid(c);
    std::vector<std::pair<Index, Index>> nbs;  // (face, cell or -1)
    for (Index f : mesh.cell_faces(c)) {
      if (!mesh.is_boundary(f)) {
        Index other = mesh.face_owner(f) == c ? mesh.face_neighbour(f) : mesh.face_owner(f);
        nbs.emplace_back(f, other);
      } else if (uses_boundary_face(f)) {
        nbs.emplace_back(f, -1);
      }
    }
    Mat3 m = Mat3::Zero();
    std::vector<Vec3> d(nbs.size());
    std::vector<Real> w(nbs.size());
    for (std::size_t j = 0; j < nbs.size(); ++j) {
      auto [f, other] = nbs[j];
      d[j] = (other >= 0 ? mesh.cell_centroid(other) : mesh.face_centroid(f)) - xc;
      w[j] = 1.0 / d[j].squaredNorm();
      m += w[j] * d[j] * d[j].transpose();
    }
    // Invert only the dim x dim block (2D: no z information).
    Mat3 inv = Mat3::Zero();
    if (dim == 2) {
      Eigen::Matrix2d m2 = m.topLeftCorner<2, 2>();
      Real scale = m2.trace();
      if (!(std::abs(m2.determinant()) > 1e-10 * scale * scale))
        throw MeshError(fmt::format("cell {} at ({:.4g}, {:.4g}) has too few neighbours for a "
                                    "least-squares gradient (a layer one cell thick?)",
                                    c, xc.x(), xc.y()));
      inv.topLeftCorner<2, 2>() = m2.inverse();
    } else {
      Real scale = m.trace();
      if (!(std::abs(m.determinant()) > 1e-10 * scale * scale * scale))
        throw MeshError(fmt::format("cell {} at ({:.4g}, {:.4g}, {:.4g}) has too few neighbours "
                                    "for a least-squares gradient",
                                    c, xc.x(), xc.y(), xc.z()));
      inv = m.inverse();
    }
    for (std::size_t j = 0; j < nbs.size(); ++j) {
      Vec3 g = w[j] * inv * d[j];
      list_.push_back({nbs[j].first, nbs[j].second, g});
      weight_sum_[c] += g;
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
