// Cantilever under end shear, plane stress (E = 210 GPa, nu = 0.25), L = 2 m, D = 0.2 m,
// P = -1000 N/m: the Timoshenko-Goodier solution (beam theory with shear deformation) as
// reference. The reference displacement is a cubic polynomial, so:
//  - the default cubic reconstruction must reproduce it to round-off on any mesh;
//  - the classical linear reconstruction (degree 1, the thesis's scheme) must converge at
//    second order, reaching 0.5 % tip error on the finest mesh.
// Both must converge in one Newton step (linear static problem, exact Jacobian).
#include <gtest/gtest.h>

#include <cmath>

#include "../support/analytic_elasticity.hpp"
#include "mesh/structured_mesh.hpp"
#include "physics/elasticity/elasticity_operator.hpp"
#include "solvers/static_solve.hpp"

using namespace rfmems;
using test_support::TimoshenkoCantilever;

namespace {

const TimoshenkoCantilever beam{2.0, 0.2, 210e9, 0.25, -1000.0};

struct Result {
  double tip_error, rms_error;
  long newton;
};

Mesh beam_mesh(int nx, int ny) {
  BoxSpec spec;
  spec.upper = Vec3(beam.L, beam.D / 2, 0);
  spec.lower = Vec3(0, -beam.D / 2, 0);
  spec.n[0] = nx;
  spec.n[1] = ny;
  return make_structured_mesh(spec);
}

// The reference's displacement on the clamp, its shear traction on the end, free elsewhere.
std::vector<ElasticityBoundary> reference_boundaries(const Mesh& mesh) {
  std::vector<ElasticityBoundary> bcs(mesh.patches().size());
  for (std::size_t p = 0; p < bcs.size(); ++p) {
    const std::string& name = mesh.patches()[p].name;
    if (name == "left")
      bcs[p] = {ElasticityBoundary::Kind::Fixed,
                [](const Vec3& x, double) { return beam.displacement(x); }};
    else if (name == "right")
      bcs[p] = {ElasticityBoundary::Kind::Traction,
                [](const Vec3& x, double) { return Vec3(0, beam.stress(x)[2], 0); }};
    else
      bcs[p] = {ElasticityBoundary::Kind::Traction, {}};
  }
  return bcs;
}

Result solve(int nx, int ny, int degree) {
  Mesh mesh = beam_mesh(nx, ny);
  const std::vector<ElasticityBoundary> bcs = reference_boundaries(mesh);
  ElasticityOperator op(mesh, {beam.E, beam.nu, 7800, Hypothesis::PlaneStress}, bcs, {}, degree);
  StaticSolution s = solve_static(op, 0.0);
  auto grad = op.cell_gradients(0.0, s.y);
  // Tip: average of the reconstructions from the two cells touching (L, 0).
  Vec3 tip = Vec3::Zero();
  int count = 0;
  double sum2 = 0, volume = 0;
  for (Index c = 0; c < mesh.n_cells(); ++c) {
    const Vec3& xc = mesh.cell_centroid(c);
    if (xc.x() > beam.L - beam.L / nx && std::abs(xc.y()) < beam.D / ny) {
      tip += op.displacement_at(c, Vec3(beam.L, 0, 0), s.y, grad);
      ++count;
    }
    Vec3 err = Vec3(s.y[2 * c], s.y[2 * c + 1], 0) - beam.displacement(xc);
    sum2 += err.squaredNorm() * mesh.cell_volume(c);
    volume += mesh.cell_volume(c);
  }
  tip /= count;
  double exact = beam.tip_deflection();
  double rms = std::sqrt(sum2 / volume) / std::abs(exact);
  return {std::abs(tip.y() - exact) / std::abs(exact), rms, s.stats.newton_iters};
}

}  // namespace

TEST(CantileverShear, ReferenceSolutionIsConsistent) {
  // Hooke's law applied to the reference displacement reproduces the reference stress.
  double h = 1e-5, E = beam.E, nu = beam.nu;
  for (Vec3 x : {Vec3(0.3, 0.05, 0), Vec3(1.7, -0.08, 0)}) {
    Vec3 dx(h, 0, 0), dy(0, h, 0);
    Vec3 ux = (beam.displacement(x + dx) - beam.displacement(x - dx)) / (2 * h);
    Vec3 uy = (beam.displacement(x + dy) - beam.displacement(x - dy)) / (2 * h);
    double c = E / (1 - nu * nu);
    Vec3 s = beam.stress(x);
    EXPECT_NEAR(c * (ux.x() + nu * uy.y()), s[0], 1e-6 * std::abs(beam.P / beam.D));
    EXPECT_NEAR(c * (uy.y() + nu * ux.x()), s[1], 1e-6 * std::abs(beam.P / beam.D));
    EXPECT_NEAR(E / (2 * (1 + nu)) * (ux.y() + uy.x()), s[2], 1e-6 * std::abs(beam.P / beam.D));
  }
}

TEST(CantileverShear, CubicReconstructionIsExactForTheCubicSolution) {
  for (int n : {40, 80}) {
    Result r = solve(n, n / 10, 3);
    std::printf("cubic, mesh %dx%d: tip error %.3e, rms error %.3e\n", n, n / 10, r.tip_error,
                r.rms_error);
    EXPECT_EQ(r.newton, 1);
    EXPECT_LT(r.rms_error, 1e-8);
    EXPECT_LT(r.tip_error, 1e-5);  // includes the linear reconstruction to the probe point
  }
}

TEST(CantileverShear, LinearReconstructionConvergesAtSecondOrder) {
  Result r[3] = {solve(160, 16, 1), solve(320, 32, 1), solve(640, 64, 1)};
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(r[i].newton, 1) << "a linear static problem needs one Newton step";
    std::printf("linear, mesh %d: tip error %.4e  rms error %.4e\n", 160 << i, r[i].tip_error,
                r[i].rms_error);
  }
  EXPECT_LT(r[2].tip_error, 0.005);
  double order_tip = test_support::observed_order(r[0].tip_error, r[2].tip_error, 4.0);
  double order_rms = test_support::observed_order(r[0].rms_error, r[2].rms_error, 4.0);
  std::printf("observed order: tip %.3f, rms %.3f\n", order_tip, order_rms);
  EXPECT_GE(order_tip, 1.8);
  EXPECT_GE(order_rms, 1.8);
}

// The tip as a run reports it (ElasticityOperator::displacement_functional): u_y at the tip's
// bottom corner as a linear functional of the unknowns equals the tip cell's reconstruction
// there, so on the cubic solution it is the exact corner deflection, while the cell's centroid,
// half a cell short of the end, reads the deflection about (3/2)(dx/2)/L low.
TEST(CantileverShear, TipFunctionalIsTheCellReconstructionAtTheCorner) {
  const int nx = 40, ny = 4;
  Mesh mesh = beam_mesh(nx, ny);
  const std::vector<ElasticityBoundary> bcs = reference_boundaries(mesh);
  ElasticityOperator op(mesh, {beam.E, beam.nu, 7800, Hypothesis::PlaneStress}, bcs);
  const StaticSolution s = solve_static(op, 0.0);
  const Vec3 corner(beam.L, -beam.D / 2, 0);
  Index tip_cell = 0;
  for (Index c = 1; c < mesh.n_cells(); ++c)
    if ((mesh.cell_centroid(c) - corner).norm() < (mesh.cell_centroid(tip_cell) - corner).norm())
      tip_cell = c;
  const LinearFunctional tip = op.displacement_functional(tip_cell, corner, 1);
  const double reconstructed =
      op.displacement_at(tip_cell, corner, s.y, op.cell_gradients(0.0, s.y)).y();
  const double exact = beam.displacement(corner).y(), centroid = s.y[2 * tip_cell + 1];
  std::printf("tip corner: functional %.9e, reconstruction %.9e, exact %.9e, centroid %.9e m\n",
              tip(s.y), reconstructed, exact, centroid);
  EXPECT_NEAR(tip(s.y), reconstructed, 1e-12 * std::abs(exact));
  EXPECT_NEAR(tip(s.y), exact, 1e-5 * std::abs(exact));
  const double centroid_shortfall = (exact - centroid) / exact;
  EXPECT_NEAR(centroid_shortfall, 1.5 * (0.5 / nx), 0.3 * 1.5 * (0.5 / nx));
}
