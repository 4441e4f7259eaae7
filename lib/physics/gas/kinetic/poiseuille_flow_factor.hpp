// The Poiseuille flow factor Q(Kn) of the kinetic gas: the rfmems-flow-factor driver's model.
//
// A case is a body-force-driven channel (cases/gas_poiseuille: diffuse walls bottom and top
// across y, or the half channel below a symmetry plane, periodic sides, body force along x,
// the channel's width H as initial.reference_length; kinetic_case.hpp) plus a list of points:
//
//   flow_factor:
//     points:
//       - {knudsen: 0.01, cells: 80, velocity_points: [8, 24, 8]}
//       - ...
//
// Each point runs the case with initial.knudsen = Kn, mesh.cells = [1, cells] and
// velocity_grid.points = velocity_points (as --set overrides after the command line's own),
// and reports the normalised flow rate G (kinetic_reference.hpp) and
//
//   Q = G / G_continuum = 6 G / delta,   delta = p0 H / (mu0 v0) = sqrt(pi) / (2 Kn),
//
// the flow rate over that of the no-slip continuum channel (delta / 6): the factor the
// Reynolds film divides the viscosity by (materials/flow_factor_table.hpp, whose Kn,
// lambda / H with lambda = (mu / p) sqrt(pi R T / 2), is this one).
//
// The iteration starts from the local Maxwellian of the first-order slip solution,
//   u_x(y) = (rho0 a / (2 mu0)) ((y - y0) (y1 - y) + sigma_P (H / delta) H),  sigma_P = 1.0162,
// (walls at y0, the mesh's lowest y, and y1 = y0 + H) rather than the gas at rest: near the
// continuum the sequential solver's slowest mode is that parabola (its sweeps grow as delta^2), and
// the start removes most of it.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "io/case_file.hpp"
#include "io/case_schema.hpp"

namespace rfmems {

struct FlowFactorPoint {
  Real knudsen = 0;
  int cells = 0;
  std::array<int, 3> velocity_points{0, 0, 0};
};

struct FlowFactorResult {
  FlowFactorPoint point;
  Real rarefaction_parameter = 0;  // delta
  Real flow_rate = 0;              // G
  Real flow_factor = 0;            // Q = 6 G / delta
  int sweeps = 0;
  Real residual_ratio = 0;
  double seconds = 0;
};

// Reads `flow_factor.points` (at least one; Kn > 0, cells >= 2, velocity points >= 2).
std::vector<FlowFactorPoint> read_flow_factor_points(const CaseNode& flow_factor);

// The overrides that set a point's Kn and grids.
std::vector<std::string> flow_factor_overrides(const FlowFactorPoint& point);

// Loads the case file with `overrides` and then the point's, builds the kinetic scene, solves it
// from the slip-flow start and returns G and Q. SolverError if it does not converge; InputError
// unless the case is a body-force-driven channel.
FlowFactorResult compute_flow_factor(const std::string& case_path,
                                     const std::vector<std::string>& overrides,
                                     const FlowFactorPoint& point);

// The table as CSV (the columns FlowFactorTable::read reads, knudsen and flow_factor, and the
// run's own), after `header` lines each written as a '#' comment.
std::string flow_factor_csv(const std::vector<FlowFactorResult>& results,
                            const std::vector<std::string>& header);

// The keys read_flow_factor_points reads (poiseuille_flow_factor.keys.yaml).
CaseSchema flow_factor_case_keys();

}  // namespace rfmems
