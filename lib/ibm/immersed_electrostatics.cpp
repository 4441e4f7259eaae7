#include "ibm/immersed_electrostatics.hpp"

#include <fmt/format.h>

#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "core/error.hpp"
#include "ibm/background_partition.hpp"
#include "parallel/ghost_exchange.hpp"
#include "solvers/klu_factorization.hpp"

namespace rfmems {

namespace {

Real normal_distance(const Mesh& mesh, Index f, const Vec3& from, const Vec3& to) {
  return std::abs((to - from).dot(mesh.face_area(f).normalized()));
}

}  // namespace

ImmersedElectrostatics::ImmersedElectrostatics(const Mesh& background,
                                               std::map<std::string, PotentialBoundary> patches,
                                               Real permittivity, IbFaceFlux ib_flux,
                                               LuReuse lu_reuse)
    : mesh_(background), permittivity_(permittivity), ib_flux_(ib_flux), lu_reuse_(lu_reuse) {
  if (background.dim() != 2) throw MeshError("immersed electrostatics: the background is not 2D");
  if (!(permittivity > 0))
    throw InputError(
        fmt::format("immersed electrostatics: permittivity {} is not > 0", permittivity));
  for (const auto& [name, bc] : patches)
    if (background.find_patch(name) < 0)
      throw InputError(
          fmt::format("immersed electrostatics: '{}' is not a background patch", name));
  for (const Patch& p : background.patches()) {
    auto it = patches.find(p.name);
    if (it == patches.end())
      throw InputError(fmt::format("immersed electrostatics: no condition for patch '{}'", p.name));
    if (it->second.kind == PotentialBoundary::Kind::Floating)
      throw InputError(
          fmt::format("immersed electrostatics: patch '{}': floating conductors "
                      "are not supported here",
                      p.name));
    boundary_.push_back(it->second);
  }
}

// What a rank keeps between distributed solves: the partition, its FLUID cells (owned, then
// ghosts) with their exchange, the matrix and the solver (kept while the pattern holds).
struct ImmersedElectrostatics::Distributed {
  std::vector<int> owner;   // per background cell
  std::vector<Index> cell;  // per local unknown: its background cell
  GhostExchange exchange;
  DistributedMatrix matrix;
  std::unique_ptr<DistributedLinearSolver> solver;
};

ImmersedElectrostatics::~ImmersedElectrostatics() = default;
ImmersedElectrostatics::ImmersedElectrostatics(ImmersedElectrostatics&&) noexcept = default;

void ImmersedElectrostatics::set_lu_reuse(LuReuse reuse) {
  lu_reuse_ = reuse;
  lu_.reset();
}

bool ImmersedElectrostatics::uses_gradient(const IbInterpolation& ib, Index k) const {
  return ib_flux_ == IbFaceFlux::FitGradient && ib.fit(k).degree >= 1;
}

void ImmersedElectrostatics::distribute(const Communicator& comm,
                                        const DistributedLinearOptions& options) {
  comm_ = comm;
  krylov_options_ = options;
  distributed_.reset();
  lu_.reset();
}

void ImmersedElectrostatics::solve_distributed(const CellMarking& marking,
                                               const IbInterpolation& ib,
                                               std::span<const Index> ib_of_face,
                                               Real body_potential) {
  const Index nc = mesh_.n_cells();
  if (!distributed_) {
    distributed_ = std::make_unique<Distributed>();
    distributed_->owner = partition_fluid_background(mesh_, marking, comm_).part;
  }
  Distributed& d = *distributed_;
  const int rank = comm_.rank();
  std::vector<Index> local(nc, -1), cell;
  for (Index c = 0; c < nc; ++c)
    if (marking.cell[c] == CellClass::Fluid && d.owner[c] == rank) {
      local[c] = static_cast<Index>(cell.size());
      cell.push_back(c);
    }
  const Index n_owned = static_cast<Index>(cell.size());
  // Owned rows in background columns; the columns not owned are the ghosts (ascending).
  std::vector<std::vector<std::pair<Index, Real>>> rows(n_owned);
  std::vector<Real> rhs(n_owned);
  std::vector<char> ghost(nc, 0);
  for (Index i = 0; i < n_owned; ++i)
    rhs[i] = assemble_row(cell[i], marking, ib, ib_of_face, body_potential, [&](Index c, Real a) {
      rows[i].emplace_back(c, a);
      if (local[c] < 0) ghost[c] = 1;
    });
  for (Index c = 0; c < nc; ++c)
    if (ghost[c]) {
      local[c] = static_cast<Index>(cell.size());
      cell.push_back(c);
    }
  const Index n_local = static_cast<Index>(cell.size());
  // The overlap: the owned rows, then the ghost rows truncated to the local columns.
  std::vector<Eigen::Triplet<Real>> triplets;
  for (Index i = 0; i < n_owned; ++i)
    for (const auto& [c, a] : rows[i]) triplets.emplace_back(i, local[c], a);
  for (Index i = n_owned; i < n_local; ++i)
    assemble_row(cell[i], marking, ib, ib_of_face, body_potential, [&](Index c, Real a) {
      if (local[c] >= 0) triplets.emplace_back(i, local[c], a);
    });
  Eigen::SparseMatrix<Real, Eigen::RowMajor> A(n_local, n_local);
  A.setFromTriplets(triplets.begin(), triplets.end());
  A.makeCompressed();

  DistributedMatrix& m = d.matrix;
  const bool same_pattern = d.solver && cell == d.cell && m.overlap_pattern.nnz() == A.nonZeros() &&
                            std::equal(m.overlap_pattern.row_ptr.begin(),
                                       m.overlap_pattern.row_ptr.end(), A.outerIndexPtr()) &&
                            std::equal(m.overlap_pattern.col_idx.begin(),
                                       m.overlap_pattern.col_idx.end(), A.innerIndexPtr());
  const bool keep = comm_.min(same_pattern ? 1.0 : 0.0) > 0;  // every rank's, or none
  const Index owned_nnz = A.outerIndexPtr()[n_owned];
  m.overlap_values.assign(A.valuePtr(), A.valuePtr() + A.nonZeros());
  m.values.assign(A.valuePtr(), A.valuePtr() + owned_nnz);  // the owned rows come first
  if (!keep) {
    d.solver.reset();
    d.cell = cell;
    std::vector<int> owner_rank(n_local);
    for (Index i = 0; i < n_local; ++i) owner_rank[i] = d.owner[cell[i]];
    d.exchange = GhostExchange(comm_, n_owned, cell, owner_rank);
    m.n_owned = n_owned;
    m.n_local = n_local;
    m.exchange = &d.exchange;
    m.overlap_pattern.row_ptr.assign(A.outerIndexPtr(), A.outerIndexPtr() + n_local + 1);
    m.overlap_pattern.col_idx.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
    m.pattern.row_ptr.assign(A.outerIndexPtr(), A.outerIndexPtr() + n_owned + 1);
    m.pattern.col_idx.assign(A.innerIndexPtr(), A.innerIndexPtr() + owned_nnz);
    d.solver = std::make_unique<DistributedLinearSolver>(comm_, m, krylov_options_);
    ++analyses_;
  } else {
    ++refactorizations_;
  }
  try {
    d.solver->factor();
  } catch (const SolverError&) {
    d.solver.reset();
    throw SolverError(
        "immersed electrostatics: singular subdomain matrix (no potential prescribed?)");
  }
  // The last potential as the initial guess (0 where the cell was not FLUID).
  std::vector<Real> phi(n_owned, 0.0);
  if (static_cast<Index>(potential_.size()) == nc)
    for (Index i = 0; i < n_owned; ++i)
      if (std::isfinite(potential_[cell[i]])) phi[i] = potential_[cell[i]];
  last_krylov_ = d.solver->solve(rhs, phi);
  krylov_iterations_ += last_krylov_.iterations;
  // Each cell's value from its owner (x + 0 = x: the owners' values exactly, on every rank).
  potential_.assign(nc, 0.0);
  for (Index i = 0; i < n_owned; ++i) potential_[cell[i]] = phi[i];
  comm_.sum_in_place(potential_);
  for (Index c = 0; c < nc; ++c)
    if (marking.cell[c] != CellClass::Fluid) potential_[c] = std::numeric_limits<Real>::quiet_NaN();
}

template <class Emit>
Real ImmersedElectrostatics::assemble_row(Index P, const CellMarking& marking,
                                          const IbInterpolation& ib,
                                          std::span<const Index> ib_of_face, Real body_potential,
                                          Emit&& emit) const {
  // Row of cell P: sum_f eps |S| / d (phi_b - phi_P) = 0, written as A phi = b.
  const Mesh& mesh = mesh_;
  auto normal_distance = [&](Index f, const Vec3& from, const Vec3& to) {
    return rfmems::normal_distance(mesh, f, from, to);
  };
  Real rhs = 0;
  const Vec3& xP = mesh.cell_centroid(P);
  for (Index f : mesh.cell_faces(P)) {
    const Real area = mesh.face_area(f).norm();
    if (ib_of_face[f] >= 0) {  // the IB interpolation's fit
      const Index k = ib_of_face[f];
      const Vec3& n_in = marking.ib_face_normal[k];
      if (uses_gradient(ib, k)) {  // eps |S| n . grad P(x_f)
        for (const IbStencilPoint& p : ib.stencil(k)) {
          const Real a = permittivity_ * area * n_in.dot(p.gradient_weight);
          if (p.kind == IbStencilPoint::Kind::FluidCell)
            emit(p.index, a);
          else
            rhs -= a * body_potential;
        }
        continue;
      }
      const Real a = permittivity_ * area / normal_distance(f, xP, mesh.face_centroid(f));
      emit(P, -a);
      for (const IbStencilPoint& p : ib.stencil(k)) {
        if (p.kind == IbStencilPoint::Kind::FluidCell)
          emit(p.index, a * p.weight);
        else
          rhs -= a * p.weight * body_potential;
      }
    } else if (!mesh.is_boundary(f)) {
      const Index N = mesh.face_owner(f) == P ? mesh.face_neighbour(f) : mesh.face_owner(f);
      const Real a = permittivity_ * area / normal_distance(f, xP, mesh.cell_centroid(N));
      emit(P, -a);
      emit(N, a);
    } else {
      const PotentialBoundary& bc = boundary_[mesh.face_patch(f)];
      if (bc.kind != PotentialBoundary::Kind::Potential) continue;  // zero flux
      const Real a = permittivity_ * area / normal_distance(f, xP, mesh.face_centroid(f));
      const Real value = bc.field ? bc.field(mesh.face_centroid(f)) : bc.value;
      emit(P, -a);
      rhs -= a * value;
    }
  }
  return rhs;
}

void ImmersedElectrostatics::solve_serial(const CellMarking& marking, const IbInterpolation& ib,
                                          std::span<const Index> ib_of_face, Real body_potential) {
  const Index nc = mesh_.n_cells();
  std::vector<Index> unknown(nc, -1);
  Index n = 0;
  for (Index c = 0; c < nc; ++c)
    if (marking.cell[c] == CellClass::Fluid) unknown[c] = n++;
  std::vector<Eigen::Triplet<Real>> triplets;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  for (Index P = 0; P < nc; ++P) {
    const Index row = unknown[P];
    if (row < 0) continue;
    rhs[row] = assemble_row(P, marking, ib, ib_of_face, body_potential,
                            [&](Index c, Real a) { triplets.emplace_back(row, unknown[c], a); });
  }
  // Duplicates summed into a compressed row-major matrix, then the project's sparse direct
  // solver (KLU) on its CSR arrays.
  Eigen::SparseMatrix<Real, Eigen::RowMajor> A(n, n);
  A.setFromTriplets(triplets.begin(), triplets.end());
  A.makeCompressed();
  const bool same_pattern =
      lu_ && lu_reuse_ == LuReuse::Reuse && pattern_.n_rows() == n &&
      pattern_.nnz() == A.nonZeros() &&
      std::equal(pattern_.row_ptr.begin(), pattern_.row_ptr.end(), A.outerIndexPtr()) &&
      std::equal(pattern_.col_idx.begin(), pattern_.col_idx.end(), A.innerIndexPtr());
  const std::span<const Real> values(A.valuePtr(), A.nonZeros());
  std::vector<Real> phi(rhs.data(), rhs.data() + n);
  try {
    if (same_pattern) {
      lu_->refactor(values);
      ++refactorizations_;
    } else {
      lu_.reset();
      pattern_.row_ptr.assign(A.outerIndexPtr(), A.outerIndexPtr() + n + 1);
      pattern_.col_idx.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
      lu_ = std::make_unique<KluFactorization>(pattern_, values);
      ++analyses_;
    }
    lu_->solve(phi);
  } catch (const SolverError&) {
    lu_.reset();
    throw SolverError("immersed electrostatics: singular matrix (no potential prescribed?)");
  }
  potential_.assign(nc, std::numeric_limits<Real>::quiet_NaN());
  for (Index c = 0; c < nc; ++c)
    if (unknown[c] >= 0) potential_[c] = phi[unknown[c]];
}

void ImmersedElectrostatics::solve(const CellMarking& marking, const IbInterpolation& ib,
                                   Real body_potential) {
  const Mesh& mesh = mesh_;
  if (ib.n_faces() != static_cast<Index>(marking.ib_faces.size()))
    throw std::invalid_argument("immersed electrostatics: interpolation of another marking");
  std::vector<Index> ib_of_face(mesh.n_faces(), -1);
  for (Index k = 0; k < ib.n_faces(); ++k) ib_of_face[ib.face(k)] = k;
  if (distributed())
    solve_distributed(marking, ib, ib_of_face, body_potential);
  else
    solve_serial(marking, ib, ib_of_face, body_potential);
  // Charge through each IB face: eps (phi_f - phi_P) / d |S|, along the normal into the body.
  ib_face_charge_.assign(ib.n_faces(), 0.0);
  ib_face_normal_ = marking.ib_face_normal;
  ib_face_area_.assign(ib.n_faces(), 0.0);
  for (Index k = 0; k < ib.n_faces(); ++k) {
    const Index f = ib.face(k), P = marking.ib_face_fluid_cell[k];
    const Real area = mesh.face_area(f).norm();
    Real phi_f = 0;
    Vec3 grad = Vec3::Zero();
    for (const IbStencilPoint& p : ib.stencil(k)) {
      const Real v =
          p.kind == IbStencilPoint::Kind::FluidCell ? potential_[p.index] : body_potential;
      phi_f += p.weight * v;
      grad += p.gradient_weight * v;
    }
    if (uses_gradient(ib, k)) {
      ib_face_charge_[k] = permittivity_ * area * marking.ib_face_normal[k].dot(grad);
    } else {
      const Real d = normal_distance(mesh, f, mesh.cell_centroid(P), mesh.face_centroid(f));
      ib_face_charge_[k] = permittivity_ * area * (phi_f - potential_[P]) / d;
    }
    ib_face_area_[k] = area;
  }
}

Real ImmersedElectrostatics::body_charge() const {
  return std::accumulate(ib_face_charge_.begin(), ib_face_charge_.end(), 0.0);
}

std::vector<Vec3> ImmersedElectrostatics::ib_face_forces() const {
  // |E_n| = sigma / eps; pressure eps E_n^2 / 2 = sigma^2 / (2 eps), out of the body (-n).
  std::vector<Vec3> f;
  for (std::size_t k = 0; k < ib_face_charge_.size(); ++k) {
    const Real sigma = ib_face_charge_[k] / ib_face_area_[k];
    f.push_back(-0.5 * sigma * sigma / permittivity_ * ib_face_area_[k] * ib_face_normal_[k]);
  }
  return f;
}

}  // namespace rfmems
