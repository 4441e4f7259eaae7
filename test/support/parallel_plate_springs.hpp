// Three independent 1-DOF parallel-plate actuators (springs k, 2k, 3k, each a mass m under its
// own plate of area A over the gap g0; the eigensolver needs at least three unknowns with mass),
// and the closed forms of the softest: at a voltage V it settles at the gap g solving
//   k (g0 - g) = eps0 A V^2 / (2 g^2),
// on the stable branch while V < V_PI = sqrt(8 k g0^3 / (27 eps0 A)) (g = 2 g0 / 3 there).
// The tests of the modes and the harmonic response under a DC bias (test/unit/coupling).
#pragma once
#include <cmath>
#include <vector>

#include "core/system_operator.hpp"
#include "physics/electrostatics/parallel_plate_actuation.hpp"
#include "physics/electrostatics/permittivity.hpp"

namespace rfmems::test {

constexpr double kSpringK = 20.0, kSpringMass = 5e-10, kPlateArea = 1.6e-8, kSpringGap = 3.75e-6;

// m_i x_i'' + (i + 1) k x_i = f_i: three uncoupled springs (positive x: opening).
class ThreeSprings : public SecondOrderOperator {
 public:
  ThreeSprings() {
    pattern_.col_idx = {0, 1, 2};
    pattern_.row_ptr = {0, 1, 2, 3};
  }
  Index size() const override { return 3; }
  void internal_residual(Real, std::span<const Real> y, std::span<Real> r) override {
    for (int i = 0; i < 3; ++i) r[i] = (i + 1) * kSpringK * y[i];
  }
  const CsrPattern& stiffness_pattern() const override { return pattern_; }
  void stiffness(Real, std::span<const Real>, std::span<Real> values) override {
    for (int i = 0; i < 3; ++i) values[i] = (i + 1) * kSpringK;
  }
  std::vector<Real> mass_diagonal() const override {
    return {kSpringMass, kSpringMass, kSpringMass};
  }

 private:
  CsrPattern pattern_;
};

// One plate of area A over each spring.
inline std::vector<GapElement> spring_plates() {
  std::vector<GapElement> elements;
  for (Index i = 0; i < 3; ++i) elements.push_back({i, kPlateArea, Vec3::Zero(), Vec3::Zero(), {}});
  return elements;
}

inline double springs_pull_in_voltage() {
  return std::sqrt(8 * kSpringK * std::pow(kSpringGap, 3) /
                   (27 * kVacuumPermittivity * kPlateArea));
}

// The gap of the softest actuator at V, by bisection on the cubic over (2 g0 / 3, g0].
inline double softest_equilibrium_gap(double V) {
  auto f = [&](double g) {
    return kSpringK * (kSpringGap - g) - kVacuumPermittivity * kPlateArea * V * V / (2 * g * g);
  };
  double lo = 2 * kSpringGap / 3, hi = kSpringGap;  // f(lo) <= 0 below pull-in, f(hi) <= 0
  if (f(hi) == 0) return hi;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) > 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace rfmems::test
