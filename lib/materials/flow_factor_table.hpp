// The Poiseuille flow factor Q(Kn) of a squeeze film from a table (the kinetic solver's,
// written by rfmems-flow-factor), in place of Veijola's fit (gas_properties.hpp).
//
//   Q(Kn) = G(delta) / G_continuum(delta),  G_continuum = delta / 6,  delta = sqrt(pi) / (2 Kn)
//
// G: the normalised flow rate of plane Poiseuille flow between diffuse walls (linear regime),
// Kn = lambda / g with lambda = (mu / p) sqrt(pi R T / 2), so Q = 12 Kn G / sqrt(pi); the film
// uses it as mu_eff = mu / Q.
//
// The file: CSV, '#' lines are comments; the first other line names the columns, of which
// `knudsen` and `flow_factor` are read (others are ignored). At least two rows, Kn > 0
// strictly increasing, Q > 1 strictly increasing.
//
// Interpolation, Kn_1 <= Kn <= Kn_n: monotone piecewise-cubic Hermite (Fritsch-Carlson, the
// slopes of Fritsch and Butland: weighted harmonic means of the neighbouring secants, zero
// at a local extremum; one-sided secants at the ends) of y = ln Q in x = ln Kn. It passes
// through every node, is C1, and cannot overshoot the data; dQ/dKn = (Q / Kn) dy/dx exactly.
//
// Outside the table:
//  - continuum end, Kn < Kn_1: first-order slip flow, Q = 1 + s Kn with s = (Q_1 - 1) / Kn_1
//    (the slip form Q = 1 + 6 sigma_P (2 / sqrt(pi)) Kn, its coefficient taken from the first
//    node; exact as Kn -> 0, where Q -> 1);
//  - free-molecular end, Kn > Kn_n: G = sqrt(pi) Q / (12 Kn) grows linearly in ln Kn towards the
//    free-molecular law's slope 1 / sqrt(pi) (Cercignani: G ~ -ln(delta) / sqrt(pi) as
//    delta -> 0), which it approaches from below: past the table the true slope lies between
//    the last interval's, s_n, and 1 / sqrt(pi). The extrapolation takes their mean,
//      G = G_n + s ln(Kn / Kn_n),  s = (s_n + 1 / sqrt(pi)) / 2,  Q = 12 Kn G / sqrt(pi),
//    whose error is at most b ln(Kn / Kn_n) with b = |1 / sqrt(pi) - s_n| / 2, and stops where
//    that bound reaches kExtrapolationError of G_n (capped at 10 Kn_n): for the kinetic table
//    (docs/data/flow_factor_bgk.csv, s_n = 0.33 at Kn_n = 10) up to Kn = 24.6;
//  - beyond: InputError naming the table and the Kn (the log law's constant is not known
//    further out).
#pragma once
#include <string>
#include <vector>

#include "core/types.hpp"

namespace rfmems {

class FlowFactorTable {
 public:
  static constexpr Real kExtrapolationError = 0.05;
  static constexpr Real kMaxReach = 10.0;

  // Nodes (Kn_i, Q_i); `source` names the table in error messages (a file, a key). Throws
  // InputError on fewer than two nodes, non-increasing Kn or Q, Kn <= 0 or Q <= 1.
  FlowFactorTable(std::vector<Real> knudsen, std::vector<Real> flow_factor, std::string source);

  // Reads the CSV file above; InputError naming the file (and line) when it is missing or
  // ill-formed.
  static FlowFactorTable read(const std::string& path);

  struct Value {
    Real q, dq_dkn;
  };
  // Q(Kn) and dQ/dKn; InputError beyond max_extrapolated_knudsen().
  Value evaluate(Real kn) const;
  Real operator()(Real kn) const { return evaluate(kn).q; }

  Real min_knudsen() const { return kn_.front(); }
  Real max_knudsen() const { return kn_.back(); }
  // The largest Kn evaluate() accepts.
  Real max_extrapolated_knudsen() const { return max_extrapolated_; }
  // The slope s of G in ln Kn past the table.
  Real free_molecular_slope() const { return fm_slope_; }
  const std::vector<Real>& knudsen() const { return kn_; }
  const std::vector<Real>& flow_factor() const { return q_; }
  const std::string& source() const { return source_; }

 private:
  std::vector<Real> kn_, q_;
  std::vector<Real> x_, y_, slope_;  // ln Kn, ln Q, dy/dx at the nodes
  Real fm_slope_ = 0, max_extrapolated_ = 0;
  std::string source_;
};

}  // namespace rfmems
