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
// Each advance over [t, t + dt] integrates the film by IDA (BDF, exact Newton with KLU) under
// the gap linear in time from the last advance's to the segments' heights at t + dt
// (physics/gas/reynolds_prescribed_motion.hpp, the partitioned scheme's film adaptor). The
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
class ReynoldsPrescribedMotion;
class IdaIntegrator;

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
  Real max_knudsen() const override { return state_.max_knudsen; }
  // The film's pressure, its rate and the gaps at the last advance's end (and the Knudsen
  // maximum).
  void save_checkpoint() override;
  void restore_checkpoint() override;

  const std::vector<Real>& pressure() const { return state_.p; }

 private:
  // The gap of each film cell with the beam at `surface`.
  std::vector<Real> gaps(const ImmersedSurface& surface) const;
  GasProperties gas_;
  std::vector<Index> segments_;  // sorted by midpoint x
  Real substrate_y_, wall_x_, tip_x_, rtol_;
  std::unique_ptr<Mesh> strip_;
  std::unique_ptr<ReynoldsFilm> film_;
  std::unique_ptr<ReynoldsPrescribedMotion> motion_;
  std::unique_ptr<IdaIntegrator> ida_;
  // The gap linear in time over the current advance [t0, t1], from h0 to h1.
  Real t0_ = 0, t1_ = 1;
  std::vector<Real> h0_, h1_;
  struct State {
    std::vector<Real> p, p_rate, h;
    Real max_knudsen = 0;
  };
  State state_;  // at the last advance's end
  State saved_;
  bool has_saved_ = false;
};

}  // namespace rfmems
