// The squeeze film under the beam of the immersed switch (the "reynolds" model of the gas
// slot, immersed_gas.hpp): the isothermal compressible Reynolds equation of the plate's film
// (physics/gas/reynolds_film.hpp, with its exact Jacobian and Veijola's rarefaction factor) on
// a strip of cells along the beam's facing side,
//
//   d(p h)/dt = d/dx( h^3 p Q(Kn) / (12 mu) dp/dx ),   Kn = lambda(p) / h,
//
// one film cell per surface segment of the facing side over the substrate (its x extent at
// rest, clipped to [wall_x, tip_x]; unit depth: the plane scene's flow runs only along the
// beam), h the segment midpoint's height above the substrate. Ends: zero flux at the anchor
// (the wall), p = p_a at the open tip (on the end face, half a cell out).
//
// Each advance over [t, t + dt] steps the film under the gap linear in time from the last
// advance's to the segments' heights at t + dt (physics/gas/prescribed_gap_film.hpp). The
// film force on segment k is -(p_k - p_a) A_k n_k (the outward normal of the facing side points
// at the substrate, so a compressed film pushes the beam up).
#pragma once
#include <memory>
#include <vector>

#include "ibm/immersed_gas.hpp"
#include "materials/gas_properties.hpp"

namespace rfmems {

class Mesh;
class ReynoldsFilm;
class PrescribedGapFilm;

class ImmersedReynoldsFilm : public ImmersedGasModel {
 public:
  // segments: the facing side's surface segments (their order along x is found here), each
  // clipped to [wall_x, tip_x] along x; substrate_y: the substrate's height; wall_x: the
  // anchor wall (zero flux); tip_x: where the film opens (the beam's free end). rtol: the film
  // integration's relative tolerance (its absolute one: rtol p_a).
  ImmersedReynoldsFilm(const GasProperties& gas, std::vector<Index> segments, Real substrate_y,
                       Real wall_x, Real tip_x, Real rtol = 1e-6);
  ~ImmersedReynoldsFilm() override;

  std::string name() const override { return "reynolds"; }
  void reset(const ImmersedSurface& surface, Real t0) override;
  std::vector<Vec3> advance(const ImmersedSurface& surface, std::span<const Vec3> segment_velocity,
                            Real t, Real dt) override;
  Real max_knudsen() const override;
  void save_checkpoint() override;
  void restore_checkpoint() override;

  const std::vector<Real>& pressure() const;

 private:
  PrescribedGapFilm& stepper() const;  // InputError before reset
  // The gap of each film cell with the beam at `surface`.
  std::vector<Real> gaps(const ImmersedSurface& surface) const;
  GasProperties gas_;
  std::vector<Index> segments_;  // sorted by midpoint x
  Real substrate_y_, wall_x_, tip_x_, rtol_;
  std::unique_ptr<Mesh> strip_;
  std::unique_ptr<ReynoldsFilm> film_;
  std::unique_ptr<PrescribedGapFilm> stepped_;
};

}  // namespace rfmems
