// The ESBGK gas in the coupled immersed-boundary switch: the ImmersedGasModel
// (immersed_gas.hpp) that wraps ImmersedKineticGas (lib/ibm) on the switch's background mesh.
//
// reset(surface): a fresh gas, the body at rest, the equilibrium at (rho0 = p0 / (R T0), 0, T0)
// in every FLUID cell. advance(surface, v, t, dt): ImmersedKineticGas::step, i.e. mark, rebuild
// what changed, the IB-face distributions (thesis three steps), one implicit gas step over
// [t, t + dt], the IB-face forces to the segments (force and moment conserving).
//
// Boundaries of make_switch_background's patches: electrode and substrate diffuse at T0 (the
// thesis's diffuse substrate), left diffuse at T0 (the anchor wall the beam is clamped in),
// top and right pressure at (p0, T0) (the open sides).
#pragma once
#include <memory>
#include <string>

#include "ibm/immersed_gas.hpp"
#include "ibm/immersed_kinetic_gas.hpp"
#include "mesh/mesh.hpp"

namespace rfmems {

struct ImmersedEsbgkSettings {
  KineticGas gas;              // air: R = 287.05, mu(T) = mu0 (T / T_ref)^omega
  Real pressure = 1.36e4;      // ambient p0 [Pa]
  Real temperature = 300;      // ambient and wall T0 [K]
  int velocities = 10;         // per direction (tensor grid n^3)
  Real velocity_extent = 3.5;  // half-width of the grid in thermal speeds sqrt(2 R T0)
  ImmersedGasOptions options;
  // The ranks the gas is distributed over (options.comm is set from it): under mpirun every
  // rank of the program, which must then all run the coupled switch (rfmems-pullin does for
  // gas: esbgk); in a program without MPI the serial communicator.
  Communicator comm = Communicator::world();

  // The n^3 grid over +-velocity_extent thermal speeds at T0, and the gas at rest at (p0, T0).
  VelocityGrid velocity_grid() const;
  GasState ambient() const;
};

struct ImmersedEsbgkStats {  // summed over the steps since reset
  long steps = 0, sweeps = 0, unconverged = 0;
  Real max_residual_ratio = 0;
};

class ImmersedEsbgkGas : public ImmersedGasModel {
 public:
  // background: make_switch_background's mesh (patches electrode, substrate, left, right,
  // top); it must outlive this. substrate_y: the substrate's height (for the Knudsen number).
  ImmersedEsbgkGas(const Mesh& background, ImmersedEsbgkSettings settings, Real substrate_y);
  ~ImmersedEsbgkGas() override;

  std::string name() const override { return "esbgk"; }
  void reset(const ImmersedSurface& surface, Real t0) override;
  std::vector<Vec3> advance(const ImmersedSurface& surface, std::span<const Vec3> segment_velocity,
                            Real t, Real dt) override;
  // lambda(p0, T0) over the smallest beam-substrate gap seen.
  Real max_knudsen() const override { return max_knudsen_; }
  // ImmersedKineticGas's checkpoint (and the Knudsen maximum); stats() keeps counting every
  // step solved, redone ones included (the work).
  void save_checkpoint() override;
  void restore_checkpoint() override;
  void hold_marking(bool hold) override { gas_->hold_marking(hold); }

  Real mean_free_path() const;
  const ImmersedKineticGas& kinetic() const { return *gas_; }
  const GasStepReport& last_step() const { return last_; }
  const ImmersedEsbgkStats& stats() const { return stats_; }

 private:
  void track_gap(const ImmersedSurface& surface);
  const Mesh& background_;
  ImmersedEsbgkSettings settings_;
  Real substrate_y_;
  std::unique_ptr<ImmersedKineticGas> gas_;
  GasStepReport last_;
  ImmersedEsbgkStats stats_;
  Real max_knudsen_ = 0, saved_max_knudsen_ = 0;
};

}  // namespace rfmems
