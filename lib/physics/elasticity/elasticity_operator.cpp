#include "physics/elasticity/elasticity_operator.hpp"

#include <fmt/format.h>
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
                                       VectorField body_force)
    : mesh_(mesh),
      material_(material),
      boundaries_(std::move(boundaries)),
      body_force_(std::move(body_force)),
      dim_(mesh.dim()),
      mu_(material.mu()),
      lambda_(material.lambda()) {
  if (boundaries_.size() != mesh_.patches().size())
    throw InputError(fmt::format("elasticity: {} boundary conditions for {} patches",
                                 boundaries_.size(), mesh_.patches().size()));
  gradient_ = std::make_unique<LeastSquaresGradient>(mesh_, [this](Index f) {
    return boundaries_[mesh_.face_patch(f)].supplies_value();
  });

  const Index nf = mesh_.n_faces();
  owner_weight_.assign(mesh_.n_interior_faces(), 0.5);
  face_e_.resize(nf);
  face_d_.resize(nf);
  for (Index f = 0; f < nf; ++f) {
    const Vec3& xp = mesh_.cell_centroid(mesh_.face_owner(f));
    Vec3 d = (mesh_.is_boundary(f) ? mesh_.face_centroid(f)
                                   : mesh_.cell_centroid(mesh_.face_neighbour(f))) - xp;
    face_d_[f] = d.norm();
    face_e_[f] = d / face_d_[f];
    if (!mesh_.is_boundary(f)) owner_weight_[f] = owner_interpolation_weight(mesh_, f);
  }

  // Stencil of each cell: the cells its face forces depend on.
  std::vector<std::set<Index>> stencils(mesh_.n_cells());
  std::vector<Term> terms;
  for (Index f = 0; f < nf; ++f) {
    Index p = mesh_.face_owner(f), n = mesh_.face_neighbour(f);
    terms.clear();
    if (n >= 0) {
      append_cell_gradient_terms(p, Mat3::Identity(), 1, terms);
      append_cell_gradient_terms(n, Mat3::Identity(), 1, terms);
    } else {
      append_cell_gradient_terms(p, Mat3::Identity(), 1, terms);
    }
    stencils[p].insert(p);
    for (const Term& t : terms) stencils[p].insert(t.cell);
    if (n >= 0) {
      stencils[n].insert(n);
      stencils[p].insert(n);
      stencils[n].insert(p);
      for (const Term& t : terms) stencils[n].insert(t.cell);
    }
  }
  for (Index c = 0; c < mesh_.n_cells(); ++c) stencils[c].insert(c);
  sparsity_ = std::make_unique<BlockSparsity>(stencils, dim_);
}

Vec3 ElasticityOperator::cell_u(std::span<const Real> u, Index c) const {
  Vec3 v = Vec3::Zero();
  for (int k = 0; k < dim_; ++k) v[k] = u[c * dim_ + k];
  return v;
}

Vec3 ElasticityOperator::boundary_value(Index f, Real t, std::span<const Real> u) const {
  const ElasticityBoundary& bc = boundaries_[mesh_.face_patch(f)];
  if (bc.kind == Kind::Symmetry) {
    // Reflection plane: the tangential part of the cell value, zero normal part.
    Vec3 up = cell_u(u, mesh_.face_owner(f));
    return up - normal_projector(mesh_.face_area(f)) * up;
  }
  return bc.at(mesh_.face_centroid(f), t);
}

std::vector<Mat3> ElasticityOperator::cell_gradients(Real t, std::span<const Real> u) const {
  std::vector<Mat3> grad(mesh_.n_cells(), Mat3::Zero());
  for (Index c = 0; c < mesh_.n_cells(); ++c) {
    Vec3 uc = cell_u(u, c);
    Mat3 G = Mat3::Zero();
    for (const GradientNeighbour& nb : gradient_->neighbours(c)) {
      Vec3 value = nb.cell >= 0 ? cell_u(u, nb.cell) : boundary_value(nb.face, t, u);
      G += (value - uc) * nb.weight.transpose();
    }
    grad[c] = G;
  }
  return grad;
}

Vec3 ElasticityOperator::face_force(const Mat3& G, const Vec3& S) const {
  return mu_ * (G * S + G.transpose() * S) + lambda_ * G.trace() * S;
}

void ElasticityOperator::internal_residual(Real t, std::span<const Real> u, std::span<Real> r) {
  std::fill(r.begin(), r.end(), 0.0);
  const std::vector<Mat3> grad = cell_gradients(t, u);
  auto add = [&](Index c, const Vec3& v) {
    for (int k = 0; k < dim_; ++k) r[c * dim_ + k] += v[k];
  };
  for (Index f = 0; f < mesh_.n_faces(); ++f) {
    const Index p = mesh_.face_owner(f), n = mesh_.face_neighbour(f);
    const Vec3& S = mesh_.face_area(f);
    const Vec3& e = face_e_[f];
    const Mat3 project = Mat3::Identity() - e * e.transpose();
    const Mat3 reflect = Mat3::Identity() - 2 * e * e.transpose();
    if (n >= 0) {
      Real w = owner_weight_[f];
      Mat3 G = (w * grad[p] + (1 - w) * grad[n]) * project +
               (cell_u(u, n) - cell_u(u, p)) / face_d_[f] * e.transpose();
      Vec3 F = face_force(G, S);
      add(p, -F);
      add(n, F);
      continue;
    }
    const ElasticityBoundary& bc = boundaries_[mesh_.face_patch(f)];
    if (bc.kind == Kind::Traction) {
      add(p, -bc.at(mesh_.face_centroid(f), t) * S.norm());
      continue;
    }
    // Normal derivative from the parabola through u_P and u_b with slope G_P e at P
    // (second order where the boundary gradient is exact for quadratics).
    Mat3 G = grad[p] * reflect + 2 * (boundary_value(f, t, u) - cell_u(u, p)) / face_d_[f] * e.transpose();
    Vec3 F = face_force(G, S);
    if (bc.kind == Kind::Symmetry) F = normal_projector(S) * F;
    add(p, -F);
  }
  if (body_force_)
    for (Index c = 0; c < mesh_.n_cells(); ++c)
      add(c, -body_force_(mesh_.cell_centroid(c), t) * mesh_.cell_volume(c));
}

void ElasticityOperator::append_cell_gradient_terms(Index c, const Mat3& project, Real scale,
                                                    std::vector<Term>& terms) const {
  // G_c = sum_j (u_j - u_c) g_j^T with u_j a cell value, a symmetry reflection S u_owner, or a
  // constant Dirichlet value (no term). Right-multiplied by `project` and scaled.
  for (const GradientNeighbour& nb : gradient_->neighbours(c)) {
    Vec3 h = scale * (project * nb.weight);
    if (nb.cell >= 0) {
      terms.push_back({nb.cell, Mat3::Identity(), h});
    } else if (boundaries_[mesh_.face_patch(nb.face)].kind == Kind::Symmetry) {
      // The reflected value belongs to the face's own cell (a second-ring face in a
      // quadratic fit is not on c).
      terms.push_back({mesh_.face_owner(nb.face),
                       Mat3::Identity() - normal_projector(mesh_.face_area(nb.face)), h});
    }
  }
  terms.push_back({c, Mat3::Identity(), -scale * (project * gradient_->weight_sum(c))});
}

void ElasticityOperator::stiffness(Real, std::span<const Real>, std::span<Real> values) {
  std::fill(values.begin(), values.end(), 0.0);
  std::vector<Term> terms;
  for (Index f = 0; f < mesh_.n_faces(); ++f) {
    const Index p = mesh_.face_owner(f), n = mesh_.face_neighbour(f);
    const Vec3& S = mesh_.face_area(f);
    const Vec3& e = face_e_[f];
    const Mat3 project = Mat3::Identity() - e * e.transpose();
    const Vec3 direct = e / face_d_[f];
    terms.clear();
    Mat3 out = Mat3::Identity();  // maps the face force to what the cell receives
    if (n >= 0) {
      Real w = owner_weight_[f];
      append_cell_gradient_terms(p, project, w, terms);
      append_cell_gradient_terms(n, project, 1 - w, terms);
      terms.push_back({n, Mat3::Identity(), direct});
      terms.push_back({p, Mat3::Identity(), -direct});
    } else {
      const ElasticityBoundary& bc = boundaries_[mesh_.face_patch(f)];
      if (bc.kind == Kind::Traction) continue;
      append_cell_gradient_terms(p, Mat3::Identity() - 2 * e * e.transpose(), 1, terms);
      terms.push_back({p, Mat3::Identity(), -2 * direct});
      if (bc.kind == Kind::Symmetry) {
        Mat3 nn = normal_projector(S);
        terms.push_back({p, Mat3::Identity() - nn, 2 * direct});
        out = nn;
      }
    }
    // F = mu (G S + G^T S) + lambda tr(G) S with G = a h^T, a = T u_c:
    // dF/da = mu (h.S) I + mu h S^T + lambda S h^T.
    for (const Term& term : terms) {
      Mat3 dF = mu_ * term.h.dot(S) * Mat3::Identity() + mu_ * term.h * S.transpose() +
                lambda_ * S * term.h.transpose();
      Mat3 block = out * dF * term.T;
      sparsity_->add_block(values, p, term.cell, -block);
      if (n >= 0) sparsity_->add_block(values, n, term.cell, block);
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
