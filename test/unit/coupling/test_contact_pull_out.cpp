// Pull-in and pull-out of a lumped parallel-plate actuator on a dielectric, against closed
// forms. A mass m on a spring k, plate area A, air gap g0 above a dielectric of thickness t_d
// and relative permittivity eps_r (electrical gap g_e = g + t_d/eps_r), contact at air gap g_c
// (contact_penalty.hpp, penetration delta). At rest, k (g0 - g) = A V^2 [p1(g) - p_c(g)/V^2],
// p1 = eps0 / (2 g_e^2):
//  - off the dielectric (p_c = 0): V^2 = 2 k (g0 - g) g_e^2 / (eps0 A), largest at
//    g_e = 2/3 g_e0: V_PI = sqrt(8 k g_e0^3 / (27 eps0 A)), g_e0 = g0 + t_d/eps_r;
//  - in contact the penalty pushes back: the equilibrium exists for V down to the touching
//    point g = g_c (p_c = 0 there):
//      V_PO = g_ec sqrt(2 k (g0 - g_c) / (eps0 A)),   g_ec = g_c + t_d/eps_r.
//    With the penalty, V^2(s)/V_PO^2 = (1 + s delta/(g0 - g_c)) / ((1 - eps s)^-2 - s^2),
//    s the penetration in units of delta, eps = delta/g_ec; its minimum over s is
//    1 - (eps - delta/(2 (g0 - g_c)))^2 + O(eps^3): the regularisation lowers V_PO by
//    eps^2/2 relative, second order in the penetration tolerance.
// Figures: the default switch's lumped values (k = 32 E b h^3/L^3 with E/(1-nu^2): 283 N/m,
// A = b L, g0 = 3.75 um, 0.1 um of eps_r = 7.6, g_c = 75 nm): V_PI = 178.6 V, V_PO = 10.69 V.
// Asserts: V_PI (displacement control) to 1e-5; V_PO from the contact branch to
// 1.2 eps^2/2 at delta = g_c/10 and g_c/100, the error ratio of the two showing order 2
// (> 1.8); the dynamic pull-out (bisection on the hold voltage from rest in contact at
// 1.05 V_PI, IDA with the release root, no damping) above the quasi-static one, converging to
// it as delta -> 0 with order ~1/2: at the drop the penalty is compressed more than at rest
// under the hold voltage (the spring's share of the load changes), and the undamped rebound
// carries the mass past the unstable equilibrium just above g_c. That barrier's height grows
// as (V_h^2/V_PO^2 - 1)^2 and the rebound energy as delta, so the excess goes as
// sqrt(delta / g_ec) asymptotically. Measured 11.5 % and 7.8 % at delta = g_c/10 and g_c/30
// (observed order 0.35, below the asymptotic 1/2 at these eps = delta/g_ec = 0.085, 0.028):
// asserted order in (0.25, 0.65). So a dynamic pull-out carries a penalty error of this size;
// a damped contact (the squeeze film) removes most of the rebound.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "coupling/dynamic_release.hpp"
#include "coupling/quasi_static_pull_in.hpp"
#include "coupling/quasi_static_pull_out.hpp"
#include "physics/electrostatics/permittivity.hpp"

using namespace rfmems;

namespace {

constexpr double kE = 200e9 / (1 - 0.31 * 0.31), kB = 40e-6, kH = 4e-6, kL = 400e-6;
constexpr double kStiffness = 32 * kE * kB * kH * kH * kH / (kL * kL * kL);
constexpr double kArea = kB * kL, kMass = 7854 * kB * kH * kL;
constexpr double kGap = 3.75e-6, kDielectric = 0.1e-6, kEpsR = 7.6, kContactGap = 75e-9;

// m x'' + k x = f: one unknown, the displacement (positive: opening).
class LumpedSpring : public SecondOrderOperator {
 public:
  LumpedSpring() { pattern_.col_idx = {0}, pattern_.row_ptr = {0, 1}; }
  Index size() const override { return 1; }
  void internal_residual(Real, std::span<const Real> y, std::span<Real> r) override {
    r[0] = kStiffness * y[0];
  }
  const CsrPattern& stiffness_pattern() const override { return pattern_; }
  void stiffness(Real, std::span<const Real>, std::span<Real> values) override {
    values[0] = kStiffness;
  }
  std::vector<Real> mass_diagonal() const override { return {kMass}; }

 private:
  CsrPattern pattern_;
};

struct Lumped {
  LumpedSpring spring;
  ParallelPlateActuation act;
  explicit Lumped(double penetration)
      : act(spring, {GapElement{0, kArea, Vec3::Zero(), Vec3::Zero(), {}}}, kGap, [] {
          ParallelPlateLaw law;
          law.dielectric_thickness = kDielectric;
          law.dielectric_permittivity = kEpsR;
          return law;
        }()) {
    act.set_contact({kContactGap, penetration});
  }
};

const double kGec = kContactGap + kDielectric / kEpsR, kGe0 = kGap + kDielectric / kEpsR;
const double kPullIn =
    std::sqrt(8 * kStiffness * kGe0 * kGe0 * kGe0 / (27 * kVacuumPermittivity * kArea));
const double kPullOut =
    kGec * std::sqrt(2 * kStiffness * (kGap - kContactGap) / (kVacuumPermittivity * kArea));

}  // namespace

TEST(ContactPullOut, LumpedActuatorClosedForms) {
  double error[2];
  int k = 0;
  for (const double penetration : {kContactGap / 10, kContactGap / 100}) {
    Lumped l(penetration);
    QuasiStaticOptions qs;
    qs.voltage_tolerance = 1e-6;
    const QuasiStaticPullIn in = trace_pull_in(l.act, 0, qs);
    EXPECT_NEAR(in.pull_in_voltage / kPullIn, 1.0, 1e-5);
    PullOutOptions po;
    po.start_voltage = 1.05 * in.pull_in_voltage;
    po.voltage_tolerance = 1e-6;
    const QuasiStaticPullOut out = trace_pull_out(
        l.act, 0, press_onto_dielectric(l.act, 0, in.fold_state, po.start_voltage, po), po);
    const double eps = penetration / kGec;
    error[k] = 1 - out.pull_out_voltage / kPullOut;
    std::printf(
        "delta = g_c/%.0f: V_PI %.5f V (closed form %.5f), V_PO %.6f V (closed form "
        "%.6f, relative error %.3e, eps^2/2 = %.3e), %ld solves\n",
        kContactGap / penetration, in.pull_in_voltage, kPullIn, out.pull_out_voltage, kPullOut,
        error[k], eps * eps / 2, out.solves);
    EXPECT_GT(error[k], 0.0);  // the penalty lowers V_PO
    EXPECT_LT(error[k], 1.2 * eps * eps / 2);
    EXPECT_LT(out.pull_out_voltage - out.released_voltage, 2e-6);
    ++k;
  }
  const double order = std::log(error[0] / error[1]) / std::log(10.0);
  std::printf("observed order of the penalty error in delta: %.2f\n", order);
  EXPECT_GT(order, 1.8);
}

TEST(ContactPullOut, LumpedDynamicReleaseConvergesToStatic) {
  double excess[2];
  int k = 0;
  for (const double penetration : {kContactGap / 10, kContactGap / 30}) {
    Lumped l(penetration);
    QuasiStaticOptions fine;  // V_PI, the bisection's upper end, to the closed form's digits
    fine.voltage_tolerance = 1e-7;
    const QuasiStaticPullIn in = trace_pull_in(l.act, 0, fine);
    PullOutOptions po;
    po.start_voltage = 1.05 * in.pull_in_voltage;
    po.voltage_tolerance = 1e-3;
    const QuasiStaticPullOut out = trace_pull_out(
        l.act, 0, press_onto_dielectric(l.act, 0, in.fold_state, po.start_voltage, po), po);

    // At rest in contact at 1.05 V_PI: the static state, zero velocity.
    ActuatedStructureSystem system(l.act, {false});
    DynamicState drop;
    drop.y = {out.branch.front().control, 0.0};
    drop.yp = {0.0, 0.0};
    DynamicOptions o;
    o.contact_gap = kContactGap;
    o.ida.rtol = 1e-6;
    o.ida.atol = 1e-6 * 1e-2 * kGap;
    o.ida.max_steps = 1000000;
    ReleaseOptions r;
    r.window = 20e-6;  // 2.4 periods of the spring (119 kHz)
    r.lift = 0.05 * kGap;
    const double tolerance = 0.005;
    const DynamicPullOut d =
        find_dynamic_pull_out(system, 0, drop, 0.0, in.pull_in_voltage, tolerance, o, r);
    excess[k] = 0.5 * (d.released + d.voltage) / out.pull_out_voltage - 1;
    std::printf(
        "delta = g_c/%.0f: dynamic pull-out (%.3f, %.3f] V against quasi-static %.4f V "
        "(%.2f %% above); %d runs\n",
        kContactGap / penetration, d.released, d.voltage, out.pull_out_voltage, 100 * excess[k],
        d.runs);
    EXPECT_GT(d.released, out.pull_out_voltage);
    EXPECT_LE(d.voltage - d.released, tolerance);
    // Far below V_PO the spring alone lifts the mass: x(t) = x0 cos(w t) from x0 (the penalty
    // vanishes with the voltage), the gap g0 + x reaches g_c + lift at
    // cos(w t) = (g0 - g_c - lift) / |x0|.
    const DynamicRun zero = run_hold(system, 0, drop, 0.0, o, r);
    ASSERT_TRUE(zero.released);
    const double w = std::sqrt(kStiffness / kMass), x0 = -drop.y[0];
    const double expected = std::acos((kGap - kContactGap - r.lift) / x0) / w;
    EXPECT_NEAR(zero.release_time / expected, 1.0, 1e-3);
    ++k;
  }
  const double order = std::log(excess[0] / excess[1]) / std::log(3.0);
  std::printf("observed order of the dynamic excess in delta: %.2f\n", order);
  EXPECT_GT(order, 0.25);
  EXPECT_LT(order, 0.65);
  EXPECT_LT(excess[1], 0.10);
}
