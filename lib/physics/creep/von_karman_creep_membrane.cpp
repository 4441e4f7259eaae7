#include "physics/creep/von_karman_creep_membrane.hpp"

#include <algorithm>

namespace rfmems {

VonKarmanCreepMembrane::VonKarmanCreepMembrane(const VonKarmanPlate& plate,
                                               const Eigen::Matrix3d& C)
    : plate_(plate), C_(C) {
  const Mesh& mesh = plate.plate().mesh();
  const Index nc = mesh.n_cells();
  cell_faces_.resize(nc);
  strain_dofs_.resize(nc);
  std::vector<Real> total(nc, 0.0);
  for (Index k = 0; k < plate.n_membrane_faces(); ++k) {
    const Index f = plate.membrane_face(k);
    const Real area = mesh.face_area(f).norm();
    for (Index c : {mesh.face_owner(f), mesh.face_neighbour(f)}) {
      if (c < 0) continue;
      cell_faces_[c].push_back({k, area});
      total[c] += area;
      for (const VonKarmanPlate::GradientWeight& g : plate.face_weights(k))
        if (g.cell >= 0)
          strain_dofs_[c].insert(strain_dofs_[c].end(),
                                 {3 * g.cell + PlateOperator::kW, plate.in_plane_index(g.cell, 0),
                                  plate.in_plane_index(g.cell, 1)});
    }
  }
  for (Index c = 0; c < nc; ++c) {
    for (CellFace& cf : cell_faces_[c]) cf.alpha /= total[c];
    std::vector<Index>& d = strain_dofs_[c];
    std::sort(d.begin(), d.end());
    d.erase(std::unique(d.begin(), d.end()), d.end());
  }
  // The Jacobian's entries, in the order plastic_force_jacobian visits them.
  for (Index k = 0; k < plate.n_membrane_faces(); ++k) {
    const Index f = plate.membrane_face(k);
    const Index p = mesh.face_owner(f), n = mesh.face_neighbour(f);
    for (const VonKarmanPlate::GradientWeight& g : plate.face_weights(k)) {
      if (g.cell < 0) continue;
      for (Index side : {p, n})
        if (side >= 0) structural_entries_.push_back({3 * side + PlateOperator::kW, 3 * g.cell});
    }
    for (Index c : {p, n}) {
      if (c < 0) continue;
      for (Index side : {p, n}) {
        if (side < 0) continue;
        for (Index row : {3 * side + PlateOperator::kW, plate.in_plane_index(side, 0),
                          plate.in_plane_index(side, 1)})
          strain_entries_.push_back({row, c});
      }
    }
  }
}

Vec3 VonKarmanCreepMembrane::face_strain(const VonKarmanPlate::FaceState& s) {
  const Mat3& G = s.gu;
  const Vec3& g = s.gw;
  return Vec3(G(0, 0) + 0.5 * g.x() * g.x(), G(1, 1) + 0.5 * g.y() * g.y(),
              0.5 * (G(0, 1) + G(1, 0)) + 0.5 * g.x() * g.y());
}

Eigen::Matrix<Real, 2, 3> VonKarmanCreepMembrane::traction(const Vec3& S) {
  Eigen::Matrix<Real, 2, 3> T;
  T << S.x(), 0, S.y(), 0, S.y(), S.x();
  return T;
}

std::vector<Vec3> VonKarmanCreepMembrane::cell_strains(Real t, std::span<const Real> y) const {
  std::vector<Vec3> face(plate_.n_membrane_faces());
  for (Index k = 0; k < plate_.n_membrane_faces(); ++k)
    face[k] = face_strain(plate_.face_state(k, t, y));
  std::vector<Vec3> eps(cell_faces_.size(), Vec3::Zero());
  for (std::size_t c = 0; c < cell_faces_.size(); ++c)
    for (const CellFace& cf : cell_faces_[c]) eps[c] += cf.alpha * face[cf.face];
  return eps;
}

void VonKarmanCreepMembrane::strain_derivatives(Real t, std::span<const Real> y, Index c,
                                                std::vector<Vec3>& d) const {
  const std::vector<Index>& dofs = strain_dofs_[c];
  d.assign(dofs.size(), Vec3::Zero());
  auto at = [&](Index dof) -> Vec3& {
    return d[std::lower_bound(dofs.begin(), dofs.end(), dof) - dofs.begin()];
  };
  for (const CellFace& cf : cell_faces_[c]) {
    const Vec3 gw = plate_.face_state(cf.face, t, y).gw;
    for (const VonKarmanPlate::GradientWeight& g : plate_.face_weights(cf.face)) {
      if (g.cell < 0) continue;
      const Vec3& a = g.w;
      const Vec3& u = g.u;
      at(3 * g.cell + PlateOperator::kW) +=
          cf.alpha * Vec3(a.x() * gw.x(), a.y() * gw.y(), 0.5 * (a.x() * gw.y() + a.y() * gw.x()));
      at(plate_.in_plane_index(g.cell, 0)) += cf.alpha * Vec3(u.x(), 0, 0.5 * u.y());
      at(plate_.in_plane_index(g.cell, 1)) += cf.alpha * Vec3(0, u.y(), 0.5 * u.x());
    }
  }
}

Vec3 VonKarmanCreepMembrane::plastic_force(Index k, const std::vector<Vec3>& P) const {
  const Mesh& mesh = plate_.plate().mesh();
  const Index f = plate_.membrane_face(k);
  const Index p = mesh.face_owner(f), n = mesh.face_neighbour(f);
  const Vec3 mean = n >= 0 ? Vec3(0.5 * (P[p] + P[n])) : P[p];
  return -C_ * mean;
}

void VonKarmanCreepMembrane::add_plastic_force(Real t, std::span<const Real> slope_state,
                                               const std::vector<Vec3>& P,
                                               std::span<Real> r) const {
  const Mesh& mesh = plate_.plate().mesh();
  for (Index k = 0; k < plate_.n_membrane_faces(); ++k) {
    const Index f = plate_.membrane_face(k);
    const Index p = mesh.face_owner(f), n = mesh.face_neighbour(f);
    const Vec3 gw = plate_.face_state(k, t, slope_state).gw;
    const Eigen::Vector2d Fu = traction(mesh.face_area(f)) * plastic_force(k, P);
    const Real Fw = gw.x() * Fu.x() + gw.y() * Fu.y();
    r[3 * p + PlateOperator::kW] -= Fw;
    r[plate_.in_plane_index(p, 0)] -= Fu.x();
    r[plate_.in_plane_index(p, 1)] -= Fu.y();
    if (n >= 0) {
      r[3 * n + PlateOperator::kW] += Fw;
      r[plate_.in_plane_index(n, 0)] += Fu.x();
      r[plate_.in_plane_index(n, 1)] += Fu.y();
    }
  }
}

void VonKarmanCreepMembrane::plastic_force_jacobian(Real t, std::span<const Real> y,
                                                    const std::vector<Vec3>& P,
                                                    std::vector<Real>& structural,
                                                    std::vector<Vec3>& strain) const {
  const Mesh& mesh = plate_.plate().mesh();
  structural.clear();
  strain.clear();
  for (Index k = 0; k < plate_.n_membrane_faces(); ++k) {
    const Index f = plate_.membrane_face(k);
    const Index p = mesh.face_owner(f), n = mesh.face_neighbour(f);
    const Vec3 gw = plate_.face_state(k, t, y).gw;
    const Eigen::Matrix<Real, 2, 3> T = traction(mesh.face_area(f));
    const Eigen::Vector2d Fu = T * plastic_force(k, P);
    // dF_w/dw_k = a_k . (N_p S); owner row -, neighbour row +.
    for (const VonKarmanPlate::GradientWeight& g : plate_.face_weights(k)) {
      if (g.cell < 0) continue;
      const Real d = g.w.x() * Fu.x() + g.w.y() * Fu.y();
      structural.push_back(-d);
      if (n >= 0) structural.push_back(d);
    }
    // dF_u/dP_c = -alpha_c T C, dF_w/dP_c = grad w_f . dF_u/dP_c.
    const Real alpha = n >= 0 ? 0.5 : 1.0;
    const Eigen::Matrix<Real, 2, 3> dFu = -alpha * T * C_;
    const Vec3 dFw = (gw.x() * dFu.row(0) + gw.y() * dFu.row(1)).transpose();
    for (Index c : {p, n}) {
      if (c < 0) continue;
      for (Index side : {p, n}) {
        if (side < 0) continue;
        const Real sign = side == p ? -1.0 : 1.0;
        strain.push_back(sign * dFw);
        strain.push_back(sign * dFu.row(0).transpose());
        strain.push_back(sign * dFu.row(1).transpose());
      }
    }
  }
}

}  // namespace rfmems
