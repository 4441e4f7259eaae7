// The flow-factor table (materials/flow_factor_table.hpp) and the one the kinetic solver wrote
// (docs/data/flow_factor_bgk.csv, rfmems-flow-factor):
//  1. the interpolant passes through every node, is monotone between them, and its dQ/dKn
//     matches central differences inside the table and on both extrapolated ends;
//  2. the ends: first-order slip below the table (Q - 1 proportional to Kn), G linear in ln Kn
//     above it with the mean of the last interval's slope and 1 / sqrt(pi), as far as half their
//     difference keeps G within 5 %, an InputError naming the table beyond;
//  3. an ill-formed file is an InputError naming the file (and the line);
//  4. the committed table: Kn from 0.01 to 10; Veijola's fit Q = 1 + 9.638 Kn^1.159 within his
//     stated 5 % of it (the fit's error, Q_Veijola / Q - 1) at every node and between them (the
//     largest is near Kn = 0.08, -4.8 %: the fit's own error there), and at its continuum end on
//     the slip-flow closed form Q = 1 + 6 sigma_P (2 / sqrt(pi)) Kn (BGK's sigma_P = 1.0162) to 0.3
//     % (the next term of G is O(1 / delta)).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "core/error.hpp"
#include "materials/flow_factor_table.hpp"
#include "materials/gas_properties.hpp"

using namespace rfmems;

namespace {

const std::string kTable = std::string(RFMEMS_SOURCE_DIR) + "/docs/data/flow_factor_bgk.csv";

Real veijola(Real kn) { return 1 + 9.638 * std::pow(kn, 1.159); }

// A table of Veijola's fit at 4 points per decade from 0.01 to 10.
FlowFactorTable veijola_table() {
  std::vector<Real> kn, q;
  for (int i = 0; i <= 12; ++i) {
    kn.push_back(std::pow(10.0, -2 + 0.25 * i));
    q.push_back(veijola(kn.back()));
  }
  return FlowFactorTable(kn, q, "veijola nodes");
}

std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = (std::filesystem::temp_directory_path() / name).string();
  std::ofstream(path) << text;
  return path;
}

}  // namespace

TEST(FlowFactorTable, ExactAtNodesMonotoneAndSmoothBetween) {
  const FlowFactorTable t = veijola_table();
  for (std::size_t i = 0; i < t.knudsen().size(); ++i)
    EXPECT_NEAR(t(t.knudsen()[i]), t.flow_factor()[i], 1e-13 * t.flow_factor()[i]) << i;
  // Between the nodes: increasing, and close to the smooth function the nodes sample.
  Real previous = 0, worst = 0;
  for (Real x = std::log(0.01); x <= std::log(10.0); x += 0.01) {
    const Real q = t(std::exp(x));
    EXPECT_GT(q, previous);
    previous = q;
    worst = std::max(worst, std::abs(q / veijola(std::exp(x)) - 1));
  }
  std::printf("largest deviation of the interpolant from the sampled fit: %.2e\n", worst);
  EXPECT_LT(worst, 2e-3);
}

TEST(FlowFactorTable, DerivativeMatchesFiniteDifferences) {
  const FlowFactorTable t = veijola_table();
  // Inside, at a node (the slope is continuous there), below and above the table.
  for (Real kn : {0.0137, 0.05, std::pow(10.0, -1.25), 0.7, 3.3, 9.99, 0.002, 1e-4, 14.0, 21.0}) {
    const Real h = 1e-6 * kn;
    const Real fd = (t(kn + h) - t(kn - h)) / (2 * h);
    const Real exact = t.evaluate(kn).dq_dkn;
    EXPECT_NEAR(exact, fd, 1e-6 * std::abs(fd)) << "Kn = " << kn;
  }
}

TEST(FlowFactorTable, EndsFollowSlipAndFreeMolecularLaws) {
  const FlowFactorTable t = veijola_table();
  // Continuum end: Q - 1 proportional to Kn, meeting the first node.
  const Real s = (t.flow_factor().front() - 1) / 0.01;
  for (Real kn : {1e-3, 1e-4, 1e-6}) EXPECT_NEAR(t(kn), 1 + s * kn, 1e-14);
  EXPECT_NEAR(t(1e-12), 1.0, 1e-10);
  // Free-molecular end: G = sqrt(pi) Q / (12 Kn) grows linearly in ln Kn from the last node,
  // with the mean of the last interval's slope and 1 / sqrt(pi).
  const Real root_pi = std::sqrt(std::numbers::pi);
  auto g = [&](Real kn) { return root_pi * t(kn) / (12 * kn); };
  const Real kn9 = std::pow(10.0, 0.75);
  const Real last = (g(10.0) - g(kn9)) / std::log(10.0 / kn9);
  const Real s_fm = (last + 1 / root_pi) / 2;
  EXPECT_NEAR(t.free_molecular_slope(), s_fm, 1e-12);
  EXPECT_GT(last, 0.2);  // Veijola's G grows as Kn^0.159 there: a slope ~0.33
  EXPECT_LT(last, 1 / root_pi);
  EXPECT_NEAR(g(20.0) - g(10.0), s_fm * std::log(2.0), 1e-12);
  // The reach: half the slopes' difference times ln(Kn / 10) is 5 % of G(10).
  const Real reach = 10.0 * std::exp(0.05 * g(10.0) / ((1 / root_pi - last) / 2));
  EXPECT_NEAR(t.max_extrapolated_knudsen(), reach, 1e-9 * reach);
  EXPECT_GT(reach, 15.0);
  EXPECT_LT(reach, 40.0);
  EXPECT_NO_THROW(t(0.999 * reach));
  try {
    t(1.01 * reach);
    FAIL() << "Kn beyond the free-molecular extrapolation was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("veijola nodes"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("beyond"), std::string::npos) << e.what();
  }
}

TEST(FlowFactorTable, IllFormedFilesNameTheFileAndLine) {
  auto message = [](const std::string& path) {
    try {
      FlowFactorTable::read(path);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  EXPECT_NE(message("/nonexistent/table.csv").find("/nonexistent/table.csv"), std::string::npos);
  const std::string no_column = write_temp("ff_no_column.csv", "# c\nknudsen,q\n0.1,2\n1,3\n");
  EXPECT_NE(message(no_column).find("flow_factor"), std::string::npos);
  const std::string bad = write_temp("ff_bad.csv", "knudsen,flow_factor\n0.1,2\n1,x3\n");
  EXPECT_NE(message(bad).find(bad + ":3"), std::string::npos) << message(bad);
  const std::string decreasing =
      write_temp("ff_decreasing.csv", "knudsen,flow_factor\n0.1,2\n1,1.5\n");
  EXPECT_NE(message(decreasing).find("increase"), std::string::npos);
  const std::string one = write_temp("ff_one.csv", "knudsen,flow_factor\n0.1,2\n");
  EXPECT_NE(message(one).find("at least two"), std::string::npos);
  const std::string ragged = write_temp("ff_ragged.csv", "knudsen,flow_factor\n0.1,2,3\n");
  EXPECT_NE(message(ragged).find(":2"), std::string::npos);
}

TEST(KineticFlowFactorTable, WithinVeijolasFivePercentFromKn001To10) {
  const FlowFactorTable t = FlowFactorTable::read(kTable);
  ASSERT_LE(t.min_knudsen(), 0.01 * (1 + 1e-6));
  ASSERT_GE(t.max_knudsen(), 10.0 * (1 - 1e-6));
  ASSERT_GE(t.knudsen().size(), 10u);
  Real worst = 0;
  for (std::size_t i = 0; i < t.knudsen().size(); ++i) {
    const Real kn = t.knudsen()[i], q = t.flow_factor()[i];
    const Real deviation = veijola(kn) / q - 1;
    std::printf("Kn = %-8.4g Q = %-9.5f Veijola %-9.5f %+6.2f %%\n", kn, q, veijola(kn),
                100 * deviation);
    worst = std::max(worst, std::abs(deviation));
  }
  for (Real x = std::log(0.01); x <= std::log(10.0); x += 0.05)
    worst = std::max(worst, std::abs(veijola(std::exp(x)) / t(std::exp(x)) - 1));
  std::printf("largest error of Veijola's fit against the table, Kn 0.01 - 10: %.2f %%\n",
              100 * worst);
  EXPECT_LT(worst, 0.05);
}

TEST(KineticFlowFactorTable, ContinuumEndMeetsTheSlipFlowClosedForm) {
  const FlowFactorTable t = FlowFactorTable::read(kTable);
  const Real sigma_p = 1.0162, slope = 6 * sigma_p * 2 / std::sqrt(std::numbers::pi);
  const Real kn = t.min_knudsen(), q = t.flow_factor().front();
  std::printf("Kn = %g: Q = %.6f, slip flow 1 + %.4f Kn = %.6f\n", kn, q, slope, 1 + slope * kn);
  EXPECT_NEAR(q / (1 + slope * kn), 1.0, 3e-3);
  // The slip coefficient the table implies at its first node, (Q - 1) / Kn: sigma_P to 5 %
  // (the O(Kn^2) term is the rest).
  EXPECT_NEAR((q - 1) / kn / slope, 1.0, 0.05);
}

TEST(GasProperties, TableRarefactionUsesTheTable) {
  GasProperties gas;
  gas.rarefaction = Rarefaction::Table;
  gas.flow_factor_table = std::make_shared<const FlowFactorTable>(veijola_table());
  EXPECT_NEAR(gas.rarefaction_factor(0.1), veijola(0.1), 1e-12);
  EXPECT_EQ(gas.rarefaction_factor_derivative(0.37), gas.flow_factor_table->evaluate(0.37).dq_dkn);
  EXPECT_NEAR(gas.effective_viscosity(101325.0, 2e-6),
              gas.viscosity / gas.rarefaction_factor(0.034), 1e-15);
}
