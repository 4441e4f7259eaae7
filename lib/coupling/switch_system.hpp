// The transient system of an electrostatically actuated switch, as IDA integrates it, and
// what a pull-in run needs to read from its state. One implementation per gas model:
//
//   ActuatedStructureSystem (this file): no gas; the structure (inertia of chosen components
//     neglected: core/reduced_inertia_system.hpp) under the parallel-plate force, monolithic;
//   SqueezeFilmSwitchSystem (squeeze_film_switch_system.hpp): plus the Reynolds film
//     pressure under the structure, monolithic on the plate's mesh.
#pragma once
#include <memory>
#include <vector>

#include "core/reduced_inertia_system.hpp"
#include "physics/electrostatics/parallel_plate_actuation.hpp"

namespace rfmems {

// What each unknown of a switch system is, for its error weight (state_tolerances.hpp):
// an inertial structural displacement [m], a quasi-static (algebraic) structural unknown (the
// plate's rotations), the velocity of an inertial displacement [m/s], a film pressure [Pa].
enum class StateKind { Displacement, QuasiStatic, Velocity, Pressure };

class SwitchSystem : public SystemOperator {
 public:
  // One kind per unknown (empty: not classified; the scalar tolerance is used).
  virtual std::vector<StateKind> state_kinds() const { return {}; }
  // The state at rest (zero displacement, ambient gas) and a derivative consistent with it
  // at t0 except for the algebraic components (IDACalcIC completes them).
  virtual void initial_state(Real t0, std::vector<Real>& y, std::vector<Real>& yp) = 0;
  // Structural displacement and velocity of unknown i of the structure.
  virtual Real displacement(std::span<const Real> y, Index i) const = 0;
  virtual Real velocity(std::span<const Real> y, std::span<const Real> yp, Index i) const = 0;
  virtual Real gas_force(std::span<const Real> /*y*/) const { return 0.0; }
  virtual ParallelPlateActuation& actuation() = 0;
  virtual const ParallelPlateActuation& actuation() const = 0;
  // The actuation's smallest gap, and its force along the gap axis on the structure [N]
  // (negative: closing); the structure's unknowns lead the state.
  Real min_gap(std::span<const Real> y) const { return actuation().min_gap(y); }
  Real electrostatic_force(Real t, std::span<const Real> y) const {
    return actuation().total_force(actuation().voltage_squared(t), y);
  }
  // The dielectric's contact force (positive: opening; contact_penalty.hpp) and the fraction
  // of the electrode's area in contact.
  Real contact_force(Real t, std::span<const Real> y) const {
    return actuation().contact_force(actuation().voltage_squared(t), y);
  }
  Real contact_fraction(std::span<const Real> y) const { return actuation().contact_fraction(y); }
};

struct SwitchScene;

// The parallel-plate scene's monolithic IDA system (switch_scene.hpp): the structure under the
// force (ActuatedStructureSystem), with the Reynolds film on the plate's cells
// (SqueezeFilmSwitchSystem, squeeze_film_switch_system.hpp) when the scene has one.
std::unique_ptr<SwitchSystem> make_switch_system(SwitchScene& scene);

// The plate's unknown over each film cell of a scene with a film (the film's cells are the
// plate's: the gap-facing unknown of each, as the structure has them); empty without one.
std::vector<Index> film_unknowns(const SwitchScene& scene);

// The kinds of a ReducedInertiaSystem's state [y (n); v]: displacement or quasi-static by
// whether y_i carries inertia, then the velocities.
std::vector<StateKind> reduced_inertia_state_kinds(const ReducedInertiaSystem& system, Index n);

class ActuatedStructureSystem : public SwitchSystem {
 public:
  ActuatedStructureSystem(ParallelPlateActuation& actuation, std::vector<bool> quasi_static);

  Index size() const override { return system_.size(); }
  std::vector<Real> differential_components() const override {
    return system_.differential_components();
  }
  void residual(Real t, std::span<const Real> y, std::span<const Real> yp,
                std::span<Real> r) override {
    system_.residual(t, y, yp, r);
  }
  const CsrPattern& jacobian_pattern() const override { return system_.jacobian_pattern(); }
  void jacobian(Real t, Real c_j, std::span<const Real> y, std::span<const Real> yp,
                std::span<Real> values) override {
    system_.jacobian(t, c_j, y, yp, values);
  }

  std::vector<StateKind> state_kinds() const override;
  void initial_state(Real t0, std::vector<Real>& y, std::vector<Real>& yp) override;
  Real displacement(std::span<const Real> y, Index i) const override { return y[i]; }
  Real velocity(std::span<const Real> y, std::span<const Real> yp, Index i) const override;
  ParallelPlateActuation& actuation() override { return actuation_; }
  const ParallelPlateActuation& actuation() const override { return actuation_; }

 private:
  ParallelPlateActuation& actuation_;
  ReducedInertiaSystem system_;
};

}  // namespace rfmems
