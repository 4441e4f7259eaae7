#include "fv/polynomial_reconstruction.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "core/error.hpp"

namespace rfmems {

namespace {

// Exponents (i, j, k) with 1 <= i + j + k <= degree, ordered by total degree.
std::vector<std::array<int, 3>> make_exponents(int dim, int degree) {
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

// The same, tabulated once (monomials() runs per stencil point: no allocation there).
constexpr int kMaxTabulatedDegree = 6;
const std::vector<std::array<int, 3>>& exponents(int dim, int degree) {
  static const auto table = [] {
    std::array<std::array<std::vector<std::array<int, 3>>, kMaxTabulatedDegree + 1>, 4> t;
    for (int d = 1; d <= 3; ++d)
      for (int g = 0; g <= kMaxTabulatedDegree; ++g) t[d][g] = make_exponents(d, g);
    return t;
  }();
  if (dim < 1 || dim > 3 || degree < 0 || degree > kMaxTabulatedDegree)
    throw std::invalid_argument(fmt::format("monomials: dim {} degree {}", dim, degree));
  return table[dim][degree];
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
  const auto& e = exponents(dim, degree);
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
        case BoundaryPoint::Value:
          out.push_back({StencilPoint::Kind::BoundaryValue, -1, f});
          break;
        case BoundaryPoint::Mirror:
          out.push_back({StencilPoint::Kind::Mirror, c, f});
          break;
        case BoundaryPoint::None:
          break;
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

  // Fits are reused across congruent stencils: W depends only on the degree and the stencil
  // offsets, and on a structured mesh most cells see the same ones. Candidates are found by
  // offsets rounded to 1e-9 of the mesh size, then accepted only if every offset agrees to
  // 1e-12 of the stencil radius (so a reused W differs from a fresh fit at round-off level).
  Vec3 lo = Vec3::Constant(std::numeric_limits<Real>::max()), hi = -lo;
  for (Index c = 0; c < mesh.n_cells(); ++c) {
    lo = lo.cwiseMin(mesh.cell_centroid(c));
    hi = hi.cwiseMax(mesh.cell_centroid(c));
  }
  const Real key_unit = 1e-9 * std::max((hi - lo).norm(), std::numeric_limits<Real>::min());
  struct Fit {
    std::vector<Vec3> offsets;
    bool ok = false;
    Index coefficients = -1;  // into coefficients_
  };
  std::map<std::vector<long long>, std::vector<Fit>> fits;
  std::vector<long long> key;
  std::vector<Vec3> offsets;

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
        offsets.resize(np);
        key.assign({degree, np});
        Real radius = 0;
        for (int j = 0; j < np; ++j) {
          offsets[j] = position(pts[j]) - xc;
          radius = std::max(radius, offsets[j].norm());
          for (int k = 0; k < 3; ++k) key.push_back(std::llround(offsets[j][k] / key_unit));
        }
        std::vector<Fit>& candidates = fits[key];
        const Fit* fit = nullptr;
        for (const Fit& f : candidates) {
          bool same = true;
          for (int j = 0; j < np && same; ++j)
            same = (f.offsets[j] - offsets[j]).norm() <= 1e-12 * radius;
          if (same) {
            fit = &f;
            break;
          }
        }
        if (!fit) {
          Fit f;
          f.offsets = offsets;
          Eigen::MatrixXd A(np, nb);
          Eigen::VectorXd w(np);
          for (int j = 0; j < np; ++j) {
            monomials(dim, degree, offsets[j], b, grad_b);
            A.row(j) = b.transpose();
            w[j] = 1.0 / offsets[j].squaredNorm();
          }
          // Column scaling keeps the normal equations well conditioned on small cells.
          Eigen::VectorXd scale = A.colwise().norm().transpose();
          if ((scale.array() > 0).all()) {
            Eigen::MatrixXd As = A * scale.cwiseInverse().asDiagonal();
            Eigen::MatrixXd M = As.transpose() * w.asDiagonal() * As;
            Eigen::LDLT<Eigen::MatrixXd> ldlt(M);
            Eigen::VectorXd diag = ldlt.vectorD();
            if (ldlt.info() == Eigen::Success && diag.minCoeff() > 1e-9 * diag.maxCoeff()) {
              f.ok = true;
              f.coefficients = static_cast<Index>(coefficients_.size());
              coefficients_.push_back(scale.cwiseInverse().asDiagonal() *
                                      ldlt.solve(As.transpose() * w.asDiagonal()));
            }
          }
          candidates.push_back(std::move(f));
          fit = &candidates.back();
        }
        if (!fit->ok) continue;
        points_.insert(points_.end(), pts.begin(), pts.end());
        offsets_.push_back(static_cast<Index>(points_.size()));
        degree_.push_back(degree);
        coefficient_index_.push_back(fit->coefficients);
        done = true;
      }
    }
    if (!done)
      throw MeshError(
          fmt::format("cell {} at ({:.4g}, {:.4g}, {:.4g}) has too few neighbours "
                      "for a least-squares gradient (a layer one cell thick?)",
                      c, xc.x(), xc.y(), xc.z()));
  }
}

void PolynomialReconstruction::weights_at(Index c, const Vec3& x, std::vector<Real>& value,
                                          std::vector<Vec3>& gradient) const {
  thread_local Eigen::VectorXd b;
  thread_local Eigen::Matrix<double, Eigen::Dynamic, 3> grad_b;
  monomials(mesh_.dim(), degree_[c], x - mesh_.cell_centroid(c), b, grad_b);
  const Eigen::MatrixXd& W = coefficients_[coefficient_index_[c]];
  const Eigen::Index nb = W.rows(), np = W.cols();
  value.resize(static_cast<std::size_t>(np));
  gradient.resize(static_cast<std::size_t>(np));
  for (Eigen::Index j = 0; j < np; ++j) {
    Real v = 0;
    Vec3 g = Vec3::Zero();
    for (Eigen::Index k = 0; k < nb; ++k) {
      const Real wkj = W(k, j);
      v += wkj * b[k];
      g += wkj * grad_b.row(k).transpose();
    }
    value[j] = v;
    gradient[j] = g;
  }
}

void PolynomialReconstruction::append_value_weights(
    Index c, const Vec3& x, Real factor, std::vector<std::pair<Index, Real>>& weights) const {
  thread_local std::vector<Real> value;
  thread_local std::vector<Vec3> gradient;
  weights_at(c, x, value, gradient);
  const std::span<const StencilPoint> stencil = points(c);
  Real sum = 0;
  for (std::size_t j = 0; j < stencil.size(); ++j) {
    sum += value[j];
    weights.push_back({stencil[j].cell, factor * value[j]});
  }
  weights.push_back({c, factor * (1 - sum)});
}

}  // namespace rfmems
