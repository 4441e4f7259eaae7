// ElectrostaticSolver: face fluxes as linear forms in the unknowns (cell potentials and
// floating conductor potentials), assembled into one sparse matrix and solved with KLU.
// See electrostatic_solver.hpp for the discretisation.
#include "physics/electrostatics/electrostatic_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>

#include "core/error.hpp"
#include "fv/polynomial_reconstruction.hpp"
#include "solvers/klu_factorization.hpp"

namespace rfmems {

// sum_k coefficient_k u_{index_k} + constant.
struct ElectrostaticSolver::Form {
  std::vector<std::pair<Index, Real>> terms;
  Real constant = 0;
  void add(Index i, Real a) { terms.emplace_back(i, a); }
};

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

ElectrostaticSolver::ElectrostaticSolver(const Mesh& mesh,
                                         std::map<std::string, PotentialBoundary> boundaries,
                                         ElectrostaticsOptions options)
    : mesh_(mesh), options_(options) {
  if (!(options_.permittivity > 0))
    throw InputError(
        fmt::format("electrostatics: permittivity {} is not > 0", options_.permittivity));
  if (options_.reconstruction_degree < 0 || options_.reconstruction_degree > 2)
    throw InputError(fmt::format("electrostatics: reconstruction degree {} is not 0, 1 or 2",
                                 options_.reconstruction_degree));
  const auto& patches = mesh.patches();
  for (const auto& [name, bc] : boundaries)
    if (mesh.find_patch(name) < 0)
      throw InputError(fmt::format("electrostatics: boundary '{}' is not a mesh patch", name));
  n_unknowns_ = mesh.n_cells();
  bool has_potential = false;
  for (const Patch& patch : patches) {
    auto it = boundaries.find(patch.name);
    if (it == boundaries.end())
      throw InputError(
          fmt::format("electrostatics: no boundary condition for patch '{}'", patch.name));
    boundary_.push_back(it->second);
    const auto kind = it->second.kind;
    has_potential = has_potential || kind == PotentialBoundary::Kind::Potential;
    floating_unknown_.push_back(kind == PotentialBoundary::Kind::Floating ? n_unknowns_++ : -1);
  }
  // Without a prescribed potential phi is defined up to a constant: a singular matrix.
  if (!has_potential)
    throw InputError("electrostatics: no patch has a prescribed potential (phi undetermined)");
}

ElectrostaticSolver::~ElectrostaticSolver() = default;

int ElectrostaticSolver::patch_of(const std::string& name) const {
  const int p = mesh_.find_patch(name);
  if (p < 0) throw InputError(fmt::format("electrostatics: no patch '{}'", name));
  return p;
}

Real ElectrostaticSolver::boundary_value(Index f) const {
  const PotentialBoundary& bc = boundary_[mesh_.face_patch(f)];
  return bc.field ? bc.field(mesh_.face_centroid(f)) : bc.value;
}

// Adds coefficient * (value carried by a stencil point): a cell or mirrored cell potential,
// a prescribed boundary value (to the constant), or a floating conductor potential.
void ElectrostaticSolver::add_point_value(Form& form, Index point_face, Index point_cell,
                                          bool is_face, Real coefficient) const {
  if (!is_face) {
    form.add(point_cell, coefficient);
    return;
  }
  const int p = mesh_.face_patch(point_face);
  if (floating_unknown_[p] >= 0)
    form.add(floating_unknown_[p], coefficient);
  else
    form.constant += coefficient * boundary_value(point_face);
}

// Adds a p_c(x) + b . grad p_c(x) with p_c(x) = u_c + sum_j v_j (u_j - u_c).
void ElectrostaticSolver::add_reconstruction(Form& form, Index c, const Vec3& x,
                                             Real value_coefficient,
                                             const Vec3& gradient_coefficient) const {
  form.add(c, value_coefficient);
  if (!reconstruction_) return;
  thread_local std::vector<Real> value;
  thread_local std::vector<Vec3> gradient;
  reconstruction_->weights_at(c, x, value, gradient);
  auto points = reconstruction_->points(c);
  for (std::size_t j = 0; j < points.size(); ++j) {
    const Real a = value_coefficient * value[j] + gradient_coefficient.dot(gradient[j]);
    const StencilPoint& p = points[j];
    const bool is_face = p.kind == StencilPoint::Kind::BoundaryValue;
    add_point_value(form, p.face, p.cell, is_face, a);
    form.add(c, -a);
  }
}

void ElectrostaticSolver::solve(const std::function<Real(const Vec3&)>& charge_density) {
  using Kind = PotentialBoundary::Kind;
  auto start = std::chrono::steady_clock::now();
  const Index nc = mesh_.n_cells(), nf = mesh_.n_faces();
  const Real eps = options_.permittivity;

  if (options_.reconstruction_degree > 0)
    reconstruction_ = std::make_unique<PolynomialReconstruction>(
        mesh_,
        [&](Index f) {
          return boundary_[mesh_.face_patch(f)].kind == Kind::ZeroFlux ? BoundaryPoint::Mirror
                                                                       : BoundaryPoint::Value;
        },
        options_.reconstruction_degree);

  // Face flux forms.
  std::vector<Form> flux(nf);
  for (Index f = 0; f < nf; ++f) {
    const Index P = mesh_.face_owner(f);
    const Vec3& S = mesh_.face_area(f);
    const Real area = S.norm();
    const Vec3 n = S / area;
    const Vec3& xf = mesh_.face_centroid(f);
    Form& F = flux[f];
    if (!mesh_.is_boundary(f)) {
      const Index N = mesh_.face_neighbour(f);
      const Real dn = (mesh_.cell_centroid(N) - mesh_.cell_centroid(P)).dot(n);
      if (!(dn > 0))
        throw MeshError(
            fmt::format("electrostatics: face {} at ({:.4g}, {:.4g}, {:.4g}): the "
                        "centroids of cells {} and {} are not on opposite sides",
                        f, xf.x(), xf.y(), xf.z(), P, N));
      add_reconstruction(F, P, xf, -eps * area / dn, 0.5 * eps * area * n);
      add_reconstruction(F, N, xf, eps * area / dn, 0.5 * eps * area * n);
      continue;
    }
    const int patch = mesh_.face_patch(f);
    if (boundary_[patch].kind == Kind::ZeroFlux) continue;
    const Real dn = (xf - mesh_.cell_centroid(P)).dot(n);  // > 0 by Mesh::check_quality
    add_reconstruction(F, P, xf, -eps * area / dn, eps * area * n);
    add_point_value(F, f, -1, true, eps * area / dn);
  }

  // Rows: cell c:  -sum_f s_f F_f = rho_c V_c;  floating conductor k:  sum_f F_f = Q_k.
  std::vector<std::pair<Index, std::pair<Index, Real>>> entries;
  std::vector<Real> rhs(n_unknowns_, 0.0);
  auto add_row = [&](Index row, const Form& form, Real sign) {
    for (auto [col, a] : form.terms) entries.push_back({row, {col, sign * a}});
    rhs[row] -= sign * form.constant;
  };
  for (Index c = 0; c < nc; ++c) {
    for (Index f : mesh_.cell_faces(c)) add_row(c, flux[f], mesh_.face_owner(f) == c ? -1.0 : 1.0);
    if (charge_density) rhs[c] += charge_density(mesh_.cell_centroid(c)) * mesh_.cell_volume(c);
  }
  for (std::size_t p = 0; p < boundary_.size(); ++p) {
    if (floating_unknown_[p] < 0) continue;
    const Patch& patch = mesh_.patches()[p];
    for (Index f = patch.first_face; f < patch.first_face + patch.n_faces; ++f)
      add_row(floating_unknown_[p], flux[f], 1.0);
    rhs[floating_unknown_[p]] += boundary_[p].value;
  }
  std::sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) {
    return a.first != b.first ? a.first < b.first : a.second.first < b.second.first;
  });
  CsrPattern pattern;
  pattern.row_ptr.assign(n_unknowns_ + 1, 0);
  std::vector<Real> values;
  for (std::size_t k = 0; k < entries.size(); ++k) {
    const auto& [row, entry] = entries[k];
    if (k > 0 && entries[k - 1].first == row && entries[k - 1].second.first == entry.first) {
      values.back() += entry.second;  // same (row, col): merge
      continue;
    }
    pattern.col_idx.push_back(entry.first);
    values.push_back(entry.second);
    ++pattern.row_ptr[row + 1];
  }
  for (Index r = 0; r < n_unknowns_; ++r) pattern.row_ptr[r + 1] += pattern.row_ptr[r];
  stats_.assembly_seconds = seconds_since(start);
  stats_.n_unknowns = n_unknowns_;
  stats_.nnz = pattern.nnz();

  // Factorise: reuse the symbolic analysis when only the values changed.
  start = std::chrono::steady_clock::now();
  stats_.symbolic_reused =
      lu_ && pattern.row_ptr == pattern_.row_ptr && pattern.col_idx == pattern_.col_idx;
  if (stats_.symbolic_reused) {
    lu_->refactor(values);
  } else {
    lu_.reset();
    lu_ = std::make_unique<KluFactorization>(pattern, values);
    pattern_ = std::move(pattern);
  }
  stats_.factor_seconds = seconds_since(start);

  start = std::chrono::steady_clock::now();
  solution_ = rhs;
  lu_->solve(solution_);
  face_flux_.assign(nf, 0.0);
  for (Index f = 0; f < nf; ++f) {
    Real value = flux[f].constant;
    for (auto [col, a] : flux[f].terms) value += a * solution_[col];
    face_flux_[f] = value;
  }
  stats_.solve_seconds = seconds_since(start);
}

std::span<const Real> ElectrostaticSolver::potential() const {
  if (solution_.empty()) throw std::logic_error("electrostatics: potential() before solve()");
  return {solution_.data(), static_cast<std::size_t>(mesh_.n_cells())};
}

Real ElectrostaticSolver::patch_potential(const std::string& name) const {
  const int p = patch_of(name);
  const PotentialBoundary& bc = boundary_[p];
  if (floating_unknown_[p] >= 0) return solution_.at(floating_unknown_[p]);
  if (bc.kind == PotentialBoundary::Kind::Potential && !bc.field) return bc.value;
  throw InputError(
      fmt::format("electrostatics: patch '{}' is not a conductor at one potential", name));
}

Vec3 ElectrostaticSolver::reconstructed_gradient(Index c, const Vec3& x) const {
  if (!reconstruction_) return Vec3::Zero();
  std::vector<Real> value;
  std::vector<Vec3> gradient;
  reconstruction_->weights_at(c, x, value, gradient);
  auto points = reconstruction_->points(c);
  Vec3 g = Vec3::Zero();
  for (std::size_t j = 0; j < points.size(); ++j) {
    const StencilPoint& p = points[j];
    Real u = 0;
    if (p.kind != StencilPoint::Kind::BoundaryValue) {
      u = solution_[p.cell];
    } else {
      const int patch = mesh_.face_patch(p.face);
      u = floating_unknown_[patch] >= 0 ? solution_[floating_unknown_[patch]]
                                        : boundary_value(p.face);
    }
    g += gradient[j] * (u - solution_[c]);
  }
  return g;
}

SurfaceLoad ElectrostaticSolver::surface_load(const std::string& name) const {
  if (solution_.empty()) throw std::logic_error("electrostatics: surface_load() before solve()");
  const int p = patch_of(name);
  const PotentialBoundary& bc = boundary_[p];
  const bool equipotential = bc.kind == PotentialBoundary::Kind::Floating ||
                             (bc.kind == PotentialBoundary::Kind::Potential && !bc.field);
  const Real eps = options_.permittivity;
  const Patch& patch = mesh_.patches()[p];
  SurfaceLoad load;
  for (Index f = patch.first_face; f < patch.first_face + patch.n_faces; ++f) {
    const Real area = mesh_.face_area(f).norm();
    const Vec3 n = mesh_.face_area(f) / area;
    const Real sigma = face_flux_[f] / area;  // eps dphi/dn
    Vec3 E = -(sigma / eps) * n;
    if (!equipotential) {
      const Vec3 g = reconstructed_gradient(mesh_.face_owner(f), mesh_.face_centroid(f));
      E -= g - g.dot(n) * n;  // tangential part from the cell's reconstruction
    }
    const Vec3 t = -eps * (E * E.dot(n) - 0.5 * E.squaredNorm() * n);
    load.faces.push_back(f);
    load.charge_density.push_back(sigma);
    load.field.push_back(E);
    load.traction.push_back(t);
    load.force += t * area;
    load.charge += sigma * area;
  }
  return load;
}

}  // namespace rfmems
