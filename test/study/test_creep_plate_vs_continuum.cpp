// Plate vs plane-stress continuum creep at the thesis's Table 4.1/4.2 set-up (sec. 4.6.1): the
// fixed-fixed strip, L = 240 um, E = 200 GPa, nu = 0.3, L/h = 10, 30, 60 with the table's loads
// (4 MPa, 60 kPa, 60 kPa), 500 h, IDA (rtol 1e-6); plastic centre deflection
// w_p = w(500 h) - w(0) of PlateCreepSystem (81 x 5 mid-surface cells, 20 Simpson intervals) and
// of ContinuumCreepSystem in plane stress on the x-z section at two meshes (the finer one is
// the reference; their difference is printed as the continuum's mesh error). The plate strip is
// L/100 wide: a plate with free long edges bends anticlastically, as the plane-stress section
// does, except within ~ a width of the clamps (physics/creep/continuum_plate_comparison.hpp).
// The figure is the thesis's "percentage error" of the plate, 1 - w_p,plate / w_p,continuum
// (thesis Table 4.2: 16.76 % at L/h = 10, 0.15 % at 30, 0.5 % at 60).
//
// Two laws: the Table 4.1 law (A = 8.33e-6 /s, B = 1.8e8, m = n = 2, sigma_y0 = 1 GPa) and the
// Coble law of sec. 4.6.2 (m = 1, mild hardening). And a diagnostic continuum whose creep law
// sees only the axial stress (ContinuumCreepSystem::set_creep_stress_mask: the plate's
// bending-only assumption), which isolates the cause of the thick-strip difference: creep of
// the transverse shear stress (the section's sigma_xy, x-z of the strip). With the Table 4.1
// law's hardening the creep strain grows only as sigma^(m/(mn+1)) = sigma^0.4 after the first
// seconds, so even the small shear stress of a slender section creeps by a sizeable fraction of
// the bending creep (measured: the plate error falls as (h/L)^1.6: 14.9, 2.5, 0.75 %); for the
// linear Coble law it falls as (h/L)^2, like the elastic shear deflection (11.9, 1.4, 0.5 %).
// The through-thickness normal stress (the section's sigma_yy) and the load on the top face
// instead of the mid-surface matter less (measured at L/h = 10: dropping sigma_yy alone from
// the creep law changes w_p by 0.2 %).
// With the Table 4.1 law also: the continuum without the shear stress alone
// (kNoShear), and the plate with transverse shear creep (PlateCreepSystem shear_creep), which
// agrees with the full continuum within 1 % (measured -0.47 %, -0.01 %, +0.01 % at L/h = 10,
// 30, 60; docs/creep.md).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "physics/creep/continuum_plate_comparison.hpp"

using namespace rfmems;

namespace {

constexpr Real kEnd = 500 * 3600.0;

IdaOptions options(const FixedFixedCreepProblem& p, bool plate) {
  const Real h = p.thickness();
  IdaOptions o;
  o.rtol = 1e-6;
  o.atol = 1e-2 * o.rtol * p.load * std::pow(p.length, 4) / (32 * p.E * h * h * h);
  if (plate) o.linear_solver = IdaOptions::LinearSolver::Spgmr;
  return o;
}

struct Case {
  Real slenderness, load;
  int coarse[2], fine[2];  // continuum meshes (nx, nz)
};

struct Row {
  Real plate, plane_coarse, plane, bending;  // w_p [m]
  Real plate_shear, no_shear;  // plate with shear creep; continuum without shear creep
  Real error() const { return 1 - plate / plane; }
  Real shear_error() const { return 1 - plate_shear / plane; }
  Real no_shear_error() const { return 1 - plate / no_shear; }
  Real bending_error() const { return 1 - plate / bending; }
  Real mesh_change() const { return std::abs(plane_coarse / plane - 1); }
};

// shear: also the continuum without shear creep (kNoShear) and the plate with shear creep
// (KLU: ~10x the bending-only plate's time).
Row compare(const Case& c, const CreepLaw& law, bool shear = false) {
  FixedFixedCreepProblem p;
  p.slenderness = c.slenderness;
  p.load = c.load;
  p.width = p.length / 100;
  p.law = law;
  Row r;
  const CreepRunResult plate = run_plate_creep(p, 81, 5, 20, options(p, true), kEnd);
  r.plate = plate.w_plastic;
  r.plane_coarse =
      run_continuum_creep(p, c.coarse[0], c.coarse[1], options(p, false), kEnd).w_plastic;
  const CreepRunResult plane =
      run_continuum_creep(p, c.fine[0], c.fine[1], options(p, false), kEnd);
  r.plane = plane.w_plastic;
  p.continuum_creep_stress = FixedFixedCreepProblem::kBendingOnly;
  r.bending = run_continuum_creep(p, c.fine[0], c.fine[1], options(p, false), kEnd).w_plastic;
  CreepRunResult with_shear;
  r.no_shear = r.plate_shear = std::nan("");
  if (shear) {
    p.continuum_creep_stress = FixedFixedCreepProblem::kNoShear;
    r.no_shear = run_continuum_creep(p, c.fine[0], c.fine[1], options(p, false), kEnd).w_plastic;
    p.plate_shear_creep = true;
    with_shear = run_plate_creep(p, 81, 5, 20, options(p, true), kEnd);
    r.plate_shear = with_shear.w_plastic;
  }
  std::printf(
      "L/h = %2g  q = %8.3g Pa  w_el plate %.4e plane %.4e  w_p plate %.5e  plane %.5e "
      "(%dx%d; %dx%d: %.2f %% off)  plate error %+6.2f %%  bending-only creep: %.5e "
      "(plate error %+6.2f %%)  no shear creep: %.5e (plate error %+6.2f %%)  plate with shear "
      "creep %.5e (error %+6.2f %%)  wall plate %.1f s, plane %.1f s, plate+shear %.1f s\n",
      c.slenderness, c.load, plate.w_elastic, plane.w_elastic, r.plate, r.plane, c.fine[0],
      c.fine[1], c.coarse[0], c.coarse[1], 100 * r.mesh_change(), 100 * r.error(), r.bending,
      100 * r.bending_error(), r.no_shear, 100 * r.no_shear_error(), r.plate_shear,
      100 * r.shear_error(), plate.wall_seconds, plane.wall_seconds, with_shear.wall_seconds);
  std::fflush(stdout);
  return r;
}

const Case kCases[] = {
    {10, 4e6, {61, 12}, {121, 16}}, {30, 6e4, {121, 8}, {241, 12}}, {60, 6e4, {241, 8}, {481, 12}}};

}  // namespace

TEST(CreepPlateVsContinuum, Table41LawAndLoads) {
  const CreepLaw law{8.33e-6, 1.8e8, 2, 2, 1e9};
  std::printf("Table 4.1 law (A = 8.33e-6 /s, B = 1.8e8, m = n = 2, sigma_y0 = 1 GPa), 500 h:\n");
  const Row thick = compare(kCases[0], law, true);
  EXPECT_GT(thick.error(), 0.10);  // measured 14.9 %, thesis 16.76 %
  EXPECT_LT(thick.error(), 0.25);
  EXPECT_LT(std::abs(thick.bending_error()), 0.01);  // measured -0.4 %
  // The plate with shear creep carries the continuum's physics: measured -0.47 %.
  EXPECT_LT(std::abs(thick.shear_error()), 0.01);
  const Row mid = compare(kCases[1], law, true);
  EXPECT_LT(std::abs(mid.error()), 0.04);  // measured 2.5 %: the shear creep (thesis 0.15 %)
  EXPECT_LT(std::abs(mid.bending_error()), 0.01);
  // The attribution: without the shear stress alone in the continuum's creep law the
  // difference goes (measured 0.04 %; 0.09 % without sigma_zz too), and the plate with shear
  // creep agrees (measured -0.01 %).
  EXPECT_LT(std::abs(mid.no_shear_error()), 0.005);
  EXPECT_LT(std::abs(mid.shear_error()), 0.01);
  EXPECT_LT(std::abs(mid.shear_error()), 0.2 * mid.error());
  const Row slender = compare(kCases[2], law, true);
  EXPECT_LT(std::abs(slender.error()), 0.015);  // measured 0.75 %
  EXPECT_LT(std::abs(slender.bending_error()), 0.01);
  EXPECT_LT(std::abs(slender.shear_error()), 0.01);  // measured +0.01 %
  // The shear creep effect falls with h/L.
  EXPECT_GT(thick.error(), mid.error());
  EXPECT_GT(mid.error(), slender.error());
}

TEST(CreepPlateVsContinuum, CobleLaw) {
  const CreepLaw law{2.08e-10, 20, 1, 0.5, 0.7e9};
  std::printf("Coble law (A = 2.08e-10 /s, B = 20, m = 1, n = 0.5, sigma_y0 = 0.7 GPa), 500 h:\n");
  // Linear creep: the shear creep deflection is O((h/L)^2) of the bending creep's, as the
  // elastic shear deflection is (measured 11.9 %, 1.4 %, 0.5 %; bending-only 0.2 % or less).
  const Row thick = compare(kCases[0], law);
  EXPECT_GT(thick.error(), 0.08);
  EXPECT_LT(std::abs(thick.bending_error()), 0.01);
  const Row mid = compare(kCases[1], law);
  EXPECT_LT(std::abs(mid.error()), 0.02);
  EXPECT_LT(std::abs(mid.bending_error()), 0.01);
  const Row slender = compare(kCases[2], law);
  EXPECT_LT(std::abs(slender.error()), 0.01);
  EXPECT_LT(std::abs(slender.bending_error()), 0.01);
  EXPECT_GT(thick.error(), mid.error());
  EXPECT_GT(mid.error(), slender.error());
}
