// Transfer of loads from the background mesh's IB faces to the structure's surface faces
// (the segments of the ImmersedSurface), and the dual map of the wall velocity back (thesis
// ch. 6: "the fluid traction and electrostatic forces are calculated on the background
// mesh and are interpolated back to the solid surface mesh").
//
// A force F_k = t_k |S_k| on IB face k (centroid x_k; t_k the gas or Maxwell traction on the
// body side) goes to three consecutive segments J_k = {s-1, s, s+1} around the segment s that
// holds the point p_k of the surface nearest x_k:
//
//   f_j = w_j F_k + c_j (F_k . (z x a_k)),   j in J_k,
//
//   w_j   linear weights in arc length between the two segment midpoints that bracket p_k
//         (sum w_j = 1, so sum_j f_j = F_k), and P_k = sum_j w_j y_j (y_j = midpoints);
//   a_k = x_k - P_k, the offset of the face from where the w's put the force;
//   c_j = z x (y_j - y_bar) / sum_i |y_i - y_bar|^2 (y_bar the mean of the three midpoints):
//         a couple (sum_j c_j = 0) whose moment sum_j y_j x c_j = z cancels the offset's,
//
// so that sum_j f_j = F_k and sum_j y_j x f_j = x_k x F_k exactly: the total force and the
// total moment about any point are conserved to round-off whatever the traction.
//
// The wall velocity goes the other way by the adjoint (transpose) of this map,
//   u(x_k) = sum_j w_j u_j + (z x a_k) sum_j c_j . u_j,
// so the power balances for any loads and velocities, sum_k F_k . u(x_k) = sum_j f_j . u_j,
// and a rigid motion u = U + omega z x x of the segments is reproduced exactly at every x_k.
#pragma once
#include <array>
#include <span>
#include <vector>

#include "core/types.hpp"
#include "ibm/cell_marking.hpp"
#include "ibm/immersed_surface.hpp"
#include "mesh/mesh.hpp"

namespace rfmems {

class ForceTransfer {
 public:
  // Built for the IB faces of `marking` (their order) and the segments of `body`.
  ForceTransfer(const Mesh& background, const CellMarking& marking, const ImmersedSurface& body);

  Index n_ib_faces() const { return static_cast<Index>(maps_.size()); }
  Index n_segments() const { return n_segments_; }

  // Forces per IB face (N, 2D: N/m) -> forces per surface segment.
  std::vector<Vec3> to_surface(std::span<const Vec3> ib_face_forces) const;
  // Velocities per surface segment -> velocity at each IB face centroid (the adjoint map).
  std::vector<Vec3> to_ib_faces(std::span<const Vec3> segment_velocities) const;

  // The IB-face forces of a traction field: F_k = t(x_k, n_k) |S_k|, n_k the unit normal out
  // of the fluid (into the body side).
  template <class Traction>
  std::vector<Vec3> ib_face_forces(Traction&& traction) const {
    std::vector<Vec3> f;
    for (std::size_t k = 0; k < maps_.size(); ++k)
      f.push_back(traction(centroids_[k], normals_[k]) * areas_[k]);
    return f;
  }

 private:
  struct FaceMap {
    std::array<Index, 3> segment;
    std::array<Real, 3> weight;
    std::array<Vec3, 3> couple;  // c_j
    Vec3 z_cross_offset;         // z x a_k
  };
  Index n_segments_ = 0;
  std::vector<FaceMap> maps_;
  std::vector<Vec3> centroids_, normals_;
  std::vector<Real> areas_;
};

}  // namespace rfmems
