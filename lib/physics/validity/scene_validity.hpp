// The scene validity report: the ranges a run saw (Knudsen number, aspect ratios) and a
// warning wherever the chosen models leave their range of validity. A pure function of a plain
// description of the scene, so each criterion is unit tested without a solve
// (test/unit/validity/test_scene_validity.cpp). Each driver describes its scene:
// coupling/switch_validity.hpp (a switch and what its run computed),
// physics/creep/creep_validity.hpp, physics/gas/kinetic/kinetic_validity.hpp.
//
// Criteria (each warning names its criterion and the value seen):
//  - Reynolds film, Kn = lambda(p)/g of the local gap over the gaps the run saw (rest gap down
//    to the smallest computed gap):
//      rarefaction veijola: Kn <= 880, the range of Veijola's fit (Veijola et al., Sensors and
//        Actuators A 48 (1995) 239, within 5 % of the Fukui-Kaneko flow rate for 0..880);
//      rarefaction none: Kn <= 0.01 (no-slip continuum film);
//      rarefaction table: Kn <= the table's largest Kn (beyond it the free-molecular log law
//        extrapolates, materials/flow_factor_table.hpp);
//    large displacement: the deepest equilibrium the run computed (the quasi-static fold)
//      beyond displacement/gap = 0.5: the film's lubrication flux goes as g^3, so at half the
//      gap the damping is 8x its value at rest and set by the thinnest region, whose slope the
//      small-slope lubrication limit neglects (a criterion of this project, not a paper's);
//    thin film: g/b <= 0.1 (b the plate's width across the open edges): the open-edge
//      (elongation) correction, of order the gap per open edge (Veijola 2004), is left out.
//  - Plate (Mindlin-Reissner; length L along x, thickness h):
//      creep: L/h >= 20 for the bending-only plate (the thesis's: shear creep neglected):
//        docs/creep.md ("Plate against continuum") measured the centre deflection off by 15 % at
//        L/h = 10, 2.5 % at 30, 0.75 % at 60 against the continuum. With creep.shear_creep the
//        plate is within 0.5 % of the continuum at L/h = 10, 30 and 60 (docs/creep.md), so the
//        static / dynamic limit applies;
//      static / dynamic: L/h >= 10. Mindlin's first-order shear deformation is in the plate;
//        below L/h ~ 10 the through-thickness (3D, thick-plate) stresses it neglects matter.
//  - Parallel-plate electrostatics: fringing adds f g/b (f = 0.65, Palmer 1937; Osterberg &
//    Senturia 1997) to the force. Without the correction: warn where f g/b or f g/L exceeds 0.1
//    (g/b or g/L > 0.154), a 10 % force error. With it: warn where g/b > 0.5, beyond which the
//    first-order (linear in g/b) correction is not claimed here (the higher-order Palmer terms
//    grow with g/b).
//  - Dynamic pull-in: the bisection's tolerance above 1 % of the quasi-static pull-in voltage
//    (a fixed voltage is coarse on a slender structure that pulls in at a few volts).
//  - Immersed field: the touch-down gap below one background cell, the 1D Reynolds film at
//    Kn > 1 or followed below half the gap, the kinetic gas's cell size (below).
//  - Kinetic gas: Kn = lambda/L over the computed density range (lambda = mu(T)/p
//    sqrt(pi R T/2) with p = rho R T), reported; the velocity grid's half-extent (its truncated
//    rules': a Gauss-Hermite rule covers the whole line) must cover
//    every wall's speed plus 3 thermal speeds sqrt(2 R T_wall) (a Maxwellian keeps
//    exp(-9) ~ 1e-4 of its mass beyond 3 thermal speeds);
//    the cell size h against the mean free path: the first-order upwind scheme adds the
//    diffusion h |c| / 2 to every ordinate, a numerical viscosity mu_num / mu = h / (2 lambda)
//    (docs/gas_damping.md "Continuum end": 6.9 there, the damping 7.2x the continuum's). Warn
//    where h / (2 lambda) > 1 at the densest state (the numerical viscosity above the physical
//    one), naming the case key that sets h. h is the largest cell's smallest extent (volume /
//    largest face: the resolution across a film's or a Couette flow's shear; the numerical
//    viscosity along a coarser direction is larger still, so the warning is never spurious).
//    With first-order transport the same ratio estimates the relative error of the wall
//    shear and heat flux (the upwind diffusion adds to the physical viscosity and
//    conductivity at the wall; measured for plane Couette flow at delta = 10: +5.1 % in shear
//    where h / (2 lambda) = 5.6 %, +1.4 % where it is 1.4 %; docs/kinetic.md), an upper bound
//    in the rarefied regime where the wall fluxes are mostly free-molecular: warn where it
//    exceeds 1 % (and the profile warning above has not fired), naming the transport key.
#pragma once
#include <limits>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "io/case_file.hpp"
#include "io/json_summary.hpp"
#include "materials/gas_properties.hpp"

namespace rfmems {

struct SceneDescription {
  enum class Analysis { Static, Dynamic, Creep };
  Analysis analysis = Analysis::Static;
  bool plate = true;               // Mindlin-Reissner plate (else a plane beam: no L/h check)
  bool plate_shear_creep = false;  // creep.shear_creep: the plate's transverse shear creeps too
  bool plate_stretching = false;   // the von Karman plate, whose creep has no shear creep
  Real length = 0;                 // L [m]: the structure's extent along x
  Real width = 0;                  // b [m]: the extent in y (plates; 0: not modelled)
  Real thickness = 0;              // h [m]
  Real gap = 0;                    // g0 [m] at rest

  bool parallel_plate = true;
  Real fringing_factor = 0;  // 0: no fringing correction

  bool reynolds = false;
  GasProperties gas;
  Real min_gap = 0;                   // the smallest gap the run computed (0: the rest gap)
  Real equilibrium_displacement = 0;  // |deflection| of the deepest equilibrium [m]

  struct Kinetic {
    bool present = false;
    Real density_min = 0, density_max = 0;  // [kg/m^3] over the computed field
    Real temperature_min = 0,
         temperature_max = 0;  // [K] over the computed field
    Real viscosity_min = 0,
         viscosity_max = 0;    // mu at temperature_min / _max [Pa s]
    Real gas_constant = 0;     // R [J/(kg K)]
    Real length = 0;           // the gap or domain length [m]
    Real velocity_extent = 0;  // the grid's smallest half-extent [m/s] (0: no check, Gauss-Hermite)
    Real wall_speed = 0;       // the largest wall velocity component [m/s]
    Real wall_temperature = 0;  // the hottest wall [K]
    Real cell_size = 0;         // h [m]: max over cells of the smallest extent (0: no check)
    std::string cell_size_key;  // the case key that sets h, e.g. "mesh.cells"
    bool first_order = true;    // first-order upwind transport (solver.transport)
  } kinetic;
};

struct ValidityRange {
  std::string name;  // e.g. "film_knudsen", "plate_length_over_thickness"
  Real min = 0, max = 0;
};

struct ValidityReport {
  std::vector<ValidityRange> ranges;
  std::vector<std::string> warnings;  // one sentence each, no program prefix
  const ValidityRange *find(const std::string &name) const;
  Json to_json() const;  // {ranges: {name: [min, max]}, warnings: [...]}
};

// The thresholds above, for the tests and the README.
struct ValidityReport;
struct ValidityCriteria {
  static constexpr Real kVeijolaMaxKnudsen = 880;
  static constexpr Real kContinuumMaxKnudsen = 0.01;
  static constexpr Real kFilmMaxDisplacementFraction = 0.5;
  static constexpr Real kFilmMaxGapOverWidth = 0.1;
  static constexpr Real kCreepPlateMinSlenderness = 20;
  static constexpr Real kPlateMinSlenderness = 10;
  static constexpr Real kFringingFactor = 0.65;
  static constexpr Real kFringingMaxForceError = 0.1;
  static constexpr Real kFringingCorrectionMaxGapOverWidth = 0.5;
  static constexpr Real kVelocityGridThermalSpeeds = 3;
  static constexpr Real kMaxUpwindViscosityRatio = 1;   // h / (2 lambda)
  static constexpr Real kMaxWallFluxError = 0.01;       // first order: h / (2 lambda)
  static constexpr Real kMaxBisectionTolerance = 0.01;  // of the quasi-static V_PI
};

// Bird's hard-sphere mean free path lambda = mu / (rho R T) sqrt(pi R T / 2) [m].
Real mean_free_path(Real density, Real temperature, Real viscosity, Real gas_constant);

// The cell-size criterion alone (for a run that has h and lambda but no SceneDescription, e.g.
// the immersed switch's ESBGK gas): the range "kinetic_upwind_viscosity_ratio" = h / (2 lambda)
// into r, and a warning naming `key` when it exceeds the limit.
void check_cell_size_against_mean_free_path(Real cell_size, Real lambda_min, Real lambda_max,
                                            const std::string &key, ValidityReport &r);

ValidityReport check_scene_validity(const SceneDescription &scene);

// Warnings on stderr, "<program>: warning: <text>" one line each.
void print_validity_warnings(const std::string &program, const ValidityReport &report);

}  // namespace rfmems
