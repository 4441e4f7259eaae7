#include "physics/elasticity/elasticity_operator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "core/error.hpp"

namespace rfmems {

using Kind = ElasticityBoundary::Kind;

namespace {
Mat3 normal_projector(const Vec3& S) {
  Vec3 n = S.normalized();
  return n * n.transpose();
}
}  // namespace

ElasticityOperator::ElasticityOperator(const Mesh& mesh, const LinearElastic& material,
                                       std::vector<ElasticityBoundary> boundaries,
                                       VectorField body_force, int reconstruction_degree)
    : mesh_(mesh),
      material_(material),
      boundaries_(std::move(boundaries)),
      body_force_(std::move(body_force)),
      dim_(mesh.dim()),
      requested_degree_(reconstruction_degree),
      mu_(material.mu()),
      lambda_(material.lambda()) {
  if (boundaries_.size() != mesh_.patches().size())
    throw InputError(fmt::format("elasticity: {} boundary conditions for {} patches",
                                 boundaries_.size(), mesh_.patches().size()));
  reconstruction_ = std::make_unique<PolynomialReconstruction>(
      mesh_,
      [this](Index f) {
        switch (boundaries_[mesh_.face_patch(f)].kind) {
          case Kind::Fixed:
            return BoundaryPoint::Value;
          case Kind::Symmetry:
            return BoundaryPoint::Mirror;
          default:
            return BoundaryPoint::None;
        }
      },
      reconstruction_degree > 0 ? reconstruction_degree : default_reconstruction_degree(dim_));

  // Geometry of each face and the evaluation weights of the reconstructions at it.
  const Index nf = mesh_.n_faces();
  face_e_.resize(nf);
  face_d_.resize(nf);
  sides_.resize(2 * nf);
  std::vector<Real> value;
  std::vector<Vec3> gradient;
  auto add_side = [&](Index f, int which, Index c) {
    reconstruction_->weights_at(c, mesh_.face_centroid(f), value, gradient);
    FaceSide& s = sides_[2 * f + which];
    s.cell = c;
    s.begin = static_cast<Index>(side_value_.size());
    side_value_.insert(side_value_.end(), value.begin(), value.end());
    side_gradient_.insert(side_gradient_.end(), gradient.begin(), gradient.end());
    s.end = static_cast<Index>(side_value_.size());
  };
  for (Index f = 0; f < nf; ++f) {
    const Index p = mesh_.face_owner(f), n = mesh_.face_neighbour(f);
    Vec3 d = (n >= 0 ? mesh_.cell_centroid(n) : mesh_.face_centroid(f)) - mesh_.cell_centroid(p);
    face_d_[f] = d.norm();
    face_e_[f] = d / face_d_[f];
    add_side(f, 0, p);
    if (n >= 0) add_side(f, 1, n);
  }
  point_offset_.push_back(0);
  for (Index c = 0; c < mesh_.n_cells(); ++c) {
    reconstruction_->weights_at(c, mesh_.cell_centroid(c), value, gradient);
    centroid_gradient_.insert(centroid_gradient_.end(), gradient.begin(), gradient.end());
    point_offset_.push_back(static_cast<Index>(centroid_gradient_.size()));
  }
  point_delta_.resize(centroid_gradient_.size());
}

const BlockSparsity& ElasticityOperator::sparsity() const {
  if (sparsity_) return *sparsity_;
  const Index nf = mesh_.n_faces();
  std::vector<std::set<Index>> stencils(mesh_.n_cells());
  for (Index c = 0; c < mesh_.n_cells(); ++c) stencils[c].insert(c);
  for (Index f = 0; f < nf; ++f) {
    const Index p = mesh_.face_owner(f), n = mesh_.face_neighbour(f);
    std::set<Index> cells{p};
    for (int which = 0; which < (n >= 0 ? 2 : 1); ++which) {
      const FaceSide& s = side(f, which);
      cells.insert(s.cell);
      for (const StencilPoint& pt : reconstruction_->points(s.cell))
        if (pt.kind != StencilPoint::Kind::BoundaryValue) cells.insert(pt.cell);
    }
    stencils[p].insert(cells.begin(), cells.end());
    if (n >= 0) stencils[n].insert(cells.begin(), cells.end());
  }
  sparsity_ = std::make_unique<BlockSparsity>(stencils, dim_);
  return *sparsity_;
}

Vec3 ElasticityOperator::cell_u(std::span<const Real> u, Index c) const {
  Vec3 v = Vec3::Zero();
  for (int k = 0; k < dim_; ++k) v[k] = u[c * dim_ + k];
  return v;
}

Mat3 ElasticityOperator::point_map(const StencilPoint& p) const {
  // A mirror image carries the reflected vector: normal component reversed.
  return p.kind == StencilPoint::Kind::Mirror
             ? Mat3(Mat3::Identity() - 2 * normal_projector(mesh_.face_area(p.face)))
             : Mat3(Mat3::Identity());
}

Vec3 ElasticityOperator::point_value(const StencilPoint& p, Real t, std::span<const Real> u) const {
  if (p.kind == StencilPoint::Kind::BoundaryValue)
    return boundaries_[mesh_.face_patch(p.face)].at(mesh_.face_centroid(p.face), t);
  return point_map(p) * cell_u(u, p.cell);
}

void ElasticityOperator::compute_point_deltas(Real t, std::span<const Real> u,
                                              bool homogeneous) const {
  for (Index c = 0; c < mesh_.n_cells(); ++c) {
    const Vec3 uc = cell_u(u, c);
    auto points = reconstruction_->points(c);
    Vec3* delta = point_delta_.data() + point_offset_[c];
    for (std::size_t j = 0; j < points.size(); ++j) {
      const StencilPoint& p = points[j];
      const Vec3 v = p.kind == StencilPoint::Kind::Cell ? cell_u(u, p.cell)
                     : homogeneous && p.kind == StencilPoint::Kind::BoundaryValue
                         ? Vec3(Vec3::Zero())
                         : point_value(p, t, u);
      delta[j] = v - uc;
    }
  }
}

void ElasticityOperator::evaluate_side(const FaceSide& s, std::span<const Real> u, Vec3& value,
                                       Mat3& gradient) const {
  value = cell_u(u, s.cell);
  gradient.setZero();
  const Vec3* delta = point_delta_.data() + point_offset_[s.cell];
  for (Index j = 0; j < s.end - s.begin; ++j) {
    value += side_value_[s.begin + j] * delta[j];
    gradient += delta[j] * side_gradient_[s.begin + j].transpose();
  }
}

std::vector<Mat3> ElasticityOperator::cell_gradients(Real t, std::span<const Real> u) const {
  compute_point_deltas(t, u);
  std::vector<Mat3> grad(mesh_.n_cells(), Mat3::Zero());
  for (Index c = 0; c < mesh_.n_cells(); ++c)
    for (Index k = point_offset_[c]; k < point_offset_[c + 1]; ++k)
      grad[c] += point_delta_[k] * centroid_gradient_[k].transpose();
  return grad;
}

Vec3 ElasticityOperator::face_force(const Mat3& G, const Vec3& S, bool homogeneous) const {
  if (nonlinear_ && !homogeneous)
    return (Mat3::Identity() + G) * (second_piola_kirchhoff(G) * S) +
           G * (material_.residual_stress * S);
  return mu_ * (G * S + G.transpose() * S) + lambda_ * G.trace() * S +
         G * (material_.residual_stress * S);
}

Mat3 ElasticityOperator::second_piola_kirchhoff(const Mat3& G) const {
  Mat3 E = 0.5 * (G + G.transpose() + G.transpose() * G);
  Mat3 I = Mat3::Identity();
  if (dim_ == 2) {  // the in-plane strain and stress (E_zz of plane stress is implied)
    E.row(2).setZero();
    E.col(2).setZero();
    I(2, 2) = 0;
  }
  return lambda_ * E.trace() * I + 2 * mu_ * E;
}

bool ElasticityOperator::face_gradient(Index f, Real t, std::span<const Real> u, bool homogeneous,
                                       Mat3& G) const {
  const Index n = mesh_.face_neighbour(f);
  const Vec3& e = face_e_[f];
  const Real inv_d = 1.0 / face_d_[f];
  Vec3 vp, vn;
  Mat3 gp, gn;
  if (n >= 0) {
    evaluate_side(side(f, 0), u, vp, gp);
    evaluate_side(side(f, 1), u, vn, gn);
    G = 0.5 * (gp + gn) + (vn - vp) * inv_d * e.transpose();
    return true;
  }
  const ElasticityBoundary& bc = boundaries_[mesh_.face_patch(f)];
  if (bc.kind == Kind::Traction) return false;
  evaluate_side(side(f, 0), u, vp, gp);
  if (bc.kind == Kind::Fixed) {
    const Vec3 ub = homogeneous ? Vec3(Vec3::Zero()) : bc.at(mesh_.face_centroid(f), t);
    G = gp + (ub - vp) * inv_d * e.transpose();
  } else {  // symmetry: no normal displacement
    G = gp - (normal_projector(mesh_.face_area(f)) * vp) * inv_d * e.transpose();
  }
  return true;
}

void ElasticityOperator::internal_residual(Real t, std::span<const Real> u, std::span<Real> r) {
  std::fill(r.begin(), r.end(), 0.0);
  add_internal_forces(t, u, false, 1.0, r);
}

void ElasticityOperator::add_damping_force(Real t, std::span<const Real> v, std::span<Real> r) {
  if (damping_time_ > 0) add_internal_forces(t, v, true, damping_time_, r);
}

void ElasticityOperator::stiffness_product(Real t, std::span<const Real>, std::span<const Real> v,
                                           std::span<Real> kv) {
  std::fill(kv.begin(), kv.end(), 0.0);
  add_internal_forces(t, v, true, 1.0, kv);
}

Real ElasticityOperator::grid_damping_time(Real zeta) const {
  if (!(material_.rho > 0) || !(zeta > 0)) return 0;
  Real h = std::numeric_limits<Real>::infinity();
  for (Index f = 0; f < mesh_.n_faces(); ++f)
    h = std::min(h, mesh_.face_neighbour(f) >= 0 ? face_d_[f] : 2 * face_d_[f]);
  return zeta * h / std::sqrt((lambda_ + 2 * mu_) / material_.rho);
}

void ElasticityOperator::add_internal_forces(Real t, std::span<const Real> u, bool homogeneous,
                                             Real scale, std::span<Real> r) const {
  auto add = [&](Index c, const Vec3& v) {
    for (int k = 0; k < dim_; ++k) r[c * dim_ + k] += scale * v[k];
  };
  compute_point_deltas(t, u, homogeneous);
  Mat3 G;
  for (Index f = 0; f < mesh_.n_faces(); ++f) {
    const Index p = mesh_.face_owner(f), n = mesh_.face_neighbour(f);
    const Vec3& S = mesh_.face_area(f);
    if (!face_gradient(f, t, u, homogeneous, G)) {  // traction
      if (!homogeneous)
        add(p, -boundaries_[mesh_.face_patch(f)].at(mesh_.face_centroid(f), t) * S.norm());
      continue;
    }
    const Vec3 F = face_force(G, S, homogeneous);
    if (n >= 0) {
      add(p, -F);
      add(n, F);
    } else if (boundaries_[mesh_.face_patch(f)].kind == Kind::Fixed) {
      add(p, -F);
    } else {  // symmetry: only the normal force is transmitted
      add(p, -(normal_projector(S) * F));
    }
  }
  if (body_force_ && !homogeneous)
    for (Index c = 0; c < mesh_.n_cells(); ++c)
      add(c, -body_force_(mesh_.cell_centroid(c), t) * mesh_.cell_volume(c));
}

void ElasticityOperator::append_side_terms(const FaceSide& s, Real grad_factor, Real value_factor,
                                           const Mat3& value_map, const Vec3& e,
                                           std::vector<Term>& terms) const {
  // p(x_f) = u_c + sum_j s_j (v_j - u_c), grad p(x_f) = sum_j (v_j - u_c) g_j^T with
  // v_j = M_j u_{cell_j} (or a constant boundary value, which has no derivative).
  auto points = reconstruction_->points(s.cell);
  Vec3 grad_sum = Vec3::Zero();
  Real value_sum = 0;
  for (Index j = 0; j < s.end - s.begin; ++j) {
    const Vec3& g = side_gradient_[s.begin + j];
    const Real v = side_value_[s.begin + j];
    grad_sum += g;
    value_sum += v;
    const StencilPoint& pt = points[j];
    if (pt.kind == StencilPoint::Kind::BoundaryValue) continue;
    const Mat3 M = point_map(pt);
    terms.push_back({pt.cell, M, grad_factor * g});
    terms.push_back({pt.cell, value_map * M, value_factor * v * e});
  }
  terms.push_back({s.cell, Mat3::Identity(), -grad_factor * grad_sum});
  terms.push_back({s.cell, value_map, value_factor * (1 - value_sum) * e});
}

std::vector<Mat3> ElasticityOperator::face_gradients(Real t, std::span<const Real> u) const {
  compute_point_deltas(t, u);
  std::vector<Mat3> G(mesh_.n_faces(), Mat3::Zero());
  for (Index f = 0; f < mesh_.n_faces(); ++f)
    if (!face_gradient(f, t, u, false, G[f])) G[f].setZero();
  return G;
}

std::vector<ElasticityOperator::GradientTerm> ElasticityOperator::face_gradient_terms(
    Index f) const {
  // The terms stiffness() differentiates the face force with.
  std::vector<Term> terms;
  const Index n = mesh_.face_neighbour(f);
  const Vec3& e = face_e_[f];
  const Real inv_d = 1.0 / face_d_[f];
  if (n >= 0) {
    append_side_terms(side(f, 0), 0.5, -inv_d, Mat3::Identity(), e, terms);
    append_side_terms(side(f, 1), 0.5, inv_d, Mat3::Identity(), e, terms);
  } else {
    const Kind kind = boundaries_[mesh_.face_patch(f)].kind;
    if (kind == Kind::Fixed)
      append_side_terms(side(f, 0), 1.0, -inv_d, Mat3::Identity(), e, terms);
    else if (kind == Kind::Symmetry)
      append_side_terms(side(f, 0), 1.0, -inv_d, normal_projector(mesh_.face_area(f)), e, terms);
  }
  std::vector<GradientTerm> out;
  out.reserve(terms.size());
  for (const Term& term : terms) out.push_back({term.cell, term.T, term.h});
  return out;
}

void ElasticityOperator::stiffness(Real t, std::span<const Real> u, std::span<Real> values) {
  std::fill(values.begin(), values.end(), 0.0);
  std::vector<Term> terms;
  const Mat3 I = Mat3::Identity();
  if (nonlinear_) compute_point_deltas(t, u);
  Mat3 G = Mat3::Zero();
  for (Index f = 0; f < mesh_.n_faces(); ++f) {
    const Index p = mesh_.face_owner(f), n = mesh_.face_neighbour(f);
    const Vec3& S = mesh_.face_area(f);
    const Vec3& e = face_e_[f];
    const Real inv_d = 1.0 / face_d_[f];
    terms.clear();
    Mat3 out = I;  // maps the face force to what the cells receive
    if (n >= 0) {
      append_side_terms(side(f, 0), 0.5, -inv_d, I, e, terms);
      append_side_terms(side(f, 1), 0.5, inv_d, I, e, terms);
    } else {
      const ElasticityBoundary& bc = boundaries_[mesh_.face_patch(f)];
      if (bc.kind == Kind::Traction) continue;
      if (bc.kind == Kind::Fixed) {
        append_side_terms(side(f, 0), 1.0, -inv_d, I, e, terms);
      } else {
        out = normal_projector(S);
        append_side_terms(side(f, 0), 1.0, -inv_d, out, e, terms);
      }
    }
    // F = mu (G S + G^T S) + lambda tr(G) S + G sigma0 S with G = a h^T, a = T u_c:
    // dF/da = mu (h.S) I + mu h S^T + lambda S h^T + (h.sigma0 S) I; with large deformations
    // the total Lagrangian derivative of the header.
    const Vec3 prestress = material_.residual_stress * S;
    Mat3 Fd = I, FFt = I;
    Vec3 FS = S, stress_S = prestress;
    if (nonlinear_) {
      face_gradient(f, t, u, false, G);
      Fd = I + G;
      FFt = Fd * Fd.transpose();
      FS = Fd * S;
      stress_S += second_piola_kirchhoff(G) * S;
    }
    for (const Term& term : terms) {
      const Vec3 Fh = Fd * term.h;
      Mat3 dF = nonlinear_ ? Mat3(term.h.dot(stress_S) * I + lambda_ * FS * Fh.transpose() +
                                  mu_ * term.h.dot(S) * FFt + mu_ * Fh * FS.transpose())
                           : Mat3((mu_ * term.h.dot(S) + term.h.dot(prestress)) * I +
                                  mu_ * term.h * S.transpose() + lambda_ * S * term.h.transpose());
      Mat3 block = out * dF * term.T;
      sparsity().add_block(values, p, term.cell, -block);
      if (n >= 0) sparsity().add_block(values, n, term.cell, block);
    }
  }
}

std::vector<Real> ElasticityOperator::mass_diagonal() const {
  std::vector<Real> m(size());
  for (Index c = 0; c < mesh_.n_cells(); ++c)
    for (int k = 0; k < dim_; ++k) m[c * dim_ + k] = material_.rho * mesh_.cell_volume(c);
  return m;
}

Vec3 ElasticityOperator::displacement_at(Index cell, const Vec3& x, std::span<const Real> u,
                                         const std::vector<Mat3>& gradients) const {
  return cell_u(u, cell) + gradients[cell] * (x - mesh_.cell_centroid(cell));
}

LinearFunctional ElasticityOperator::displacement_functional(Index cell, const Vec3& x,
                                                             int component) const {
  // u_k(x) = u_c,k + (G_c (x - x_c))_k, G_c = sum_terms (map u_cell) weight^T.
  const Vec3 d = x - mesh_.cell_centroid(cell);
  std::map<Index, Real> weights{{cell * dim_ + component, 1.0}};
  for (const GradientTerm& term : centroid_gradient_terms(cell)) {
    const Real s = term.weight.dot(d);
    for (int l = 0; l < dim_; ++l) weights[term.cell * dim_ + l] += s * term.map(component, l);
  }
  LinearFunctional out;
  for (const auto& [i, w] : weights)
    if (w != 0) out.terms.emplace_back(i, w);
  return out;
}

std::vector<ElasticityOperator::GradientTerm> ElasticityOperator::centroid_gradient_terms(
    Index c) const {
  // G_c = sum_j (v_j - u_c) g_j^T with v_j = M_j u_{cell_j} (or a boundary value).
  std::vector<GradientTerm> out;
  auto points = reconstruction_->points(c);
  Vec3 sum = Vec3::Zero();
  for (std::size_t j = 0; j < points.size(); ++j) {
    const Vec3& g = centroid_gradient_[point_offset_[c] + j];
    sum += g;
    if (points[j].kind != StencilPoint::Kind::BoundaryValue)
      out.push_back({points[j].cell, point_map(points[j]), g});
  }
  out.push_back({c, Mat3::Identity(), -sum});
  return out;
}

void ElasticityOperator::primary_matrix(int k, Real kappa, CsrPattern& pattern,
                                        std::vector<Real>& values) const {
  const Index nc = mesh_.n_cells();
  std::vector<std::set<Index>> stencils(nc);
  for (Index c = 0; c < nc; ++c) stencils[c].insert(c);
  for (Index f = 0; f < mesh_.n_interior_faces(); ++f) {
    stencils[mesh_.face_owner(f)].insert(mesh_.face_neighbour(f));
    stencils[mesh_.face_neighbour(f)].insert(mesh_.face_owner(f));
  }
  BlockSparsity scalar(stencils, 1);
  pattern = scalar.pattern();
  values.assign(pattern.nnz(), 0.0);
  for (Index f = 0; f < mesh_.n_faces(); ++f) {
    const Index p = mesh_.face_owner(f), n = mesh_.face_neighbour(f);
    const Vec3& S = mesh_.face_area(f);
    Real a = kappa * face_e_[f].dot(S) / face_d_[f];
    if (n >= 0) {
      scalar.add(values, p, p, a);
      scalar.add(values, p, n, -a);
      scalar.add(values, n, n, a);
      scalar.add(values, n, p, -a);
      continue;
    }
    const ElasticityBoundary& bc = boundaries_[mesh_.face_patch(f)];
    if (bc.kind == Kind::Fixed) scalar.add(values, p, p, a);
    if (bc.kind == Kind::Symmetry) {
      Vec3 nrm = S.normalized();
      scalar.add(values, p, p, a * nrm[k] * nrm[k]);
    }
  }
}

}  // namespace rfmems
