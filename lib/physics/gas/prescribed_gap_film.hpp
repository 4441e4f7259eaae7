// A squeeze film stepped under a prescribed gap, the gas step of a partitioned coupling: each
// advance over [t, t + dt] integrates the isothermal Reynolds equation (reynolds_film.hpp, exact
// Jacobian) by IDA (BDF of order at most 2, Newton with KLU; rtol, atol = rtol p_a) under the
// gap of each film cell linear in time from the last advance's to the new one
// (reynolds_prescribed_motion.hpp), IDA restarted at order 1 from the pressure rate consistent
// with the new interval's gap rate. Used under a plate's cells (film_under_structure.hpp) and on
// the strip under an immersed beam (ibm/immersed_reynolds_film.hpp).
#pragma once
#include <memory>
#include <vector>

#include "core/types.hpp"

namespace rfmems {

class ReynoldsFilm;
class ReynoldsPrescribedMotion;
class IdaIntegrator;

class PrescribedGapFilm {
 public:
  // The film at the ambient pressure over the gap per cell `gap` at time t0 (film outlives this).
  PrescribedGapFilm(const ReynoldsFilm& film, std::vector<Real> gap, Real t0, Real rtol = 1e-6);
  ~PrescribedGapFilm();

  // Advances over [t, t + dt] to the gap per cell `gap` at t + dt; returns the pressure there.
  const std::vector<Real>& advance(std::vector<Real> gap, Real t, Real dt);
  const std::vector<Real>& pressure() const { return state_.p; }
  // The largest Knudsen number lambda(p) / g over the cells at the advances' ends.
  Real max_knudsen() const { return state_.max_knudsen; }
  // The pressure, its rate and the gap after the last advance (and the Knudsen maximum).
  void save_checkpoint();
  void restore_checkpoint();

 private:
  const ReynoldsFilm& film_;
  std::unique_ptr<ReynoldsPrescribedMotion> motion_;
  std::unique_ptr<IdaIntegrator> ida_;
  // The gap linear in time over the current advance [t0, t1], from h0 to h1.
  Real t0_ = 0, t1_ = 1;
  std::vector<Real> h0_, h1_;
  struct State {
    std::vector<Real> p, p_rate, h;
    Real max_knudsen = 0;
  };
  State state_;  // at the last advance's end
  State saved_;
  bool has_saved_ = false;
};

}  // namespace rfmems
