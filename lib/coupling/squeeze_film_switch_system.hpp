// A plate switch damped by the squeeze film under it, monolithic: the plate under the
// parallel-plate force (ParallelPlateActuation, rotations quasi-static) and the Reynolds film
// (physics/gas/reynolds_film.hpp) on the same mesh, one cell of film under each plate cell:
//
//   Y = [ structure state S (ReducedInertiaSystem: y, and a velocity v per inertial unknown);
//         film pressure p per cell ]
//   F_S = ReducedInertiaSystem residual, minus (p_c - p_a) A_c in the momentum row of w_c
//   F_p = Reynolds residual with gap g_c = g0 + w_c, gap rate g'_c = v(w_c)
//
// Jacobian: the structure block as ReducedInertiaSystem assembles it, -A_c at (row of v(w_c),
// column p_c), and in the film rows dF/dp + c_j dF/dp' on the p columns, dF/dg on the w
// columns and dF/dg' on the v columns (the gap rate is the state v, not a derivative). So IDA
// sees the exact coupled tangent: no staggering error and no stability limit from the
// coupling. The film is where the damping of the switch comes from (thesis ch. 2:
// pull-in slows as the pressure rises).
#pragma once
#include <vector>

#include "coupling/switch_system.hpp"
#include "physics/gas/reynolds_film.hpp"

namespace rfmems {

class SqueezeFilmSwitchSystem : public SwitchSystem {
 public:
  // w_dof[c]: the structure unknown of the deflection of plate cell c (= film cell c).
  SqueezeFilmSwitchSystem(ParallelPlateActuation& actuation, std::vector<bool> quasi_static,
                          const ReynoldsFilm& film, std::vector<Index> w_dof);

  Index size() const override { return m_ + n_cells_; }
  std::vector<Real> differential_components() const override;
  void residual(Real t, std::span<const Real> y, std::span<const Real> yp,
                std::span<Real> r) override;
  const CsrPattern& jacobian_pattern() const override { return pattern_; }
  void jacobian(Real t, Real c_j, std::span<const Real> y, std::span<const Real> yp,
                std::span<Real> values) override;

  std::vector<StateKind> state_kinds() const override;
  void initial_state(Real t0, std::vector<Real>& y, std::vector<Real>& yp) override;
  Real displacement(std::span<const Real> y, Index i) const override { return y[i]; }
  Real velocity(std::span<const Real> y, std::span<const Real> yp, Index i) const override;
  Real gas_force(std::span<const Real> y) const override;
  ParallelPlateActuation& actuation() override { return actuation_; }
  const ParallelPlateActuation& actuation() const override { return actuation_; }

 private:
  void film_inputs(std::span<const Real> y, std::span<const Real> yp);

  ParallelPlateActuation& actuation_;
  ReducedInertiaSystem structure_;
  const ReynoldsFilm& film_;
  std::vector<Index> w_dof_, v_index_;  // per cell: w's index in y, its velocity's in Y
  Index m_, n_cells_;
  Real p_ambient_;
  CsrPattern pattern_;
  std::vector<Index> structure_position_;  // structure value k -> combined value index
  std::vector<Index> coupling_position_;   // per cell: (row v(w_c), column p_c)
  // Per film pattern entry k (row c, column c'): combined positions of the w, v and p columns.
  std::vector<Index> film_w_position_, film_v_position_, film_p_position_;
  // Scratch.
  std::vector<Real> gap_, gap_rate_, structure_values_, film_values_, film_values0_;
};

}  // namespace rfmems
