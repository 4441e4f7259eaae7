// PlateCreepSystem::initial_state is the equilibrium to round-off, and IDA starts from it at
// the tolerances of the creep studies. The set-up is the study's thick strip
// (test/study/test_creep_plate_vs_continuum.cpp, Coble law, L/h = 10, q = 4 MPa, 81 x 5 cells
// on L x L/100), where one KLU solve from rest left 1e-13 rad (5e-11 of |beta|) of round-off in
// the rotations: IDA's first corrector removed it in a jump that does not shrink with the step,
// the error test (atol 1.7e-16 on every unknown) failed at every h, and IDA stopped at t = 0
// with IDA_ERR_FAIL.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "physics/creep/continuum_plate_comparison.hpp"

using namespace rfmems;

namespace {

FixedFixedCreepProblem thick_strip() {
  FixedFixedCreepProblem p;
  p.slenderness = 10;
  p.load = 4e6;
  p.width = p.length / 100;
  p.law = CreepLaw{2.08e-10, 20, 1, 0.5, 0.7e9};  // Coble (thesis sec. 4.6.2)
  return p;
}

// The study's options: rtol 1e-6, atol 1e-2 rtol w_beam (w_beam = q L^4 / (32 E h^3)).
IdaOptions study_options(const FixedFixedCreepProblem& p, IdaOptions::LinearSolver solver) {
  const Real h = p.thickness();
  IdaOptions o;
  o.rtol = 1e-6;
  o.atol = 1e-2 * o.rtol * p.load * std::pow(p.length, 4) / (32 * p.E * h * h * h);
  o.linear_solver = solver;
  return o;
}

Real max_abs(std::span<const Real> v) {
  Real m = 0;
  for (Real x : v) m = std::max(m, std::abs(x));
  return m;
}

}  // namespace

TEST(PlateCreepInitialState, IsTheEquilibriumToRoundOff) {
  const auto plate = make_fixed_fixed_creep_plate(thick_strip(), 81, 5);
  PlateCreepSystem& system = *plate->system;
  std::vector<Real> y, yp;
  system.initial_state(0, y, yp);
  // A further Newton step on the linear plate moves the state by its round-off only.
  std::vector<Real> again = y;
  system.equilibrate(0, again);
  const Index ns = system.structural_size();
  Real change = 0;
  for (Index k = 0; k < ns; ++k) change = std::max(change, std::abs(again[k] - y[k]));
  const Real size = max_abs(std::span<const Real>(y).first(ns));
  std::printf("max |y| %.3e, change by a further Newton step %.3e (%.1e of max |y|)\n", size,
              change, change / size);
  EXPECT_LT(change, 5e-12 * size);  // measured 9.8e-14 (one solve from rest alone: 5.3e-11)
}

TEST(PlateCreepInitialState, IdaStartsAtTheInitialCreepRate) {
  // Over the first second the deflection grows at the initial state's rate w'(0) (the stress
  // redistributes and hardens over hours): IDA with the study's tolerances, both linear solvers.
  const FixedFixedCreepProblem p = thick_strip();
  for (auto solver : {IdaOptions::LinearSolver::Spgmr, IdaOptions::LinearSolver::Direct}) {
    const auto plate = make_fixed_fixed_creep_plate(p, 81, 5);
    std::vector<Real> y, yp;
    plate->system->initial_state(0, y, yp);
    const Index w = 3 * plate->centre;
    IdaIntegrator ida(*plate->system, study_options(p, solver));
    ida.initialize(0, y, yp);
    const Real t1 = 1.0;
    ASSERT_NO_THROW(ida.advance(t1));
    const Real creep = ida.y()[w] - y[w], linear = yp[w] * t1;
    std::printf("%s: w(1 s) - w(0) = %.6e m, w'(0) t = %.6e m, %ld steps\n",
                solver == IdaOptions::LinearSolver::Spgmr ? "SPGMR" : "KLU", creep, linear,
                ida.stats().steps);
    EXPECT_LT(linear, 0);  // downwards
    EXPECT_NEAR(creep / linear, 1.0, 1e-3);
  }
}
