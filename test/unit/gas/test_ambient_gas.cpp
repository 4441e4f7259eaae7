// The gas section of a switch case, one meaning per key for every gas model:
//  1. the mean free path by default is the kinetic-theory one at the case's own p0 and T0,
//     lambda = mu / p0 sqrt(pi R T0 / 2) (air, R = 287 J/(kg K)), so the film's Knudsen number
//     at p0 is lambda / g, whatever p0;
//  2. a given mean free path is lambda at p0: the film's Kn at a pressure p is lambda p0 / (p g);
//  3. the pressure is required when the gas is on, and optional when it is off; a value out of
//     range is bad input naming the key;
//  4. rarefaction: table reads gas.flow_factor_table relative to the case file; a missing table,
//     a table without rarefaction: table, and rarefaction: table without one name the key.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "io/case_file.hpp"
#include "physics/gas/ambient_gas.hpp"

using namespace rfmems;

namespace {

AmbientGas read(const std::string& gas, bool on) {
  const CaseFile cf = CaseFile::parse("gas: " + gas + "\n", "g.yaml");
  AmbientGas a = read_ambient_gas(cf.root().child("gas"), on);
  cf.check_all_used();
  return a;
}

}  // namespace

TEST(AmbientGas, MeanFreePathDefaultsToKineticTheoryAtTheAmbientState) {
  constexpr Real gap = 1.5e-6, T0 = 350, mu = 2e-5;
  for (const char* p0 : {"13600 Pa", "101325 Pa"}) {
    const AmbientGas a =
        read(std::string("{pressure: ") + p0 + ", temperature: 350 K, viscosity: 2e-5 Pa*s}", true);
    const Real p = a.film.ambient_pressure;
    const Real lambda = mu / p * std::sqrt(M_PI * 287.0 * T0 / 2);
    EXPECT_NEAR(a.film.mean_free_path, lambda, 1e-12 * lambda);
    EXPECT_NEAR(a.film.knudsen(p, gap), lambda / gap, 1e-12 * lambda / gap);
    EXPECT_EQ(a.temperature, T0);
  }
  // Air at 1 atm and 300 K with the default viscosity: about 67 nm.
  const AmbientGas air = read("{pressure: 1 atm}", true);
  EXPECT_NEAR(air.film.mean_free_path, 67.1e-9, 0.1e-9);
  EXPECT_EQ(air.omega, 0.74);
}

TEST(AmbientGas, GivenMeanFreePathIsAtTheAmbientPressure) {
  const AmbientGas a = read("{pressure: 13600 Pa, mean_free_path: 496.19522 nm}", true);
  EXPECT_NEAR(a.film.knudsen(13600, 1e-6), 0.49619522, 1e-12);
  // At 1 atm the same gas has 66.6 nm: lambda scales as 1 / p.
  EXPECT_NEAR(a.film.knudsen(101325, 1e-6), 0.0666, 1e-6);
}

TEST(AmbientGas, PressureRequiredWhenTheGasIsOn) {
  EXPECT_THROW(read("{temperature: 300 K}", true), InputError);
  EXPECT_NO_THROW(read("{temperature: 300 K}", false));
  try {
    read("{pressure: -3 Pa}", false);
    FAIL() << "a negative pressure was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("gas.pressure"), std::string::npos) << e.what();
  }
}

TEST(AmbientGas, FlowFactorTableIsRelativeToTheCaseFile) {
  const std::string case_path = std::string(RFMEMS_SOURCE_DIR) + "/cases/switch_plate/case.yaml";
  auto read_at = [&](const std::string& gas) {
    const CaseFile cf = CaseFile::parse("gas: " + gas + "\n", case_path);
    AmbientGas a = read_ambient_gas(cf.root().child("gas"), true);
    cf.check_all_used();
    return a;
  };
  const AmbientGas a = read_at(
      "{pressure: 1 atm, rarefaction: table, flow_factor_table: "
      "../../docs/data/flow_factor_bgk.csv}");
  ASSERT_EQ(a.film.rarefaction, Rarefaction::Table);
  ASSERT_TRUE(a.film.flow_factor_table);
  EXPECT_EQ(a.film.flow_factor_table->knudsen().size(), 13u);
  EXPECT_NEAR(a.film.flow_factor_table->min_knudsen(), 0.01, 1e-12);
  // A missing table names the key and the file; a table without `rarefaction: table` is refused.
  for (const char* gas :
       {"{pressure: 1 atm, rarefaction: table, flow_factor_table: none.csv}",
        "{pressure: 1 atm, flow_factor_table: ../../docs/data/flow_factor_bgk.csv}",
        "{pressure: 1 atm, rarefaction: table}"}) {
    try {
      read_at(gas);
      FAIL() << gas << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("gas.flow_factor_table"), std::string::npos) << e.what();
    }
  }
}
