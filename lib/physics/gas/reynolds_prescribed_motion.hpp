// The squeeze film alone, under a prescribed plate motion, as a SystemOperator for IDA
// (transients) or KINSOL (quasi-static: y' = 0 with the gap still moving): the gap g and gap
// rate g' per cell at time t, either functions g(x, t), g'(x, t) evaluated at the cell
// centroids or given per cell (a partitioned coupling's structure: its gap over a step).
//
// Two choices of unknown y per cell:
//   Pressure      y = p [Pa]. F = ReynoldsFilm::residual(p, y', g, g'). What the coupled
//                 plate-film system uses; IDA tolerances in Pa (atol ~ 1e-6 p_a works).
//   GapPressure   y = p g / g_ref [Pa] (g_ref: the mean gap at the initial time given to the
//                 constructor), the conserved variable scaled back to pressure units. Then
//                 F = A g_ref y' - sum_f flux_f(p = g_ref y / g) exactly, and because the
//                 fluxes cancel in pairs, every BDF step of IDA (exact Newton with KLU, whose
//                 Jacobian column sums carry only c_j A g_ref) keeps sum_c A p g constant to
//                 round-off. With y = p the product rule d(p g)/dt = p' g + p g' is applied
//                 to BDF derivatives, which conserves mass only to the truncation error.
//
// Jacobian: Pressure: the film's pressure_jacobian; GapPressure, with p = g_ref y / g and
// p' = (g_ref y' - p g') / g:  J = (dF/dp) diag(g_ref / g) + diag(A g_ref (c_j - g'/g)).
//
// The residual is left in its natural units, Pa m^3/s per cell (unit depth, rows
// ~ p g A / t): IDA's Newton test acts on the correction in y (tolerances in Pa), so with the
// KLU direct solver row scaling is immaterial, and with SPGMR the left preconditioner (an LU
// of this Jacobian) brings the Krylov residual back to y units too.
#pragma once
#include <functional>
#include <vector>

#include "core/system_operator.hpp"
#include "physics/gas/reynolds_film.hpp"

namespace rfmems {

using FilmField = std::function<Real(const Vec3& x, Real t)>;
// Fills the gap and its rate per cell at time t.
using CellGap = std::function<void(Real t, std::span<Real> gap, std::span<Real> gap_rate)>;

class ReynoldsPrescribedMotion : public SystemOperator {
 public:
  enum class Unknown { Pressure, GapPressure };

  // gap and gap_rate must be consistent (gap_rate = d gap / dt); t0 fixes g_ref.
  ReynoldsPrescribedMotion(const ReynoldsFilm& film, FilmField gap, FilmField gap_rate,
                           Unknown unknown = Unknown::Pressure, Real t0 = 0);
  ReynoldsPrescribedMotion(const ReynoldsFilm& film, CellGap gap,
                           Unknown unknown = Unknown::Pressure, Real t0 = 0);

  Index size() const override { return film_.size(); }
  std::vector<Real> differential_components() const override;
  void residual(Real t, std::span<const Real> y, std::span<const Real> yp,
                std::span<Real> r) override;
  const CsrPattern& jacobian_pattern() const override { return film_.cell_pattern(); }
  void jacobian(Real t, Real c_j, std::span<const Real> y, std::span<const Real> yp,
                std::span<Real> values) override;

  Unknown unknown() const { return unknown_; }
  Real reference_gap() const { return reference_gap_; }
  // The gap and its rate at the cell centroids at time t.
  std::vector<Real> gap(Real t) const;
  std::vector<Real> gap_rate(Real t) const;
  // State <-> pressure.
  std::vector<Real> pressure(Real t, std::span<const Real> y) const;
  std::vector<Real> state(Real t, std::span<const Real> p) const;
  // y' with F(t, y, y') = 0 (the storage term is diagonal): the consistent initial rate.
  std::vector<Real> consistent_rate(Real t, std::span<const Real> y);
  // Film mass in pressure units, sum_c A_c p_c g_c [Pa m^3 per unit depth].
  Real mass(Real t, std::span<const Real> y) const;

 private:
  // Fills p, p', g, g' from (t, y, y').
  void unpack(Real t, std::span<const Real> y, std::span<const Real> yp);

  const ReynoldsFilm& film_;
  CellGap gap_;
  Unknown unknown_;
  Real reference_gap_ = 1;
  std::vector<Real> p_, p_rate_, g_, g_rate_, values_;
};

}  // namespace rfmems
