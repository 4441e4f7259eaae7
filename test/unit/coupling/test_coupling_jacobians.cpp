// Finite-difference checks of the coupled switch Jacobians: the plate under the
// parallel-plate force (static adaptor: K + V^2 A p1'(g) on the diagonal) and the monolithic
// plate + parallel-plate + Reynolds film system for IDA (dF/dY + c_j dF/dY', including the
// film's gap and gap-rate columns, which point at the plate's w and its velocity), on a
// deflected plate with a non-uniform film pressure.
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
        *plate.op, elements_over_electrode(plate.gap_elements(""), {30e-6, 70e-6}, true), kGap, law);
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
};

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
    std::vector<FilmBoundary> bcs;
    for (const Patch& p : f.plate.mesh->patches())
      bcs.push_back({p.name == "left" || p.name == "right" ? FilmBoundary::Kind::Wall
                                                           : FilmBoundary::Kind::Open});
    ReynoldsFilm film(*f.plate.mesh, gas, bcs);
    std::vector<Index> w_dof;
    for (Index c = 0; c < film.size(); ++c) w_dof.push_back(3 * c);
    SqueezeFilmSwitchSystem system(*f.act, f.plate.quasi_static_components(), film, w_dof);

    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<double> y, yp;
    system.initial_state(0.0, y, yp);
    const std::vector<double> w = f.deflection(rng);
    std::copy(w.begin(), w.end(), y.begin());
    const Index m = system.size() - film.size();
    // Steps for the differences; scales (typical sizes) to weigh the columns.
    std::vector<double> steps(y.size()), scales(y.size());
    for (Index i = 0; i < system.size(); ++i) {
      if (i >= m) {  // film pressure and its rate
        y[i] = ambient * (1 + 0.2 * u(rng));
        yp[i] = ambient * 1e5 * u(rng);
        steps[i] = 1e-6 * ambient;
        scales[i] = ambient;
      } else if (i >= static_cast<Index>(w.size())) {  // velocities [m/s]
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
    const auto check = test_support::check_jacobian(system, 1e-6, 3e6, y, yp, steps, scales);
    // Round-off of the y' differences in the rows y' - v (c_j eps |y'| / step): ~2e-6.
    EXPECT_LT(check.max_row_relative, 1e-5) << "ambient " << ambient;
    EXPECT_LT(check.max_entry_relative, 1e-4) << "ambient " << ambient;
    std::printf("ambient %g Pa: max row-relative difference %.2e (row %ld of %ld, film from %ld), "
                "entry-relative %.2e (%ld, %ld)\n",
                ambient, check.max_row_relative, static_cast<long>(check.worst_row),
                static_cast<long>(system.size()), static_cast<long>(m), check.max_entry_relative,
                static_cast<long>(check.worst_entry_row), static_cast<long>(check.worst_entry_col));
  }
}
