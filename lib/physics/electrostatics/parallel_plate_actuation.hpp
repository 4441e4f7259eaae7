// A structure pulled towards an electrode by the parallel-plate law
// (physics/electrostatics/parallel_plate.hpp), as one SecondOrderOperator:
//
//   M y'' + R(t, y) + V(t)^2 sum_e A_e sum_q a_q p1(g_q) n_e = 0,
//   g_q = g0 + u_q(y),   u_q = offset_q + sum_k w_qk y[k]
//
// where each element e of the surface facing the electrode (StructuralModel::gap_elements,
// with its area A_e already multiplied by the fraction of it over the electrode) carries the
// force of its quadrature points q (area fractions a_q; GapPoint) on its unknown y[dof_e]
// along the gap axis (positive: opening), p1 is the pressure per V^2 and n_e = the unit vector
// of dof_e: the force -A p1 V^2 closes the gap. The displacement u_q at a point is the
// structure's reconstruction of its surface there (a plate: its w polynomial, Simpson points
// on the cell's edges and corners; plate_scene.cpp), or the element's own unknown (one point,
// a continuum's faces). The Jacobian adds V^2 A_e a_q p1'(g_q) w_qk (negative: the
// electrostatic spring softening) in row dof_e, column k: the diagonal and, for reconstructed
// points, the reconstruction's stencil (stiffness_pattern() is the structure's pattern with
// those entries). The coupling is monolithic: one Newton step of a static solve or an IDA step
// sees the exact tangent.
//
// With a contact penalty (contact_penalty.hpp) each point also carries the contact pressure
// p_c(g, V) = V^2 p1(g_c) phi((g_c - g)/delta), opening: the residual adds
// -V^2 A_e a_q p1(g_c) phi(s_q) n_e and the tangent +V^2 A_e a_q p1(g_c) phi'(s_q)/delta w_qk,
// so the structure can rest on the dielectric, contact is sensed where the reconstructed
// surface is closest, and the exact tangent includes the contact stiffness.
//
// Without contact, a gap that closes to g_e <= 0 (electrical gap) raises RecoverableError: IDA
// retries with a smaller step, KINSOL backtracks; without contact a run that really touches down is
// stopped before by the contact root (see dynamic_pull_in.hpp).
#pragma once
#include <algorithm>
#include <functional>
#include <vector>

#include "core/system_operator.hpp"
#include "physics/electrostatics/contact_penalty.hpp"
#include "physics/electrostatics/parallel_plate.hpp"
#include "physics/structure/structural_model.hpp"

namespace rfmems {

// The electrode: the region of the substrate (x, and y for a plate) under the structure.
struct ElectrodeExtent {
  Real x_min = -1e300, x_max = 1e300;
  Real y_min = -1e300, y_max = 1e300;  // plates only (across the width)
};

// The gap elements' areas scaled by the fraction of their bounding box over the electrode
// (exact for rectangular cells and faces); elements entirely off the electrode are dropped.
// Along y only for plates (the gap axis is z); a continuum's faces are lines in x.
std::vector<GapElement> elements_over_electrode(const std::vector<GapElement>& elements,
                                                const ElectrodeExtent& electrode, bool use_y);

class ParallelPlateActuation : public SecondOrderOperator {
 public:
  ParallelPlateActuation(SecondOrderOperator& structure, std::vector<GapElement> elements,
                         Real initial_gap, ParallelPlateLaw law);

  // Contact with the dielectric (default: none).
  void set_contact(const ContactPenalty& contact);
  const ContactPenalty& contact() const { return contact_; }

  // V(t)^2 [V^2]; zero until set.
  void set_voltage_squared(std::function<Real(Real t)> v2) { voltage_squared_ = std::move(v2); }
  Real voltage_squared(Real t) const { return voltage_squared_ ? voltage_squared_(t) : 0.0; }

  Index size() const override { return structure_.size(); }
  void internal_residual(Real t, std::span<const Real> y, std::span<Real> r) override;
  const CsrPattern& stiffness_pattern() const override { return pattern_; }
  void stiffness(Real t, std::span<const Real> y, std::span<Real> values) override;
  std::vector<Real> mass_diagonal() const override { return structure_.mass_diagonal(); }
  Real damping_time() const override { return structure_.damping_time(); }
  void add_damping_force(Real t, std::span<const Real> v, std::span<Real> r) override {
    structure_.add_damping_force(t, v, r);
  }

  // d(residual)/d(V^2) = sum_e A_e sum_q a_q (p1(g_q) - p_c(g_q)/V^2) n_e (the force per V^2,
  // with the residual's sign).
  void residual_per_volt2(std::span<const Real> y, std::span<Real> out) const;
  // Air gap at element e's unknown, and at its point q.
  Real gap(std::span<const Real> y, std::size_t e) const { return gap0_ + y[elements_[e].dof]; }
  Real gap(std::span<const Real> y, const GapPoint& q) const {
    return gap0_ + gap_displacement(q, y);
  }
  // The smallest air gap over the points (the touching criterion), and the electrostatic force
  // along the gap axis summed over the points (negative: closing) at V^2.
  Real min_gap(std::span<const Real> y) const;
  Real total_force(Real voltage_squared, std::span<const Real> y) const;
  // The contact force along the gap axis summed over the points (positive: opening) at V^2,
  // and the fraction of the electrode's area in contact (g_q < g_c).
  Real contact_force(Real voltage_squared, std::span<const Real> y) const;
  Real contact_fraction(std::span<const Real> y) const;

  const std::vector<GapElement>& elements() const { return elements_; }
  Real initial_gap() const { return gap0_; }
  const ParallelPlateLaw& law() const { return law_; }
  SecondOrderOperator& structure() { return structure_; }

 private:
  void check_gap(Real g, std::size_t e) const;
  // sum_q a_q f(g_q) over element e's points.
  template <class F>
  Real point_sum(std::span<const Real> y, std::size_t e, F f) const {
    Real sum = 0;
    for (const GapPoint& q : elements_[e].points) sum += q.area_fraction * f(gap(y, q));
    return sum;
  }
  // Electrostatic pressure per V^2 at air gap g, and its derivative. Off the dielectric the
  // parallel-plate law. In contact (g < g_c) the surfaces touch: the penetration g_c - g is the
  // penalty's regularisation, not a thinner gap, so the field stays that of the dielectric's
  // equivalent gap g_c + t_d/eps_r (the hold-down force of Rebeiz, RF MEMS: Theory, Design and
  // Technology, 2003; a penalty regularises the contact constraint only, Wriggers,
  // Computational Contact Mechanics, 2006). C^1 over one penetration tolerance:
  //   p = p1c + a (u - u^2 / (2 delta))  (0 < u = g_c - g < delta),   p1c + a delta / 2 beyond,
  // with a = -p1'(g_c). Bounded, so the penalty's slope 2 p1c/delta wins at every depth and
  // the net pressure (electrostatic minus contact) vanishes at s = 1 + delta / (2 g_ec) at any
  // voltage; continuing the 1/g_e^2 singularity into the penetration instead let a cell that
  // overshoots past s ~ 3 (delta = g_c/5) fall through the dielectric (IDA_CONV_FAIL on the
  // plate; docs/pull-in.md, "Contact and pull-out").
  Real electrostatic_per_volt2(Real g) const {
    if (!contact_.enabled() || g >= contact_.gap) return law_.pressure_per_volt2(g);
    const Real u = std::min(contact_.gap - g, contact_.penetration);
    return p1_contact_ + slope_contact_ * (u - 0.5 * u * u / contact_.penetration);
  }
  Real electrostatic_per_volt2_derivative(Real g) const {
    if (!contact_.enabled() || g >= contact_.gap) return law_.pressure_per_volt2_derivative(g);
    const Real u = std::min(contact_.gap - g, contact_.penetration);
    return -slope_contact_ * (1 - u / contact_.penetration);
  }
  // Net pressure per V^2 (electrostatic minus contact) at air gap g, and its derivative.
  Real net_pressure_per_volt2(Real g) const {
    return electrostatic_per_volt2(g) - contact_.pressure_per_volt2(g, p1_contact_);
  }
  Real net_pressure_per_volt2_derivative(Real g) const {
    return electrostatic_per_volt2_derivative(g) -
           contact_.pressure_per_volt2_derivative(g, p1_contact_);
  }

  SecondOrderOperator& structure_;
  std::vector<GapElement> elements_;
  Real gap0_;
  ParallelPlateLaw law_;
  ContactPenalty contact_;
  Real p1_contact_ = 0;     // p1(g_c)
  Real slope_contact_ = 0;  // -p1'(g_c)
  std::function<Real(Real)> voltage_squared_;
  CsrPattern pattern_;                     // the structure's, with the points' stencils
  std::vector<Index> structure_position_;  // per structure entry: its index in pattern_
  std::vector<Index> term_position_;       // per (element, point, term): index of (dof_e, k)
  std::vector<Real> structure_values_;
};

}  // namespace rfmems
