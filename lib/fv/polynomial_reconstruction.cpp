#include "fv/polynomial_reconstruction.hpp"

#include <algorithm>
#include <array>
#include <fmt/format.h>

#include "core/error.hpp"

namespace rfmems {

namespace {

// Exponents (i, j, k) with 1 <= i + j + k <= degree, ordered by total degree.
std::vector<std::array<int, 3>> exponents(int dim, int degree) {
  std::vector<std::array<int, 3>> e;
  for (int total = 1; total <= degree; ++total)
    for (int i = total; i >= 0; --i)
      for (int j = total - i; j >= 0; --j) {
        int k = total - i - j;
        if (dim == 2 && k != 0) continue;
        e.push_back({i, j, k});
      }
  return e;
}

double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }

double power(double x, int n) {
  double r = 1;
  for (int i = 0; i < n; ++i) r *= x;
  return r;
}

}  // namespace

int n_monomials(int dim, int degree) { return static_cast<int>(exponents(dim, degree).size()); }

void monomials(int dim, int degree, const Vec3& d, Eigen::VectorXd& value,
               Eigen::Matrix<double, Eigen::Dynamic, 3>& gradient) {
  // Taylor-scaled monomials x^i y^j z^k / (i! j! k!), so the first dim coefficients are the
  // gradient at the centroid.
  auto e = exponents(dim, degree);
  value.resize(static_cast<Eigen::Index>(e.size()));
  gradient.setZero(static_cast<Eigen::Index>(e.size()), 3);
  for (std::size_t m = 0; m < e.size(); ++m) {
    auto [i, j, k] = e[m];
    double scale = 1.0 / (factorial(i) * factorial(j) * factorial(k));
    double px = power(d.x(), i), py = power(d.y(), j), pz = power(d.z(), k);
    value[m] = scale * px * py * pz;
    if (i > 0) gradient(m, 0) = scale * i * power(d.x(), i - 1) * py * pz;
    if (j > 0) gradient(m, 1) = scale * j * px * power(d.y(), j - 1) * pz;
    if (k > 0) gradient(m, 2) = scale * k * px * py * power(d.z(), k - 1);
  }
}

Vec3 PolynomialReconstruction::position(const StencilPoint& p) const {
  switch (p.kind) {
    case StencilPoint::Kind::Cell:
      return mesh_.cell_centroid(p.cell);
    case StencilPoint::Kind::BoundaryValue:
      return mesh_.face_centroid(p.face);
    case StencilPoint::Kind::Mirror: {
      const Vec3 n = mesh_.face_area(p.face).normalized();
      const Vec3& x = mesh_.cell_centroid(p.cell);
      return x + 2 * (mesh_.face_centroid(p.face) - x).dot(n) * n;
    }
  }
  return Vec3::Zero();
}

PolynomialReconstruction::PolynomialReconstruction(
    const Mesh& mesh, const std::function<BoundaryPoint(Index)>& boundary_point, int max_degree)
    : mesh_(mesh) {
  const int dim = mesh.dim();
  // The first ring of cell c: face neighbours and the points its boundary faces carry.
  auto first_ring = [&](Index c, std::vector<StencilPoint>& out) {
    for (Index f : mesh.cell_faces(c)) {
      if (!mesh.is_boundary(f)) {
        Index other = mesh.face_owner(f) == c ? mesh.face_neighbour(f) : mesh.face_owner(f);
        out.push_back({StencilPoint::Kind::Cell, other, -1});
        continue;
      }
      switch (boundary_point(f)) {
        case BoundaryPoint::Value: out.push_back({StencilPoint::Kind::BoundaryValue, -1, f}); break;
        case BoundaryPoint::Mirror: out.push_back({StencilPoint::Kind::Mirror, c, f}); break;
        case BoundaryPoint::None: break;
      }
    }
  };
  auto same = [](const StencilPoint& a, const StencilPoint& b) {
    return a.kind == b.kind && a.cell == b.cell && a.face == b.face;
  };
  // Stencil of `rings` rings around c (c itself excluded).
  auto stencil = [&](Index c, int rings) {
    std::vector<StencilPoint> all, frontier{{StencilPoint::Kind::Cell, c, -1}};
    std::vector<Index> visited{c};
    for (int r = 0; r < rings; ++r) {
      std::vector<StencilPoint> next;
      for (const StencilPoint& p : frontier) {
        if (p.kind != StencilPoint::Kind::Cell) continue;
        std::vector<StencilPoint> ring;
        first_ring(p.cell, ring);
        for (const StencilPoint& q : ring) {
          if (q.kind == StencilPoint::Kind::Cell) {
            if (std::find(visited.begin(), visited.end(), q.cell) != visited.end()) continue;
            visited.push_back(q.cell);
          } else if (std::any_of(all.begin(), all.end(), [&](auto& a) { return same(a, q); })) {
            continue;
          }
          all.push_back(q);
          next.push_back(q);
        }
      }
      frontier = std::move(next);
    }
    return all;
  };

  Eigen::VectorXd b;
  Eigen::Matrix<double, Eigen::Dynamic, 3> grad_b;
  for (Index c = 0; c < mesh.n_cells(); ++c) {
    const Vec3& xc = mesh.cell_centroid(c);
    bool done = false;
    for (int degree = std::max(max_degree, 1); degree >= 1 && !done; --degree) {
      for (int rings = std::max(1, degree - 1); rings <= std::max(1, degree) && !done; ++rings) {
        std::vector<StencilPoint> pts = stencil(c, rings);
        const int nb = n_monomials(dim, degree), np = static_cast<int>(pts.size());
        if (np < nb) continue;
        Eigen::MatrixXd A(np, nb);
        Eigen::VectorXd w(np);
        for (int j = 0; j < np; ++j) {
          Vec3 d = position(pts[j]) - xc;
          monomials(dim, degree, d, b, grad_b);
          A.row(j) = b.transpose();
          w[j] = 1.0 / d.squaredNorm();
        }
        // Column scaling keeps the normal equations well conditioned on small cells.
        Eigen::VectorXd scale = A.colwise().norm().transpose();
        if ((scale.array() <= 0).any()) continue;
        Eigen::MatrixXd As = A * scale.cwiseInverse().asDiagonal();
        Eigen::MatrixXd M = As.transpose() * w.asDiagonal() * As;
        Eigen::LDLT<Eigen::MatrixXd> ldlt(M);
        Eigen::VectorXd diag = ldlt.vectorD();
        if (ldlt.info() != Eigen::Success || diag.minCoeff() <= 1e-9 * diag.maxCoeff()) continue;
        Eigen::MatrixXd W = scale.cwiseInverse().asDiagonal() *
                            ldlt.solve(As.transpose() * w.asDiagonal());
        points_.insert(points_.end(), pts.begin(), pts.end());
        offsets_.push_back(static_cast<Index>(points_.size()));
        degree_.push_back(degree);
        coefficients_.push_back(std::move(W));
        done = true;
      }
    }
    if (!done)
      throw MeshError(fmt::format("cell {} at ({:.4g}, {:.4g}, {:.4g}) has too few neighbours "
                                  "for a least-squares gradient (a layer one cell thick?)",
                                  c, xc.x(), xc.y(), xc.z()));
  }
}

void PolynomialReconstruction::weights_at(Index c, const Vec3& x, std::vector<Real>& value,
                                          std::vector<Vec3>& gradient) const {
  Eigen::VectorXd b;
  Eigen::Matrix<double, Eigen::Dynamic, 3> grad_b;
  monomials(mesh_.dim(), degree_[c], x - mesh_.cell_centroid(c), b, grad_b);
  const Eigen::MatrixXd& W = coefficients_[c];
  Eigen::VectorXd v = W.transpose() * b;                  // n_points
  Eigen::Matrix<double, Eigen::Dynamic, 3> g = W.transpose() * grad_b;  // n_points x 3
  value.resize(v.size());
  gradient.resize(v.size());
  for (Eigen::Index j = 0; j < v.size(); ++j) {
    value[j] = v[j];
    gradient[j] = g.row(j).transpose();
  }
}

}  // namespace rfmems
