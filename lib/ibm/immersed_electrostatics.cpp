#include "ibm/immersed_electrostatics.hpp"

#include <fmt/format.h>

#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "core/error.hpp"
#include "solvers/klu_factorization.hpp"

namespace rfmems {

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

ImmersedElectrostatics::~ImmersedElectrostatics() = default;
ImmersedElectrostatics::ImmersedElectrostatics(ImmersedElectrostatics&&) noexcept = default;

void ImmersedElectrostatics::set_lu_reuse(LuReuse reuse) {
  lu_reuse_ = reuse;
  lu_.reset();
}

bool ImmersedElectrostatics::uses_gradient(const IbInterpolation& ib, Index k) const {
  return ib_flux_ == IbFaceFlux::FitGradient && ib.fit(k).degree >= 1;
}

void ImmersedElectrostatics::solve(const CellMarking& marking, const IbInterpolation& ib,
                                   Real body_potential) {
  const Mesh& mesh = mesh_;
  const Index nc = mesh.n_cells();
  std::vector<Index> unknown(nc, -1);
  Index n = 0;
  for (Index c = 0; c < nc; ++c)
    if (marking.cell[c] == CellClass::Fluid) unknown[c] = n++;
  if (ib.n_faces() != static_cast<Index>(marking.ib_faces.size()))
    throw std::invalid_argument("immersed electrostatics: interpolation of another marking");

  // Row of cell P: sum_f eps |S| / d (phi_b - phi_P) = 0, written as A phi = b.
  std::vector<Eigen::Triplet<Real>> triplets;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  std::vector<Index> ib_of_face(mesh.n_faces(), -1);
  for (Index k = 0; k < ib.n_faces(); ++k) ib_of_face[ib.face(k)] = k;
  auto normal_distance = [&](Index f, const Vec3& from, const Vec3& to) {
    return std::abs((to - from).dot(mesh.face_area(f).normalized()));
  };
  for (Index P = 0; P < nc; ++P) {
    const Index row = unknown[P];
    if (row < 0) continue;
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
              triplets.emplace_back(row, unknown[p.index], a);
            else
              rhs[row] -= a * body_potential;
          }
          continue;
        }
        const Real a = permittivity_ * area / normal_distance(f, xP, mesh.face_centroid(f));
        triplets.emplace_back(row, row, -a);
        for (const IbStencilPoint& p : ib.stencil(k)) {
          if (p.kind == IbStencilPoint::Kind::FluidCell)
            triplets.emplace_back(row, unknown[p.index], a * p.weight);
          else
            rhs[row] -= a * p.weight * body_potential;
        }
      } else if (!mesh.is_boundary(f)) {
        const Index N = mesh.face_owner(f) == P ? mesh.face_neighbour(f) : mesh.face_owner(f);
        const Real a = permittivity_ * area / normal_distance(f, xP, mesh.cell_centroid(N));
        triplets.emplace_back(row, row, -a);
        triplets.emplace_back(row, unknown[N], a);
      } else {
        const PotentialBoundary& bc = boundary_[mesh.face_patch(f)];
        if (bc.kind != PotentialBoundary::Kind::Potential) continue;  // zero flux
        const Real a = permittivity_ * area / normal_distance(f, xP, mesh.face_centroid(f));
        const Real value = bc.field ? bc.field(mesh.face_centroid(f)) : bc.value;
        triplets.emplace_back(row, row, -a);
        rhs[row] -= a * value;
      }
    }
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
      const Real d = normal_distance(f, mesh.cell_centroid(P), mesh.face_centroid(f));
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
