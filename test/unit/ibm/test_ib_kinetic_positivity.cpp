// Positivity of the IB-face distribution (lib/ibm/ib_kinetic_face_values, clip_negative):
// the step-(iii) fits (Lebesgue constants up to 2.5) overshoot where f jumps across a stencil.
// No measured gas state of the project produced a negative value (closed box, the switch's
// first gas steps: docs/ibm.md "Positivity"), so the state here is made to: argon at rest in a
// 24 x 24 box around a square body moving at 40 m/s, f the rest Maxwellian left of x = 0.42 and
// 1e-2 of it right of it (the jump crosses the body's top and bottom IB faces).
//
// Asserted: the unclipped update has negative entering values (the test can fail); with the
// clip every value filled into an IB face is >= 0; the mass flux of every IB face is the same
// with and without the clip: the impermeable wall's rho_ref u_i . S_i with balance_mass_flux
// (1e-12 of rho_ref c_th |S|), the unclipped one without it (except at a face whose entering
// values were all negative, which takes its FLUID cell's; unclipped, such a face cannot be
// balanced at all, clipped it is). Measured: 216 of 2808 entering
// values negative, all on 2 faces whose entering half is all negative (to -1.7e-10 rho, a few
// % of the Maxwellian's peak): a linear extrapolation across the 100x jump.
#include <gtest/gtest.h>

#include <cmath>

#include "ibm/fluid_face_graph.hpp"
#include "ibm/force_transfer.hpp"
#include "ibm/ib_kinetic_face_values.hpp"
#include "mesh/structured_mesh.hpp"
#include "physics/gas/kinetic/equilibrium.hpp"

namespace rfmems {
namespace {

constexpr Real T0 = 273.15;

TEST(IbKineticPositivity, ClipKeepsEveryFaceMassFlux) {
  BoxSpec spec;
  spec.n[0] = spec.n[1] = 24;
  const Mesh mesh = make_structured_mesh(spec);
  const ImmersedSurface body = ImmersedSurface::rectangle({0.31, 0.37, 0}, {0.53, 0.61, 0}, 3, 3);
  const std::vector<Vec3> segment_velocity(body.n_segments(), Vec3(40, 0, 0));
  const CellMarking marking = CellMarker(mesh).mark(body);
  const FluidFaceGraph fluid = fluid_face_graph(face_graph_of(mesh), marking);
  const std::vector<Vec3> face_velocity =
      ForceTransfer(mesh, marking, body).to_ib_faces(segment_velocity);
  const KineticGas gas = KineticGas::argon();
  const VelocityGrid grid = VelocityGrid::uniform(6, 6, 6, 3.5 * gas.thermal_speed(T0));
  const Index N = grid.size();
  const Real rho = gas.density_for_knudsen(0.1, T0, 1.0);
  std::vector<Real> m(N);
  evaluate_equilibrium(equilibrium(maxwellian_target(rho, Vec3::Zero(), T0, gas), gas.model, grid),
                       grid, m);
  const FaceGraph& g = fluid.graph;
  std::vector<Real> f(g.n_cells() * N, 0.0);
  for (Index c = 0; c < g.n_cells(); ++c)
    for (Index k = 0; k < N; ++k) f[c * N + k] = (g.cell_centroid[c].x() < 0.42 ? 1 : 1e-2) * m[k];

  // Per IB graph face: the lowest filled value and the mass flux sum_k w_k (c_k . S) f_k.
  struct Faces {
    Real lowest = 0;
    std::vector<Real> flux;
    std::vector<bool> all_negative;  // every entering value < 0 (unclipped)
    IbPositivityReport report;
  };
  auto run = [&](bool clip, bool balance) {
    IbKineticOptions o;
    o.wall_temperature = T0;
    o.clip_negative = clip;
    o.balance_mass_flux = balance;
    IbKineticFaceValues values(mesh, fluid, marking, body, segment_velocity, face_velocity, grid,
                               gas, rho, o);
    // First-order transport: the owners' values at the faces are their cell values.
    std::vector<Real> owner((g.n_faces() - g.n_interior_faces) * N);
    for (Index face = g.n_interior_faces; face < g.n_faces(); ++face)
      std::copy_n(f.data() + g.face_owner[face] * N, N,
                  owner.data() + (face - g.n_interior_faces) * N);
    values.update(f, owner);
    Faces out;
    out.report = values.positivity();
    std::vector<Real> v(N);
    for (Index face = 0; face < g.n_faces(); ++face) {
      if (fluid.ib_face[face] < 0) continue;
      values.fill(face, std::span<const Real>(f).subspan(g.face_owner[face] * N, N), v);
      Real flux = 0;
      bool all_negative = true;
      for (Index k = 0; k < N; ++k) {
        if (grid.c[k].dot(g.face_area[face]) < 0 && !(v[k] < 0)) all_negative = false;
        out.lowest = std::min(out.lowest, v[k]);
        flux += grid.w[k] * grid.c[k].dot(g.face_area[face]) * v[k];
      }
      out.flux.push_back(flux);
      out.all_negative.push_back(all_negative);
    }
    return out;
  };
  const Faces raw = run(false, true), clipped = run(true, true);
  const Faces raw_free = run(false, false), clipped_free = run(true, false);
  std::printf(
      "%lld of %lld entering values negative on %lld faces, deepest min/max|.| %.3e; lowest filled "
      "value / rho: unclipped %.3e, clipped %.3e\n",
      static_cast<long long>(raw.report.negative_entering),
      static_cast<long long>(raw.report.entering_values),
      static_cast<long long>(raw.report.faces_with_negative), raw.report.most_negative_entering,
      raw.lowest / rho, clipped.lowest / rho);
  EXPECT_GT(raw.report.negative_entering, 0);
  EXPECT_LT(raw.lowest, 0);
  EXPECT_GE(clipped.lowest, 0);
  EXPECT_EQ(clipped.report.negative_entering, raw.report.negative_entering);  // counted before
  Index all_negative = 0;
  for (bool b : raw.all_negative) all_negative += b;
  EXPECT_GT(all_negative, 0);
  EXPECT_EQ(clipped.report.faces_from_cell, all_negative);
  ASSERT_EQ(raw.flux.size(), clipped.flux.size());
  const Real scale = rho * gas.thermal_speed(T0) / 24;  // rho c_th |S|
  Index k = 0;
  for (Index face = 0; face < g.n_faces(); ++face) {
    if (fluid.ib_face[face] < 0) continue;
    const Real target = rho * face_velocity[fluid.ib_face[face]].dot(g.face_area[face]);
    // Unclipped, an all-negative entering half carries mass out and the balance's factor
    // cannot fix it (it needs an entering flux); clipped, every face balances.
    if (!raw.all_negative[k]) EXPECT_NEAR(raw.flux[k], target, 1e-12 * scale);
    EXPECT_NEAR(clipped.flux[k], target, 1e-12 * scale);
    // Without the balance, a face whose entering half was all negative takes the cell's values
    // (its flux changes); every other face keeps its unclipped flux.
    if (!raw_free.all_negative[k])
      EXPECT_NEAR(clipped_free.flux[k], raw_free.flux[k], 1e-12 * scale);
    ++k;
  }
  EXPECT_GE(clipped_free.lowest, 0);
}

}  // namespace
}  // namespace rfmems
