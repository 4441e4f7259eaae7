// A structure coupled to a field across its gap (physics/electrostatics/gap_field.hpp) and to
// the gas on its surface (physics/gas/structure_gas.hpp) in partitioned steps: its equilibria and
// the one time loop of every scheme but the monolithic system, whichever structure, field and
// gas.
//
// Equilibria (one KLU factorisation of the linear structure's stiffness K for the whole solve):
//   at a voltage      K u = f(u, V) by the plain fixed point (voltage_control_fixed_point.hpp);
//   at a deflection   of the control, the Aitken-relaxed fixed point with V^2 = delta / l(z)
//                     per iterate (displacement_control_fixed_point.hpp), traced through the
//                     fold by trace_fold (quasi_static_pull_in.hpp).
//
// Time loop (run): M u'' + R(u) = f(u) + f_gas from rest under a step voltage V, IDA (BDF,
// adaptive order and step) in one-step mode, the structure's quasi-static components without
// inertia (core/reduced_inertia_system.hpp). Inside a step the field's load is the gap-scaled
// lagged load (gap_scaled_lagged_load.hpp): F at the reference state times (g_ref / g)^2, so
// that the Jacobian carries the electrostatic softening. The scheme (coupling_settings.hpp):
//   staggered         F refreshed at every state IDA accepts (first order in the step);
//   implicit          the field solved in every residual (the exact coupled residual, the
//                     scaled lagged model only in the Jacobian);
//   strongly_coupled  per step, Aitken-relaxed iterations on the interface load, the step
//                     redone from IDA's checkpoint until |F(u_k) - A_k| <= tolerance |F(u_k)|
//                     (Kuettler & Wall 2008): it converges to the implicit step. With
//                     strong_gas the gas is inside every iterate too (from its own checkpoint).
// An exact field (the parallel-plate law, GapFieldTraits::exact) is inside the structure's
// operator with its exact Jacobian: then the schemes partition the gas alone (strongly_coupled
// iterates on the gas load).
// The gas is advanced over every gas_every accepted steps (one gas step spanning them) and its
// force held over the next structural steps (lagged), unless it is inside the strong iteration.
//
// The steps run in every switch run's time loop (time_loop.hpp): the events of run_events.hpp
// (touch-down: the pull-in time, the run ends; turning back; lift-off; the settle and past-fold
// rules after every accepted step) and a history sample at every output time.
#pragma once
#include <vector>

#include "core/linear_functional.hpp"
#include "coupling/dynamic_pull_in.hpp"
#include "coupling/quasi_static_pull_in.hpp"
#include "physics/elasticity/elasticity_operator.hpp"
#include "physics/electrostatics/gap_field.hpp"
#include "physics/gas/structure_gas.hpp"

namespace rfmems {

// The structure as the coupling sees it: its operator (with the field inside when the field is
// exact), the components whose inertia a run neglects (empty: none) and the unknown that
// crosses the gap in each facing cell.
struct CoupledStructure {
  SecondOrderOperator& op;
  std::vector<bool> quasi_static;
  std::vector<Index> gap_unknowns;
};

// An equilibrium at a voltage.
struct StructureEquilibrium {
  std::vector<Real> u;
  Real control = 0;  // the control's deflection [m]
  Real force_y = 0;  // the field's total force along y at the last iterate [N/m]
  int iterations = 0;
};

// What the loop did, summed over the runs since reset_times(): CPU seconds by physics (the
// field's own in GapField::seconds), steps, the strong coupling's iterations (one field
// load each; the most in a step, the steps left unconverged at max_iterations and the largest
// relative interface residual a step ended with) and the largest Knudsen number the gas saw.
struct CoupledRunTimes {
  double structure = 0, gas = 0;
  Real gas_max_knudsen = 0;
  long structure_steps = 0, gas_steps = 0;
  long coupling_iterations = 0, unconverged_steps = 0;
  int max_coupling_iterations = 0;
  double max_coupling_residual = 0;
  Json json() const;
};

class FieldCoupledStructure {
 public:
  // field: the load across the gap; control: the deflection reported and controlled (one
  // unknown, or a point's gap-axis displacement from its cell's reconstruction).
  FieldCoupledStructure(CoupledStructure structure, GapField& field, LinearFunctional control);
  // A plane beam (its elasticity operator, with density for run; every cell facing the gap).
  FieldCoupledStructure(ElasticityOperator& beam, GapField& field, LinearFunctional control);

  StructureEquilibrium solve_static(Real voltage);
  QuasiStaticPullIn trace_quasi_static(const QuasiStaticOptions& options);
  // A step voltage V from rest with the run's events, IDA settings and scheme (see above);
  // gas may be null.
  DynamicRun run(Real voltage, const DynamicOptions& options, StructureGas* gas = nullptr);

  GapField& field() { return field_; }
  const LinearFunctional& control() const { return control_; }
  const CoupledRunTimes& times() const { return times_; }
  void reset_times() { times_ = {}; }

 private:
  // The fixed points need a field that gives its load (not an exact one inside the operator).
  void require_lagged_field() const;
  CoupledStructure structure_;
  GapField& field_;
  LinearFunctional control_;
  CoupledRunTimes times_;
};

}  // namespace rfmems
