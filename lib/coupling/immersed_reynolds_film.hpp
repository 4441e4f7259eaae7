// A 1D isothermal compressible Reynolds film under the beam of the immersed switch (the
// "reynolds" model of the gas slot, immersed_gas.hpp; thesis ch. 1 for the equation):
//
//   d(p h)/dt = d/dx( h^3 p Q(Kn) / (12 mu) dp/dx ),   Kn = lambda(p) / h,
//
// Q(Kn) = 1 + 9.638 Kn^1.159 (Veijola 1995, materials/gas_properties.hpp), on the surface
// segments of the beam's facing side that lie over the substrate (one film cell per segment,
// h = the segment midpoint's height above the substrate, dx its length along x). Ends: zero
// flux at the anchor (the wall), p = p_a at the open tip (on the end face, half a cell out).
// Backward Euler over each coupled step; the coefficient h^3 p Q / (12 mu) at the faces is
// lagged in Picard iterations (p stays within a few per cent of p_a: 3-6 iterations to 1e-12),
// each a tridiagonal solve. The film force on segment k is -(p_k - p_a) |S_k| n_k (the outward
// normal of the facing side points at the substrate, so a compressed film pushes the beam up).
//
// Width: plane (per unit depth) - flow only along the beam, as the 2D scene has it.
#pragma once
#include <vector>

#include "coupling/immersed_gas.hpp"
#include "materials/gas_properties.hpp"

namespace rfmems {

class ImmersedReynoldsFilm : public ImmersedGasModel {
 public:
  // segments: the facing side's surface segments (their order along x is found here), each
  // clipped to [wall_x, tip_x] along x; substrate_y: the substrate's height; wall_x: the
  // anchor wall (zero flux); tip_x: where the film opens (the beam's free end).
  ImmersedReynoldsFilm(const GasProperties& gas, std::vector<Index> segments, Real substrate_y,
                       Real wall_x, Real tip_x);

  std::string name() const override { return "reynolds"; }
  void reset(const ImmersedSurface& surface, Real t0) override;
  std::vector<Vec3> advance(const ImmersedSurface& surface, std::span<const Vec3> segment_velocity,
                            Real t, Real dt) override;
  Real max_knudsen() const override { return max_knudsen_; }
  // The film's pressure and gaps at the last step's end (and the Knudsen maximum).
  void save_checkpoint() override;
  void restore_checkpoint() override;

  const std::vector<Real>& pressure() const { return p_; }

 private:
  void geometry(const ImmersedSurface& surface, std::vector<Real>& h, std::vector<Real>& x,
                std::vector<Real>& dx) const;
  GasProperties gas_;
  std::vector<Index> segments_;  // sorted by midpoint x
  Real substrate_y_, wall_x_, tip_x_;
  std::vector<Real> p_, h_;  // per film cell at the last step's end
  Real max_knudsen_ = 0;
  struct Saved {
    std::vector<Real> p, h;
    Real max_knudsen = 0;
    bool valid = false;
  } saved_;
};

}  // namespace rfmems
