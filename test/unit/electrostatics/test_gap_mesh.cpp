// The gap mesh under a beam and a full gap solve at production size.
//
// Asserted: the gap's top nodes coincide with a graded beam mesh's bottom nodes (match_nodes
// finds every partner at distance 0, and throws MeshError, naming the node, for a shifted
// beam); the bottom splits into electrode and substrate faces by centroid; the gap area is
// exact. On a 400 x 40 gap (electrode on the middle half, substrate zero-flux): charge is
// conserved (plate charge = -electrode charge to round-off) before and after a 50 % parabolic
// deflection; the second solve reuses the symbolic factorisation; the attraction grows. The
// timings (first factorisation, refactorisation after motion) are printed.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "mesh/mesh_motion.hpp"
#include "mesh/structured_mesh.hpp"
#include "physics/electrostatics/electrostatic_solver.hpp"
#include "physics/electrostatics/gap_mesh.hpp"

namespace rfmems {
namespace {

constexpr Real L = 300e-6, h = 2e-6, g = 3e-6;

TEST(GapMesh, ConformsToTheBeamAndSplitsTheBottom) {
  BoxSpec beam_spec;
  beam_spec.lower = Vec3(0, 0, 0);
  beam_spec.upper = Vec3(L, h, 0);
  beam_spec.n[0] = 60;
  beam_spec.n[1] = 4;
  beam_spec.grading[0] = 2.0;
  Mesh beam = make_structured_mesh(beam_spec);

  GapMeshSpec spec;
  spec.x = patch_node_x(beam, "bottom");
  spec.gap = g;
  spec.n_y = 8;
  spec.electrode_begin = L / 3;
  spec.electrode_end = 2 * L / 3;
  Mesh gap = make_gap_mesh(spec);
  for (const char* name : {"top", "electrode", "substrate", "left", "right"})
    EXPECT_GE(gap.find_patch(name), 0) << name;
  EXPECT_EQ(gap.patches().size(), 5u);

  Real area = 0;
  for (Index c = 0; c < gap.n_cells(); ++c) area += gap.cell_volume(c);
  EXPECT_NEAR(area, L * g, 1e-12 * L * g);
  const Patch& electrode = gap.patches()[gap.find_patch("electrode")];
  const Patch& substrate = gap.patches()[gap.find_patch("substrate")];
  EXPECT_EQ(electrode.n_faces + substrate.n_faces, 60);
  for (Index f = electrode.first_face; f < electrode.first_face + electrode.n_faces; ++f) {
    EXPECT_GE(gap.face_centroid(f).x(), L / 3);
    EXPECT_LE(gap.face_centroid(f).x(), 2 * L / 3);
    EXPECT_NEAR(gap.face_centroid(f).y(), -g, 1e-20);
  }

  const auto beam_nodes = beam.patch_nodes(beam.find_patch("bottom"));
  const auto top_nodes = gap.patch_nodes(gap.find_patch("top"));
  ASSERT_EQ(top_nodes.size(), 61u);
  const auto match = match_nodes(beam, beam_nodes, gap, top_nodes, 1e-12);
  for (std::size_t i = 0; i < top_nodes.size(); ++i)
    EXPECT_EQ(beam.nodes()[match[i]], gap.nodes()[top_nodes[i]]);

  Mesh shifted =
      make_structured_mesh(beam_spec, [](const Vec3& p) { return Vec3(p + Vec3(1e-7, 0, 0)); });
  try {
    match_nodes(shifted, beam_nodes, gap, top_nodes, 1e-9);
    FAIL() << "no MeshError";
  } catch (const MeshError& e) {
    EXPECT_NE(std::string(e.what()).find("node "), std::string::npos) << e.what();
  }
}

TEST(GapMesh, FourHundredByFortySolveAndRefactorAfterMotion) {
  GapMeshSpec spec;
  for (int i = 0; i <= 400; ++i) spec.x.push_back(L * i / 400);
  spec.gap = g;
  spec.n_y = 40;
  spec.electrode_begin = L / 4;
  spec.electrode_end = 3 * L / 4;
  Mesh mesh = make_gap_mesh(spec);
  const std::map<std::string, PotentialBoundary> bcs{
      {"top", PotentialBoundary::potential(30.0)},
      {"electrode", PotentialBoundary::potential(0.0)},
      {"substrate", PotentialBoundary::zero_flux()},
      {"left", PotentialBoundary::zero_flux()},
      {"right", PotentialBoundary::zero_flux()}};
  ElectrostaticSolver solver(mesh, bcs);
  MeshMotion motion(mesh, {"top"}, {"electrode", "substrate"});

  solver.solve();
  const auto first = solver.stats();
  const SurfaceLoad before = solver.surface_load("top");
  const Real q_electrode = solver.surface_load("electrode").charge;
  EXPECT_FALSE(first.symbolic_reused);
  EXPECT_NEAR(before.charge + q_electrode, 0.0, 1e-10 * before.charge);

  std::vector<Vec3> d;
  for (Index n : motion.moving_nodes()) {
    const Real xi = motion.reference_nodes()[n].x() / L;
    d.emplace_back(0, -0.5 * g * 4 * xi * (1 - xi), 0);
  }
  motion.move(d);
  solver.solve();
  const auto second = solver.stats();
  const SurfaceLoad after = solver.surface_load("top");
  EXPECT_TRUE(second.symbolic_reused);
  EXPECT_NEAR(after.charge + solver.surface_load("electrode").charge, 0.0, 1e-10 * after.charge);
  EXPECT_GT(-after.force.y(), 1.5 * -before.force.y());

  ElectrostaticSolver fresh(mesh, bcs);  // the moved mesh factorised from scratch
  fresh.solve();
  for (Index c = 0; c < mesh.n_cells(); ++c)
    ASSERT_NEAR(fresh.potential()[c], solver.potential()[c], 1e-9);
  std::printf("400 x 40 gap: %lld unknowns, %lld nonzeros\n",
              static_cast<long long>(first.n_unknowns), static_cast<long long>(first.nnz));
  std::printf("first solve:  assembly %.3f s, analyse+factorise %.3f s, solve %.3f s\n",
              first.assembly_seconds, first.factor_seconds, first.solve_seconds);
  std::printf(
      "after motion: assembly %.3f s, refactorise %.3f s, solve %.3f s (fresh analyse+factorise "
      "%.3f s)\n",
      second.assembly_seconds, second.factor_seconds, second.solve_seconds,
      fresh.stats().factor_seconds);
  std::printf("force on the beam: %.4e -> %.4e N/m, min volume ratio %.3f\n", before.force.y(),
              after.force.y(), motion.min_volume_ratio());
}

}  // namespace
}  // namespace rfmems
