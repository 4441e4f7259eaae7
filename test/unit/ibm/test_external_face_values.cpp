// Tests of the External boundary kind of the kinetic operator (the hook the immersed gas uses,
// lib/physics/gas/kinetic/external_face_values.hpp).
//
// Asserted:
//  - a source that fills its faces with the diffuse-wall rule (fill_boundary_face) reproduces
//    the body-fitted DiffuseWall run: Couette flow at Kn = 0.1 (10 cells, 6^3 velocities,
//    sequential solver), the same iterations, distributions equal to round-off (1e-13 relative)
//    and the same wall force;
//  - update_boundary_values(f) calls the source's update once, then fill per External face;
//  - an External patch without a source is an error (std::logic_error), and the patch counts
//    as closed (is_closed) like a wall;
//  - fill_boundary_face rejects an External condition.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "mesh/structured_mesh.hpp"
#include "physics/gas/kinetic/sequential_solver.hpp"

namespace rfmems {
namespace {

constexpr Real T0 = 273.15, U = 10;

class DiffuseWallSource : public ExternalFaceValues {
 public:
  DiffuseWallSource(const FaceGraph& g, const VelocityGrid& grid, const KineticGas& gas,
                    KineticBoundary wall)
      : g_(g), grid_(grid), wall_(wall), maxwellian_(boundary_maxwellian(wall, grid, gas)) {}
  void update(std::span<const Real>, std::span<const Real>) override { ++updates; }
  void fill(Index face, std::span<const Real> owner, std::span<Real> out) const override {
    ++fills;
    fill_boundary_face(wall_, g_.face_area[face], owner, grid_, {}, maxwellian_, out);
  }
  int updates = 0;
  mutable int fills = 0;

 private:
  const FaceGraph& g_;
  const VelocityGrid& grid_;
  KineticBoundary wall_;
  std::vector<Real> maxwellian_;
};

struct SolvedState {
  std::vector<Real> f;
  int iterations = 0;
  Vec3 top_force = Vec3::Zero();
};

TEST(ExternalFaceValues, DiffuseWallSourceReproducesTheDiffuseWall) {
  BoxSpec spec;
  spec.n[0] = 1;
  spec.n[1] = 10;
  const FaceGraph g = face_graph_of(make_structured_mesh(spec));
  const KineticGas gas = KineticGas::argon();
  const VelocityGrid grid = VelocityGrid::uniform(6, 6, 6, 3.5 * gas.thermal_speed(T0));
  const Real rho = gas.density_for_knudsen(0.1, T0, 1.0);
  const KineticBoundary moving = KineticBoundary::diffuse_wall(T0, Vec3(0, 0, U));
  auto run = [&](bool external, DiffuseWallSource* source) {
    std::vector<KineticBoundary> bcs(g.patch_names.size(), KineticBoundary::specular_wall());
    bcs[g.find_patch("bottom")] = KineticBoundary::diffuse_wall(T0);
    bcs[g.find_patch("top")] = external ? KineticBoundary::external() : moving;
    KineticOperator op(g, grid, gas, bcs);
    if (source) op.set_external_face_values(source);
    SolvedState r;
    r.f.resize(op.size());
    op.initialize(r.f, [&](const Vec3&) { return GasState{rho, Vec3::Zero(), T0}; });
    r.iterations = solve_sequential(op, r.f).iterations;
    r.top_force = op.wall_force("top", r.f);
    return r;
  };
  const SolvedState body_fitted = run(false, nullptr);
  DiffuseWallSource source(g, grid, gas, moving);
  const SolvedState external = run(true, &source);
  EXPECT_EQ(external.iterations, body_fitted.iterations);
  Real scale = 0, diff = 0;
  for (std::size_t i = 0; i < body_fitted.f.size(); ++i) {
    scale = std::max(scale, std::abs(body_fitted.f[i]));
    diff = std::max(diff, std::abs(external.f[i] - body_fitted.f[i]));
  }
  EXPECT_LE(diff, 1e-13 * scale);
  EXPECT_LE((external.top_force - body_fitted.top_force).norm(),
            1e-12 * body_fitted.top_force.norm());
  EXPECT_GT(std::abs(body_fitted.top_force.z()), 0);

  // One update per full refresh, one fill per External face (the top face).
  std::vector<KineticBoundary> bcs(g.patch_names.size(), KineticBoundary::specular_wall());
  bcs[g.find_patch("top")] = KineticBoundary::external();
  KineticOperator op(g, grid, gas, bcs);
  EXPECT_TRUE(op.is_closed());
  std::vector<Real> f(op.size(), 1.0);
  EXPECT_THROW(op.update_boundary_values(f), std::logic_error);
  DiffuseWallSource counter(g, grid, gas, moving);
  op.set_external_face_values(&counter);
  op.update_boundary_values(f);
  EXPECT_EQ(counter.updates, 1);
  EXPECT_EQ(counter.fills, 1);

  std::vector<Real> out(grid.size());
  EXPECT_THROW(fill_boundary_face(KineticBoundary::external(), Vec3(0, 1, 0), f, grid, {}, {}, out),
               std::logic_error);
}

}  // namespace
}  // namespace rfmems
