// The plate-vs-continuum creep benchmark of thesis Tables 4.1-4.2: a fixed-fixed
// strip of length L and thickness h = L/(L/h) under a uniform downward pressure q, its two
// ends clamped, the rest free; creep for a given time. The same problem in two models:
//
//   plate      PlateCreepSystem on the mid-surface (L x width), ends Clamped, long edges Free,
//              q on the mid-surface; Simpson points through the thickness.
//   continuum  ContinuumCreepSystem on the x-z section (L x h) in plane stress, ends Fixed
//              (u = 0), q as a traction on the top face, the bottom face free; or on the 3D
//              strip (L x h x width), the same ends and load, its long side faces free.
//
// Which 2D continuum: a plate with free long edges bends anticlastically (M_yy = 0 away from
// the clamps: sigma_yy = 0 in every fibre), i.e. as a narrow beam with modulus E, which is the
// plane-stress section; plane strain (E/(1 - nu^2), sigma_yy = nu sigma_xx) would be cylindrical
// bending, which the plate only has within ~ a width of a clamp. So the plate strip is made
// narrow (width ~ L/20 and below) for the comparison, and the width's own effect is measured.
//
// Both run IDA from the elastic state (initial_state); the result is the centre deflection at
// t = 0 and its creep increment w(t_end) - w(0) (the thesis's "plastic deformation").
#pragma once
#include <array>
#include <memory>
#include <vector>

#include "materials/creep_law.hpp"
#include "materials/linear_elastic.hpp"
#include "mesh/mesh.hpp"
#include "physics/creep/continuum_creep_system.hpp"
#include "physics/creep/plate_creep_system.hpp"
#include "physics/plate/plate_operator.hpp"
#include "solvers/ida_integrator.hpp"

namespace rfmems {

struct FixedFixedCreepProblem {
  Real length = 240e-6;   // L [m]
  Real slenderness = 60;  // L/h
  Real width = 12e-6;     // plate width [m] (the plane-stress section has none)
  Real load = 6e4;        // q [Pa], downward
  Real E = 200e9, nu = 0.3, rho = 7854;
  CreepLaw law{8.33e-6, 1.8e8, 2, 2, 1e9};  // thesis Table 4.1 (grain-boundary sliding)
  int continuum_source_degree = 2;          // ContinuumCreepSystem's sigma_p reconstruction degree
  int continuum_reconstruction_degree = 0;  // the displacement's (ElasticityOperator; 0: default)
  // Diagnostic: the stress components the continuum's creep law sees (Voigt xx, yy, zz, xy,
  // yz, xz; ContinuumCreepSystem::set_creep_stress_mask). kBendingOnly keeps the axial stress
  // alone, dropping the section's transverse shear xy and through-thickness yy: the plate's
  // bending-only creep assumption inside the continuum model.
  std::array<bool, 6> continuum_creep_stress{true, true, true, true, true, true};
  static constexpr std::array<bool, 6> kBendingOnly{true, false, true, false, false, false};
  // ... without the transverse shear xy alone (the through-thickness yy kept).
  static constexpr std::array<bool, 6> kNoShear{true, true, true, false, true, true};
  // The plate model with transverse shear creep (PlateCreepSystem shear_creep; run with KLU).
  bool plate_shear_creep = false;
  // The continuum on its half x <= L/2, the plane x = L/2 a symmetry boundary (u_x = 0, no
  // shear traction): the strip, its load and its clamps are mirror-symmetric about it, so this
  // is the same problem at half the unknowns. nx then counts the half's cells.
  bool continuum_half_length = false;
  // The continuum's linear solves (ContinuumCreepSystem::set_linear_solver).
  ContinuumCreepSystem::LinearSolver continuum_linear_solver =
      ContinuumCreepSystem::LinearSolver::Krylov;
  Real thickness() const { return length / slenderness; }
};

struct CreepRunResult {
  Real w_elastic = 0;  // centre deflection at t = 0 [m]
  Real w_plastic = 0;  // w(t_end) - w(0) [m]
  Index unknowns = 0;
  IntegratorStats stats;
  double wall_seconds = 0;     // set-up, initial state and integration
  double elastic_seconds = 0;  // set-up and the initial (elastic, static) state
  double cpu_seconds = 0, elastic_cpu_seconds = 0;  // the same in the process's CPU time
};

// The plate model of the problem, for runs that drive its creep system themselves (the
// benchmarks' explicit and implicit integrations, the Table 4.1 study).
struct FixedFixedCreepPlate {
  Mesh mesh;
  std::unique_ptr<PlateOperator> op;
  std::unique_ptr<PlateCreepSystem> system;
  Index centre = -1;  // the cell nearest the centre of the mid-surface: w = state[3 centre]
};
std::unique_ptr<FixedFixedCreepPlate> make_fixed_fixed_creep_plate(
    const FixedFixedCreepProblem& problem, int nx, int ny, int thickness_intervals = 20);

// nx x ny cells on the plate's mid-surface; thickness_intervals Simpson intervals. IDA with its
// options (the Schur-complement preconditioned SPGMR of the plate if linear_solver is Spgmr).
CreepRunResult run_plate_creep(const FixedFixedCreepProblem& problem, int nx, int ny,
                               int thickness_intervals, const IdaOptions& options, Real end_time);
// The continuum model's mesh, boundaries and material: nx x nz cells on the x-z section, plane
// stress; with width_cells > 0 the 3D strip of width problem.width (the thesis's comparison),
// nx x nz x width_cells cells, its long faces free; on the half span with
// continuum_half_length.
// The comparison reads the deflection at the span's centre (x = L/2, mid-thickness and, in 3D,
// mid-width), in the cell nearest to it.
struct ContinuumStrip {
  Mesh mesh;
  std::vector<ElasticityBoundary> boundaries;
  LinearElastic material;
  Vec3 centre;
  Index centre_cell = 0;
};
ContinuumStrip make_continuum_strip(const FixedFixedCreepProblem& problem, int nx, int nz,
                                    int width_cells = 0);

// The strip's linear elastic system at rest, for its static solves by sparse LU or by
// multigrid: the operator's own stiffness K (the default reconstruction), the compact (linear
// reconstruction) operator's K_c, the matrix a multigrid is built from, and the load
// f = -R(0), the top's pressure. `strip` must outlive it.
struct ContinuumStripStatics {
  explicit ContinuumStripStatics(const ContinuumStrip& strip);
  ElasticityOperator op, compact;
  std::vector<Real> load, stiffness, compact_stiffness;
};

// The continuum strip's creep run.
CreepRunResult run_continuum_creep(const FixedFixedCreepProblem& problem, int nx, int nz,
                                   const IdaOptions& options, Real end_time, int width_cells = 0);

}  // namespace rfmems
