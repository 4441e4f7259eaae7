#include "ibm/ib_interpolation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "fv/polynomial_reconstruction.hpp"
#include "ibm/boost_geometry.hpp"

namespace rfmems {

using namespace ibm_geometry;

namespace {

// FLUID cells within `rings` face-neighbour rings of c0 (c0 first).
std::vector<Index> fluid_rings(const Mesh& mesh, const CellMarking& marking, Index c0, int rings) {
  std::vector<Index> all{c0}, frontier{c0};
  for (int r = 1; r < rings + 1 && !frontier.empty(); ++r) {
    std::vector<Index> next;
    for (Index c : frontier)
      for (Index f : mesh.cell_faces(c)) {
        if (mesh.is_boundary(f)) continue;
        const Index n = mesh.face_owner(f) == c ? mesh.face_neighbour(f) : mesh.face_owner(f);
        if (marking.cell[n] != CellClass::Fluid) continue;
        if (std::find(all.begin(), all.end(), n) != all.end()) continue;
        all.push_back(n);
        next.push_back(n);
      }
    frontier = std::move(next);
  }
  return all;
}

// x inside or on the convex hull of the points (2D). On the hull is not one-sided: it is the
// case of an IB face on the surface (a body edge along a grid line), between its wall points.
bool covered_by_hull(const Vec3& x, const std::vector<Vec3>& points) {
  if (points.size() < 3) return false;
  bg::model::multi_point<Point> mp;
  for (const Vec3& p : points) bg::append(mp, point(p));
  Polygon hull;
  bg::convex_hull(mp, hull);
  return bg::covered_by(point(x), hull);
}

struct Fit {
  std::vector<Real> weights;
  std::vector<Vec3> gradient_weights;  // zero for degree 0
  Real condition = 0, lebesgue = 0;
};

// Weighted least-squares value at `x` of the degree-`degree` polynomial through
// `points` (as weights on the point values), or false if there are fewer points
// than coefficients.
bool fit_value(int degree, const Vec3& x, Real h, const std::vector<Vec3>& points,
               Real min_points_per_coefficient, Fit& out) {
  const int nb = 1 + (degree > 0 ? n_monomials(2, degree) : 0);
  const int np = static_cast<int>(points.size());
  if (np < nb || (degree > 0 && np < min_points_per_coefficient * nb)) return false;
  Eigen::MatrixXd A(np, nb);
  Eigen::VectorXd sqrt_omega(np);
  Eigen::VectorXd b;
  Eigen::Matrix<double, Eigen::Dynamic, 3> grad_b;
  for (int j = 0; j < np; ++j) {
    const Vec3 d = (points[j] - x) / h;  // scaled so every column is O(1)
    A(j, 0) = 1;
    if (degree > 0) {
      monomials(2, degree, d, b, grad_b);
      A.row(j).tail(nb - 1) = b.transpose();
    }
    sqrt_omega[j] = 1.0 / std::max(d.norm(), 0.5);
  }
  Eigen::MatrixXd As = sqrt_omega.asDiagonal() * A;
  const Eigen::VectorXd scale = As.colwise().norm().transpose();
  if ((scale.array() <= 0).any()) return false;
  As = As * scale.cwiseInverse().asDiagonal();
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(As, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd& s = svd.singularValues();
  out.condition = s[s.size() - 1] > 0 ? s[0] / s[s.size() - 1] : INFINITY;
  if (!std::isfinite(out.condition)) return false;
  // a_0 = e_0^T S^-1 V Sigma^-1 U^T diag(sqrt_omega) phi.
  const Eigen::RowVectorXd v0 = svd.matrixV().row(0) / scale[0];
  const Eigen::RowVectorXd row =
      (v0 * s.cwiseInverse().asDiagonal() * svd.matrixU().transpose()) * sqrt_omega.asDiagonal();
  out.weights.assign(row.data(), row.data() + np);
  out.lebesgue = row.cwiseAbs().sum();
  // grad P(x) = (a_1, a_2) / h: the rows of the degree-1 coefficients, unscaled.
  out.gradient_weights.assign(np, Vec3::Zero());
  if (degree > 0)
    for (int r = 1; r <= 2; ++r) {
      const Eigen::RowVectorXd g = (svd.matrixV().row(r) / scale[r] *
                                    s.cwiseInverse().asDiagonal() * svd.matrixU().transpose()) *
                                   sqrt_omega.asDiagonal() / h;
      for (int j = 0; j < np; ++j) out.gradient_weights[j][r - 1] = g[j];
    }
  return true;
}

}  // namespace

namespace {

// The accepted stencil of target x beside FLUID cell c0 (the rule of the header).
void build_stencil(const Mesh& mesh, const CellMarking& marking, const ImmersedSurface& body,
                   const IbInterpolationOptions& options, const BoxTree& wall_tree, const Vec3& x,
                   Index c0, std::vector<IbStencilPoint>& chosen, IbFaceFit& info) {
  const Real h = std::sqrt(mesh.cell_volume(c0));
  std::vector<BoxValue> hits;
  Fit fit;
  for (int degree = options.degree; degree >= 0; --degree) {
    for (int rings = 1; rings <= options.max_rings; ++rings) {
      std::vector<IbStencilPoint> pts;
      std::vector<Vec3> xs;
      for (Index c : fluid_rings(mesh, marking, c0, rings)) {
        pts.push_back({IbStencilPoint::Kind::FluidCell, c, 0.0, Vec3::Zero()});
        xs.push_back(mesh.cell_centroid(c));
      }
      const Real radius = (rings + 0.5) * h;
      hits.clear();
      wall_tree.query(bgi::intersects(Box(Point(x.x() - radius, x.y() - radius),
                                          Point(x.x() + radius, x.y() + radius))),
                      std::back_inserter(hits));
      std::sort(hits.begin(), hits.end(), [](auto& a, auto& b) { return a.second < b.second; });
      for (const auto& [box, s] : hits)
        if ((body.midpoint(s) - x).norm() <= radius) {
          pts.push_back({IbStencilPoint::Kind::WallPoint, s, 0.0, Vec3::Zero()});
          xs.push_back(body.midpoint(s));
        }
      if (!fit_value(degree, x, h, xs, options.min_points_per_coefficient, fit)) continue;
      const bool last_resort = degree == 0;
      if (!last_resort &&
          (fit.condition > options.max_condition || fit.lebesgue > options.max_lebesgue))
        continue;
      for (std::size_t j = 0; j < pts.size(); ++j) {
        pts[j].weight = fit.weights[j];
        pts[j].gradient_weight = fit.gradient_weights[j];
      }
      chosen = std::move(pts);
      info = {degree, rings, fit.condition, fit.lebesgue, !covered_by_hull(x, xs)};
      return;
    }
  }
  // degree 0 on ring 1 always fits (c0 itself)
  throw std::logic_error("IB interpolation: no stencil for a target");
}

void check(const IbInterpolationOptions& options) {
  if (options.degree < 0 || options.degree > 2)
    throw InputError(fmt::format("IB interpolation: degree {} is not 0, 1 or 2", options.degree));
  if (options.max_rings < 1)
    throw InputError(fmt::format("IB interpolation: max_rings {} is not >= 1", options.max_rings));
}

}  // namespace

void IbInterpolation::add(Index id, const Vec3& x, std::vector<IbStencilPoint> stencil,
                          const IbFaceFit& fit) {
  faces_.push_back(id);
  targets_.push_back(x);
  points_.insert(points_.end(), stencil.begin(), stencil.end());
  offsets_.push_back(static_cast<Index>(points_.size()));
  fits_.push_back(fit);
}

IbInterpolation::IbInterpolation(const Mesh& mesh, const CellMarking& marking,
                                 const ImmersedSurface& body, IbInterpolationOptions options) {
  check(options);
  // R-tree of the admissible wall points.
  std::vector<BoxValue> wall;
  if (options.use_wall_points)
    for (Index k = 0; k < body.n_segments(); ++k)
      if (!options.wall_point_admissible || options.wall_point_admissible(k))
        wall.emplace_back(box_of(body.midpoint(k), body.midpoint(k)), k);
  const BoxTree wall_tree(wall.begin(), wall.end());
  for (std::size_t k = 0; k < marking.ib_faces.size(); ++k) {
    const Index f = marking.ib_faces[k];
    std::vector<IbStencilPoint> stencil;
    IbFaceFit fit;
    build_stencil(mesh, marking, body, options, wall_tree, mesh.face_centroid(f),
                  marking.ib_face_fluid_cell[k], stencil, fit);
    add(f, mesh.face_centroid(f), std::move(stencil), fit);
  }
}

IbInterpolationOptions IbInterpolation::surface_point_options() {
  IbInterpolationOptions o;
  o.use_wall_points = false;
  o.max_lebesgue = 8.0;
  o.min_points_per_coefficient = 1.5;
  o.max_rings = 4;
  return o;
}

IbInterpolation IbInterpolation::to_surface_points(const Mesh& mesh, const CellMarking& marking,
                                                   const ImmersedSurface& body,
                                                   IbInterpolationOptions options) {
  check(options);
  // Seeds: the FLUID cell nearest each segment midpoint (an R-tree of FLUID centroids).
  std::vector<BoxValue> fluid;
  for (Index c = 0; c < mesh.n_cells(); ++c)
    if (marking.cell[c] == CellClass::Fluid)
      fluid.emplace_back(box_of(mesh.cell_centroid(c), mesh.cell_centroid(c)), c);
  if (fluid.empty()) throw MeshError("IB interpolation: no FLUID cell to interpolate from");
  const BoxTree fluid_tree(fluid.begin(), fluid.end());
  const BoxTree no_walls;
  IbInterpolation out;
  std::vector<BoxValue> nearest;
  for (Index k = 0; k < body.n_segments(); ++k) {
    const Vec3 x = body.midpoint(k);
    nearest.clear();
    fluid_tree.query(bgi::nearest(point(x), 1), std::back_inserter(nearest));
    std::vector<IbStencilPoint> stencil;
    IbFaceFit fit;
    build_stencil(mesh, marking, body, options, no_walls, x, nearest.front().second, stencil, fit);
    out.add(k, x, std::move(stencil), fit);
  }
  return out;
}

Index IbInterpolation::count_one_sided() const {
  return std::count_if(fits_.begin(), fits_.end(), [](auto& f) { return f.one_sided; });
}

Index IbInterpolation::count_degree(int degree) const {
  return std::count_if(fits_.begin(), fits_.end(), [&](auto& f) { return f.degree == degree; });
}

Real IbInterpolation::interpolate(Index k, std::span<const Real> cell_values,
                                  std::span<const Real> wall_values) const {
  Real v = 0;
  for (const IbStencilPoint& p : stencil(k))
    v += p.weight *
         (p.kind == IbStencilPoint::Kind::FluidCell ? cell_values[p.index] : wall_values[p.index]);
  return v;
}

Vec3 IbInterpolation::gradient(Index k, std::span<const Real> cell_values,
                               std::span<const Real> wall_values) const {
  Vec3 g = Vec3::Zero();
  for (const IbStencilPoint& p : stencil(k))
    g += p.gradient_weight *
         (p.kind == IbStencilPoint::Kind::FluidCell ? cell_values[p.index] : wall_values[p.index]);
  return g;
}

std::vector<Real> IbInterpolation::interpolate(std::span<const Real> cell_values,
                                               std::span<const Real> wall_values) const {
  std::vector<Real> out(faces_.size());
  for (Index k = 0; k < n_faces(); ++k) out[k] = interpolate(k, cell_values, wall_values);
  return out;
}

}  // namespace rfmems
