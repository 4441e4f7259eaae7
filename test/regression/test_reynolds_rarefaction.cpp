// Rarefaction: the squeeze-film damping of a strip (width W = 100 um, gap 2 um, Open long
// sides, Wall ends, 40 cells) with the Veijola effective viscosity
//   mu_eff = mu / Q,  Q = 1 + 9.638 Kn^1.159,  Kn = lambda_ref p_ref / (p_a g),
// at p_a = 1 atm (Kn = 0.034, Q = 1.1914) and at 1 kPa (Kn = 3.445, Q = 41.42).
// In the incompressible limit (quasi-static; gap rate 10 nm/s, so (p - p_a)/p_a < 1e-6) the
// damping per length is c = mu_eff W^3 / g^3, and the scheme's error for this problem is
// exactly the factor 1 + 2 (h/W)^2 (test_reynolds_incompressible.cpp), so both pressures give
//   c_FV = mu_eff(p_a) W^3 / g^3 (1 + 2 (h/W)^2)
// to 1e-6, and their ratio c(1 kPa)/c(1 atm) = Q(1 atm)/Q(1 kPa) = 0.02876. The
// continuum model (Rarefaction::None) gives the same damping at both pressures.
// The same strip both ways, Veijola's fit and the kinetic solver's flow-factor table
// (docs/data/flow_factor_bgk.csv), from 1 atm to 300 Pa (Kn 0.034 to 11.5, the last beyond the
// table's Kn = 10, on its free-molecular extrapolation): each damping is its own mu_eff W^3 / g^3
// to 1e-6, so their ratio is Q_Veijola / Q_table, within Veijola's 5 % up to Kn = 10.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "mesh/structured_mesh.hpp"
#include "physics/gas/reynolds_film.hpp"
#include "physics/gas/reynolds_quasi_static.hpp"

using namespace rfmems;

namespace {

constexpr double kW = 100e-6, kLength = 10e-6, kGap = 2e-6, kGapRate = -1e-8;
constexpr int kCells = 40;

// Damping per unit length c = -F / (g' L).
double strip_damping(const GasProperties& gas) {
  BoxSpec spec;
  spec.upper = Vec3(kW, kLength, 0);
  spec.n[0] = kCells;
  spec.n[1] = 1;
  Mesh mesh = make_structured_mesh(spec);
  std::vector<FilmBoundary> bcs(mesh.patches().size());
  for (std::size_t i = 0; i < bcs.size(); ++i) {
    const std::string& name = mesh.patches()[i].name;
    bcs[i].kind =
        (name == "left" || name == "right") ? FilmBoundary::Kind::Open : FilmBoundary::Kind::Wall;
  }
  ReynoldsFilm film(mesh, gas, bcs);
  std::vector<double> gap(film.size(), kGap), rate(film.size(), kGapRate);
  return -film.total_force(quasi_static_pressure(film, gap, rate, 2)) / (kGapRate * kLength);
}

TEST(ReynoldsRarefaction, DampingFollowsTheVeijolaFactor) {
  GasProperties atm, low;
  low.ambient_pressure = 1000.0;
  const double q_atm = atm.rarefaction_factor(atm.knudsen(atm.ambient_pressure, kGap));
  const double q_low = low.rarefaction_factor(low.knudsen(low.ambient_pressure, kGap));
  EXPECT_NEAR(q_atm, 1.1914, 1e-4);  // hand values
  EXPECT_NEAR(q_low, 41.42, 0.01);

  const double discretisation = 1 + 2.0 / (kCells * kCells);
  const double c_atm = strip_damping(atm), c_low = strip_damping(low);
  for (auto [c, q, name] : {std::tuple{c_atm, q_atm, "1 atm"}, std::tuple{c_low, q_low, "1 kPa"}}) {
    const double exact = atm.viscosity / q * kW * kW * kW / (kGap * kGap * kGap);
    std::printf("%s: c = %.6e N s/m^2, mu_eff W^3/g^3 = %.6e, ratio %.8f (1 + 2 (h/W)^2 = %.8f)\n",
                name, c, exact, c / exact, discretisation);
    EXPECT_NEAR(c / exact / discretisation, 1.0, 1e-6);
  }
  std::printf("c(1 kPa) / c(1 atm) = %.6f, Q(1 atm) / Q(1 kPa) = %.6f\n", c_low / c_atm,
              q_atm / q_low);
  EXPECT_NEAR(c_low / c_atm / (q_atm / q_low), 1.0, 1e-6);
  EXPECT_NEAR(c_low / c_atm, 0.02876, 1e-5);

  // Without rarefaction the damping does not depend on the ambient pressure.
  atm.rarefaction = low.rarefaction = Rarefaction::None;
  EXPECT_NEAR(strip_damping(low) / strip_damping(atm), 1.0, 1e-6);
}

}  // namespace

TEST(ReynoldsRarefaction, KineticTableAgainstVeijolaOnTheStrip) {
  const auto table = std::make_shared<const FlowFactorTable>(
      FlowFactorTable::read(std::string(RFMEMS_SOURCE_DIR) + "/docs/data/flow_factor_bgk.csv"));
  const double discretisation = 1 + 2.0 / (kCells * kCells);
  for (double pa : {101325.0, 1e4, 1e3, 300.0}) {
    GasProperties veijola, kinetic;
    veijola.ambient_pressure = kinetic.ambient_pressure = pa;
    kinetic.rarefaction = Rarefaction::Table;
    kinetic.flow_factor_table = table;
    const double kn = veijola.knudsen(pa, kGap);
    const double c_veijola = strip_damping(veijola), c_table = strip_damping(kinetic);
    const double q_table = (*table)(kn);
    const double exact = veijola.viscosity / q_table * kW * kW * kW / (kGap * kGap * kGap);
    std::printf(
        "p_a = %-8g Kn = %-7.4g c Veijola = %.5e, c table = %.5e N s/m^2, "
        "table / Veijola = %.4f\n",
        pa, kn, c_veijola, c_table, c_table / c_veijola);
    EXPECT_NEAR(c_table / exact / discretisation, 1.0, 1e-6) << pa;
    if (kn <= 10) {
      EXPECT_NEAR(c_table / c_veijola, 1.0, 0.05) << pa;
    }
  }
}
