// Finite-difference checks of the coupled switch Jacobians: the plate under the
// parallel-plate force (static adaptor: K + V^2 A p1'(g) on the diagonal) and the monolithic
// plate + parallel-plate + Reynolds film system for IDA (dF/dY + c_j dF/dY', including the
// film's gap and gap-rate columns, which point at the plate's w and its velocity), on a
// deflected plate with a non-uniform film pressure; and both again with the actuated cells
// pressed into the dielectric's contact penalty, whose entries are also checked on their own
// scale (there a 0.1 % error in them is caught: PerturbedContact).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "../../support/jacobian_check.hpp"
#include "core/structural_systems.hpp"
#include "coupling/squeeze_film_switch_system.hpp"
#include "io/case_file.hpp"
#include "physics/plate/plate_scene.hpp"

using namespace rfmems;

namespace {

constexpr double kGap = 2e-6;

struct Fixture {
  PlateScene plate;
  std::unique_ptr<ParallelPlateActuation> act;
  Fixture() {
    const CaseFile cf = CaseFile::parse(
        "mesh: {type: rectangle, size: [100 um, 40 um], cells: [6, 3]}\n"
        "material: {E: 200 GPa, nu: 0.31, density: 7854}\n"
        "model: {structure: plate, thickness: 2 um}\n"
        "boundaries: {left: {type: clamped}, right: {type: clamped}, top: {type: free}, "
        "bottom: {type: free}}\n",
        "j.yaml");
    plate = build_plate_scene(cf.root(), "", AnalysisType::Transient);
    ParallelPlateLaw law;
    law.dielectric_thickness = 0.1e-6;
    law.dielectric_permittivity = 7.6;
    law.fringing_factor = 0.65;
    law.width = 40e-6;
    act = std::make_unique<ParallelPlateActuation>(
        *plate.op, elements_over_electrode(plate.gap_elements(""), {30e-6, 70e-6}, true), kGap,
        law);
    act->set_voltage_squared([](Real t) { return (40.0 + 1e6 * t) * (40.0 + 1e6 * t); });
  }
  // A deflected plate state: w up to 0.3 gap down, rotations of its slope's size.
  std::vector<double> deflection(std::mt19937& rng) const {
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<double> y(plate.op->size());
    for (std::size_t i = 0; i < y.size(); ++i)
      y[i] = i % 3 == 0 ? -0.15 * kGap * (1 + u(rng)) : 0.01 * u(rng);
    return y;
  }
  // The film's edges: walls at the clamped ends, open along the free sides.
  std::vector<FilmBoundary> film_boundaries() const {
    std::vector<FilmBoundary> bcs;
    for (const Patch& p : plate.mesh->patches())
      bcs.push_back({p.name == "left" || p.name == "right" ? FilmBoundary::Kind::Wall
                                                           : FilmBoundary::Kind::Open});
    return bcs;
  }
};

// Random film pressures about `ambient` (entries from m on), velocities and rates (from n_w to
// m) and deflection rates (below n_w) of their typical sizes, with the finite-difference steps
// and column scales that go with each kind of unknown.
void randomise_film_state(Index m, Index n_w, double ambient, std::mt19937& rng,
                          std::vector<double>& y, std::vector<double>& yp,
                          std::vector<double>& steps, std::vector<double>& scales) {
  std::uniform_real_distribution<double> u(-1, 1);
  steps.assign(y.size(), 0.0);
  scales.assign(y.size(), 0.0);
  for (Index i = 0; i < static_cast<Index>(y.size()); ++i) {
    if (i >= m) {  // film pressure and its rate
      y[i] = ambient * (1 + 0.2 * u(rng));
      yp[i] = ambient * 1e5 * u(rng);
      steps[i] = 1e-6 * ambient;
      scales[i] = ambient;
    } else if (i >= n_w) {  // velocities [m/s]
      y[i] = 0.1 * u(rng);
      yp[i] = 1e5 * u(rng);
      // F is linear in v and v': a large step has no truncation error and keeps the tiny
      // inertia entries c_j M above the round-off of the differences.
      steps[i] = 1e3;
      scales[i] = 0.1;
    } else {
      yp[i] = 0.1 * u(rng);
      steps[i] = i % 3 == 0 ? 1e-6 * kGap : 1e-6;
      scales[i] = i % 3 == 0 ? kGap : 0.01;
    }
  }
}

}  // namespace

TEST(CouplingJacobian, ParallelPlateActuationStiffness) {
  Fixture f;
  std::mt19937 rng(3);
  const std::vector<double> y = f.deflection(rng), yp(y.size(), 0.0);
  StaticSystem system(*f.act);
  std::vector<double> steps(y.size());
  for (std::size_t i = 0; i < y.size(); ++i) steps[i] = i % 3 == 0 ? 1e-6 * kGap : 1e-6;
  const auto check = test_support::check_jacobian(system, 1e-6, 0.0, y, yp, steps);
  EXPECT_LT(check.max_row_relative, 1e-7);
  EXPECT_LT(check.max_entry_relative, 1e-4);
}

TEST(CouplingJacobian, PlateParallelPlateReynoldsMonolithic) {
  for (const double ambient : {101325.0, 1000.0}) {
    Fixture f;
    GasProperties gas;
    gas.ambient_pressure = ambient;
    ReynoldsFilm film(*f.plate.mesh, gas, f.film_boundaries());
    std::vector<Index> w_dof;
    for (Index c = 0; c < film.size(); ++c) w_dof.push_back(3 * c);
    SqueezeFilmSwitchSystem system(*f.act, f.plate.quasi_static_components(), film, w_dof);

    std::mt19937 rng(7);
    std::vector<double> y, yp;
    system.initial_state(0.0, y, yp);
    const std::vector<double> w = f.deflection(rng);
    std::copy(w.begin(), w.end(), y.begin());
    const Index m = system.size() - film.size();
    // Steps for the differences; scales (typical sizes) to weigh the columns.
    std::vector<double> steps, scales;
    randomise_film_state(m, static_cast<Index>(w.size()), ambient, rng, y, yp, steps, scales);
    const auto check = test_support::check_jacobian(system, 1e-6, 3e6, y, yp, steps, scales);
    // Round-off of the y' differences in the rows y' - v (c_j eps |y'| / step): ~2e-6.
    EXPECT_LT(check.max_row_relative, 1e-5) << "ambient " << ambient;
    EXPECT_LT(check.max_entry_relative, 1e-4) << "ambient " << ambient;
    std::printf(
        "ambient %g Pa: max row-relative difference %.2e (row %ld of %ld, film from %ld), "
        "entry-relative %.2e (%ld, %ld)\n",
        ambient, check.max_row_relative, static_cast<long>(check.worst_row),
        static_cast<long>(system.size()), static_cast<long>(m), check.max_entry_relative,
        static_cast<long>(check.worst_entry_row), static_cast<long>(check.worst_entry_col));
  }
}

namespace {

// The contact penalty (contact_penalty.hpp) at g_c = 0.1 gap, delta = g_c/10, with the
// actuated cells pressed into it at s = 0.3, 0.7, 1.6, 2.4 (both pieces of phi, away from its
// kinks at 0 and 1 by more than the difference step).
constexpr double kContactGap = 0.1 * kGap, kPenetration = 0.1 * kContactGap;

void press(const ParallelPlateActuation& act, std::vector<double>& y) {
  const double s[] = {0.3, 0.7, 1.6, 2.4};
  for (std::size_t e = 0; e < act.elements().size(); ++e)
    y[act.elements()[e].dof] = kContactGap - s[e % 4] * kPenetration - kGap;
}

// The contact part of element e's diagonal entry, -V^2 A_e sum_q a_q p_c'(g_q) w_q,dof_e, over
// its quadrature points (the reconstructed surface: each point's own-cell weight).
double contact_diagonal_part(const ParallelPlateActuation& act, std::span<const double> y,
                             const GapElement& e, double v2) {
  const double p1c = act.law().pressure_per_volt2(kContactGap);
  double part = 0;
  for (const GapPoint& q : e.points)
    for (const DofWeight& t : q.terms)
      if (t.dof == e.dof)
        part -= v2 * e.area * q.area_fraction *
                act.contact().pressure_per_volt2_derivative(act.gap(y, q), p1c) * t.weight;
  return part;
}

// The static system with the contact part of each pressed diagonal entry off by 0.1 %: the
// check of the contact entries below must see it.
class PerturbedContact : public SystemOperator {
 public:
  PerturbedContact(ParallelPlateActuation& act) : act_(act), base_(act) {}
  Index size() const override { return base_.size(); }
  std::vector<Real> differential_components() const override {
    return base_.differential_components();
  }
  void residual(Real t, std::span<const Real> y, std::span<const Real> yp,
                std::span<Real> r) override {
    base_.residual(t, y, yp, r);
  }
  const CsrPattern& jacobian_pattern() const override { return base_.jacobian_pattern(); }
  void jacobian(Real t, Real c_j, std::span<const Real> y, std::span<const Real> yp,
                std::span<Real> values) override {
    base_.jacobian(t, c_j, y, yp, values);
    for (const GapElement& e : act_.elements())
      values[jacobian_pattern().find(e.dof, e.dof)] +=
          1e-3 * contact_diagonal_part(act_, y, e, act_.voltage_squared(t));
  }

 private:
  ParallelPlateActuation& act_;
  StaticSystem base_;
};

}  // namespace

TEST(CouplingJacobian, ContactPenaltyStiffness) {
  Fixture f;
  f.act->set_contact({kContactGap, kPenetration});
  std::mt19937 rng(5);
  std::vector<double> y = f.deflection(rng);
  press(*f.act, y);
  const std::vector<double> yp(y.size(), 0.0);
  std::vector<double> steps(y.size());
  for (std::size_t i = 0; i < y.size(); ++i) steps[i] = i % 3 == 0 ? 1e-6 * kGap : 1e-6;
  StaticSystem system(*f.act);
  const auto check = test_support::check_jacobian(system, 1e-6, 0.0, y, yp, steps);
  const double v2 = f.act->voltage_squared(1e-6);
  std::printf("contact: entry-relative difference %.2e; the force in contact %.3e N\n",
              check.max_entry_relative, f.act->contact_force(v2, y));
  EXPECT_GT(f.act->contact_force(v2, y), 0.0);
  EXPECT_LT(check.max_row_relative, 1e-7);
  EXPECT_LT(check.max_entry_relative, 1e-4);
  // The contact entries on their own scale: |J_fd - J| over the contact part of the entry
  // (the penalty's stiffness is a few % of the plate's diagonal here, so the whole-entry
  // measure above would let a 0.1 % error in it pass).
  auto contact_error = [&](SystemOperator& op) {
    const std::vector<double> values = test_support::analytic_jacobian(op, 1e-6, 0.0, y, yp);
    std::vector<double> part(y.size(), 0.0);
    for (const GapElement& e : f.act->elements())
      part[e.dof] += contact_diagonal_part(*f.act, y, e, v2);
    double worst = 0;
    test_support::for_each_jacobian_entry(op, 1e-6, 0.0, y, yp, steps, values,
                                          [&](Index i, Index j, double fd, double an) {
                                            if (i == j && part[i] > 0)
                                              worst = std::max(worst, std::abs(fd - an) / part[i]);
                                          });
    return worst;
  };
  const double good = contact_error(system);
  PerturbedContact perturbed(*f.act);
  const double bad = contact_error(perturbed);
  std::printf("contact entries: error / contact part %.2e; with a 0.1 %% error in them %.2e\n",
              good, bad);
  EXPECT_LT(good, 1e-4);
  EXPECT_GT(bad, 5e-4);
}

TEST(CouplingJacobian, PlateReynoldsInContactMonolithic) {
  Fixture f;
  f.act->set_contact({kContactGap, kPenetration});
  GasProperties gas;
  ReynoldsFilm film(*f.plate.mesh, gas, f.film_boundaries());
  std::vector<Index> w_dof;
  for (Index c = 0; c < film.size(); ++c) w_dof.push_back(3 * c);
  SqueezeFilmSwitchSystem system(*f.act, f.plate.quasi_static_components(), film, w_dof);
  std::mt19937 rng(11);
  std::vector<double> y, yp;
  system.initial_state(0.0, y, yp);
  std::vector<double> w = f.deflection(rng);
  press(*f.act, w);
  std::copy(w.begin(), w.end(), y.begin());
  const Index m = system.size() - film.size();
  std::vector<double> steps, scales;
  randomise_film_state(m, static_cast<Index>(w.size()), gas.ambient_pressure, rng, y, yp, steps,
                       scales);
  const auto check = test_support::check_jacobian(system, 1e-6, 3e6, y, yp, steps, scales);
  std::printf(
      "film + contact: row-relative %.2e (row %ld), entry-relative %.2e (%ld, %ld), "
      "film from %ld\n",
      check.max_row_relative, (long)check.worst_row, check.max_entry_relative,
      (long)check.worst_entry_row, (long)check.worst_entry_col, (long)m);
  EXPECT_LT(check.max_row_relative, 1e-5);
  EXPECT_LT(check.max_entry_relative, 1e-4);
}
