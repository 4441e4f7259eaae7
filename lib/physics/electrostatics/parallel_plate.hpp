// The parallel-plate law: the electrostatic pressure on a conductor at a local gap g above a
// grounded electrode at potential difference V,
//
//   p(g, V) = eps0 V^2 / (2 g_e^2) (1 + f g_e / b),     g_e = g + t_d / eps_r
//
// pulling the conductor towards the electrode. g_e is the electrical gap through the air gap g
// and a dielectric layer (thickness t_d, relative permittivity eps_r) on the electrode; the
// optional first-order fringing correction f g_e / b (f = 0.65 for a strip of width b:
// Palmer 1937, as used for MEMS beams by Osterberg & Senturia 1997) adds the field lines
// around the edges.
//
// Valid where the gap is small against the lateral scale over which it changes (slope
// dg/dx << 1 and g << the structure's span): then each point of the structure sees the field
// of two parallel plates. That is the case for RF MEMS membranes (g/L ~ 1e-2); where not,
// use the Laplace solver.
#pragma once
#include "core/types.hpp"
#include "physics/electrostatics/permittivity.hpp"

namespace rfmems {

struct ParallelPlateLaw {
  Real dielectric_thickness = 0;     // t_d [m]
  Real dielectric_permittivity = 1;  // eps_r
  Real fringing_factor = 0;          // f (0: no fringing correction)
  Real width = 0;                    // b [m] (used with fringing only)

  Real electrical_gap(Real g) const { return g + dielectric_thickness / dielectric_permittivity; }

  // Pressure per unit V^2 [Pa/V^2] at air gap g (> -t_d/eps_r), and its derivative in g.
  Real pressure_per_volt2(Real g) const {
    const Real ge = electrical_gap(g);
    return 0.5 * kVacuumPermittivity / (ge * ge) * fringe(ge);
  }
  Real pressure_per_volt2_derivative(Real g) const {
    const Real ge = electrical_gap(g);
    // d/dg [eps0/2 (ge^-2 + f ge^-1 / b)] = eps0/2 (-2 ge^-3 - f ge^-2 / b)
    const Real f_over_b = fringing_factor > 0 ? fringing_factor / width : 0.0;
    return 0.5 * kVacuumPermittivity * (-2 / (ge * ge * ge) - f_over_b / (ge * ge));
  }

 private:
  Real fringe(Real ge) const {
    return fringing_factor > 0 ? 1 + fringing_factor * ge / width : 1.0;
  }
};

}  // namespace rfmems
