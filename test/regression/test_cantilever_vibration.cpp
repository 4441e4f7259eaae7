// Transient vibration of a cantilever (thesis sec. 2.7.4): plane stress, E = 200 GPa,
// nu = 0.31, rho = 7854 kg/m^3, L = 2 m, h = 0.04 m, 80 x 8 cells (cubic reconstruction; the
// static deflection is within 0.5 % of 160 x 16), end shear traction ramped linearly over
// 0.02 s then held. Integrated with IDA (adaptive order and step, KLU) at rtol 1e-6 with the
// order capped at 2: BDF3-5 are not A-stable, and undamped elastodynamics has eigenvalues on
// the imaginary axis, so at higher orders IDA collapses its step (measured: h ~ 1e-7 s at
// order 5 against 1e-5 s at order 2). Asserts: the first frequency within 1 % of Euler-Bernoulli
// 3.516/(2 pi L^2) sqrt(EI/(rho b h)) = 8.15 Hz, and amplitude decay under 1 % over 10 periods
// (no artificial damping, unlike the thesis's first-order scheme).
#include <gtest/gtest.h>

#include <cmath>

#include "../support/oscillation.hpp"
#include "core/structural_systems.hpp"
#include "mesh/structured_mesh.hpp"
#include "physics/elasticity/elasticity_operator.hpp"
#include "solvers/ida_integrator.hpp"
#include "solvers/static_solve.hpp"

using namespace rfmems;

TEST(CantileverVibration, FrequencyAndAmplitudeUnderAdaptiveBdf) {
  const double L = 2.0, h = 0.04, E = 200e9, nu = 0.31, rho = 7854, tau = -1000.0, ramp = 0.02;
  BoxSpec spec;
  spec.lower = Vec3(0, -h / 2, 0);
  spec.upper = Vec3(L, h / 2, 0);
  spec.n[0] = 80;
  spec.n[1] = 8;
  Mesh mesh = make_structured_mesh(spec);
  std::vector<ElasticityBoundary> bcs(mesh.patches().size());
  for (std::size_t p = 0; p < bcs.size(); ++p) {
    const std::string& name = mesh.patches()[p].name;
    if (name == "left")
      bcs[p] = {ElasticityBoundary::Kind::Fixed, {}};
    else if (name == "right")
      bcs[p] = {ElasticityBoundary::Kind::Traction,
                [=](const Vec3&, double t) { return Vec3(0, tau * std::min(t / ramp, 1.0), 0); }};
    else
      bcs[p] = {ElasticityBoundary::Kind::Traction, {}};
  }
  ElasticityOperator op(mesh, {E, nu, rho, Hypothesis::PlaneStress}, bcs);

  // The tip probe: cells touching (L, 0).
  std::vector<Index> tip_cells;
  for (Index c = 0; c < mesh.n_cells(); ++c) {
    const Vec3& x = mesh.cell_centroid(c);
    if (x.x() > L - L / 80 && std::abs(x.y()) < h / 8) tip_cells.push_back(c);
  }
  ASSERT_EQ(tip_cells.size(), 2u);
  auto tip = [&](std::span<const double> u) {
    double w = 0;
    for (Index c : tip_cells) w += u[2 * c + 1];
    return w / tip_cells.size();
  };

  const double static_tip = tip(solve_static(op, 1.0).y);
  const double f_eb = 3.516 / (2 * M_PI * L * L) * std::sqrt(E * h * h / (12 * rho));
  const double period = 1 / f_eb, t_end = ramp + 11.2 * period;

  FirstOrderSystem system(op);
  IdaOptions options;
  options.rtol = 1e-6;
  options.atol = 1e-6 * 1e-4;  // 1e-6 of the ~1e-4 m tip deflection
  options.max_order = 2;
  IdaIntegrator ida(system, options);
  std::vector<double> y0(system.size(), 0.0), yp0(system.size(), 0.0);
  ida.initialize(0.0, y0, yp0);
  std::vector<double> t, w;
  const int samples_per_period = 200;
  for (double tout = period / samples_per_period; tout <= t_end;
       tout += period / samples_per_period) {
    ida.advance(tout);
    t.push_back(ida.time());
    w.push_back(tip(ida.y().subspan(0, op.size())));
  }
  auto osc = test_support::analyse_oscillation(t, w, static_tip, ramp);
  IntegratorStats stats = ida.stats();
  double f = 1 / osc.period;
  double decay = 1 - osc.last_amplitude / osc.first_amplitude;
  std::printf(
      "f = %.5f Hz (Euler-Bernoulli %.5f Hz, %+.3f %%), %d periods, amplitude %.4e -> %.4e "
      "(decay %.3f %%); IDA: %ld steps, %ld residuals, %ld Jacobians, last order %d\n",
      f, f_eb, 100 * (f / f_eb - 1), osc.n_periods, osc.first_amplitude, osc.last_amplitude,
      100 * decay, stats.steps, stats.residual_evals, stats.jacobian_evals, stats.last_order);
  EXPECT_GE(osc.n_periods, 10);
  EXPECT_NEAR(f / f_eb, 1.0, 0.01);
  EXPECT_LT(std::abs(decay), 0.01);
}
