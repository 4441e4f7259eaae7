// What a creep run (creep_run.hpp) needs of a plate creep case (creep_case.hpp), and how its
// outputs go into a result file:
//   system     a fresh PlateCreepSystem (law, thickness points, the hold voltage if any) on the
//              case's plate operator (on its von Karman plate with geometric nonlinearity), per
//              run segment;
//   gap        min over the gap points over the electrode of g0 + u_q (the plate's w
//              reconstruction at 3 x 3 Simpson points per quadrilateral cell, as the hold load
//              and physics/electrostatics/parallel_plate_actuation.hpp sample it), its rate u_q(w')
//              there;
//   series     per probe its deflection w [m]; min_gap [m] (with a gap); the largest von Mises
//              stress over the two surfaces (z = +-h/2, where creep is fastest) [Pa]; the largest
//              effective creep strain [-]; with a residual stress or geometric nonlinearity,
//              mean_membrane_stress_xx (the cell mean of N_xx / h) [Pa];
//   fields     the plate's own (deflection, rotation, elastic moment, shear force: PlateScene),
//              plastic_moment (M_p,xx, M_p,yy, M_p,xy) [N m/m], von_mises_top, von_mises_bottom
//              [Pa] and creep_strain (max over the thickness of eps_eff) per cell; with a
//              residual stress, membrane_force (N_xx, N_yy, N_xy) [N/m] per cell
//              (PlateCreepSystem::membrane_forces); with geometric nonlinearity the plate's
//              fields hold the stretching part A : eps_m as membrane_force, and the whole
//              N = h sigma0 + A : eps_m - C int eps_p dz is total_membrane_force.
#pragma once
#include "io/result_writer.hpp"
#include "physics/creep/creep_case.hpp"
#include "physics/creep/creep_run.hpp"

namespace rfmems {

CreepRunModel make_plate_creep_model(const CreepCase& creep_case);

// A hold voltage above pull-in has no elastic equilibrium at t = 0: bad input naming
// actuation.voltage (of `root`), not a solver failure. Nothing to check without a hold.
void check_hold_equilibrium(const CaseNode& root, const CreepCase& creep_case,
                            const CreepRunModel& model);

// Writes output `index` (fields kept by the run) as step `index` of the result file.
void write_plate_creep_output(const CreepCase& creep_case, ResultWriter& writer, int index,
                              const CreepOutput& output);

}  // namespace rfmems
