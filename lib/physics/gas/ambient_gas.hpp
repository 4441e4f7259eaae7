// The gas around a switch, read from a case's `gas:` section, with one meaning and one default
// per key for every gas model (Reynolds film under a plate or a beam, ESBGK on the immersed
// background):
//
//   gas:
//     pressure: 1 atm            # ambient p0; required unless model: none
//     temperature: 300 K         # ambient and wall T0
//     viscosity: 1.85e-5 Pa*s    # mu at T0 (air at 300 K)
//     omega: 0.74                # mu(T) = mu (T / T0)^omega (the kinetic gas's temperature law)
//     mean_free_path: 67 nm      # lambda at p0 and T0; default mu / p0 sqrt(pi R T0 / 2), air
//     rarefaction: veijola       # the film's flow factor: veijola | none | table
//     flow_factor_table: FILE    # rarefaction: table: Q(Kn) (materials/flow_factor_table.hpp),
//                                # a path relative to the case file
//
// The film's Knudsen number at a local pressure p and gap g is lambda p0 / (p g).
#pragma once
#include "io/case_file.hpp"
#include "materials/gas_properties.hpp"

namespace rfmems {

struct AmbientGas {
  GasProperties film;  // p0, mu(T0), lambda(p0) (reference_pressure = p0), rarefaction
  Real temperature = 300;
  Real omega = 0.74;
};

// pressure_required: the case's gas is on (its model is not none). Every key is read, and
// checked, either way, so that a case toggled by --set gas.model=... stays valid.
AmbientGas read_ambient_gas(const CaseNode& gas, bool pressure_required);

// The keys read_ambient_gas reads (ambient_gas.keys.yaml; io/case_schema.hpp).
CaseSchema ambient_gas_case_keys();

}  // namespace rfmems
