// Mesh motion of the gap under a beam (300 um x 3 um, 150 x 15 quads): the top wall moves,
// the electrode stays, the side walls slide.
//
// Asserted: a parabolic (fixed-fixed) top deflection of 90 % of the gap keeps every cell
// valid (min volume ratio ~ 0.1 = the uniform compression of the linear blend), the moving
// nodes take exactly the prescribed displacement and the fixed nodes stay exactly; a
// deflection of 110 % throws MeshError naming the cell and leaves the mesh as it was; moves
// are relative to the reference (repeating one gives the same nodes; zero gives the
// reference back exactly); side nodes slide along their walls (x unchanged to the bit) under
// a cantilever-like deflection; the exponential blend with r0 = gap height inverts cells at
// 90 % (why the linear blend is the default, see mesh_motion.hpp) but passes at 50 %; bad
// input is InputError.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "mesh/mesh_motion.hpp"
#include "physics/electrostatics/gap_mesh.hpp"

namespace rfmems {
namespace {

constexpr Real L = 300e-6, g = 3e-6;

Mesh gap_mesh() {
  GapMeshSpec spec;
  for (int i = 0; i <= 150; ++i) spec.x.push_back(L * i / 150);
  spec.gap = g;
  spec.n_y = 15;
  return make_gap_mesh(spec);
}

// Prescribed top displacement: d_y = -fraction g 4 (x/L)(1 - x/L).
std::vector<Vec3> parabolic(const Mesh& mesh, const MeshMotion& motion, Real fraction) {
  std::vector<Vec3> d;
  for (Index n : motion.moving_nodes()) {
    const Real xi = motion.reference_nodes()[n].x() / L;
    d.emplace_back(0, -fraction * g * 4 * xi * (1 - xi), 0);
  }
  (void)mesh;
  return d;
}

TEST(MeshMotion, NinetyPercentParabolicDeflectionStaysValid) {
  Mesh mesh = gap_mesh();
  MeshMotion motion(mesh, {"top"}, {"electrode"});
  EXPECT_EQ(motion.moving_nodes().size(), 151u);
  const auto d = parabolic(mesh, motion, 0.9);
  ASSERT_NO_THROW(motion.move(d));
  const Real ratio = motion.min_volume_ratio();
  std::printf("90 %% deflection: min cell volume ratio %.4f\n", ratio);
  EXPECT_GT(ratio, 0.09);
  mesh.check_quality();
  const auto& ref = motion.reference_nodes();
  for (std::size_t i = 0; i < d.size(); ++i) {
    const Index n = motion.moving_nodes()[i];
    EXPECT_EQ(motion.node_displacement()[n], d[i]);
    EXPECT_EQ(mesh.nodes()[n], Vec3(ref[n] + d[i]));
  }
  for (Index n : mesh.patch_nodes(mesh.find_patch("electrode")))
    EXPECT_EQ(mesh.nodes()[n], ref[n]) << "fixed node " << n;
}

TEST(MeshMotion, BeyondTheGapThrowsNamingTheCellAndRestores) {
  Mesh mesh = gap_mesh();
  MeshMotion motion(mesh, {"top"}, {"electrode"});
  motion.move(parabolic(mesh, motion, 0.5));
  const std::vector<Vec3> before = mesh.nodes();
  try {
    motion.move(parabolic(mesh, motion, 1.1));
    FAIL() << "no MeshError";
  } catch (const MeshError& e) {
    const std::string message = e.what();
    std::printf("%s\n", message.c_str());
    EXPECT_NE(message.find("mesh motion: cell "), std::string::npos) << message;
    EXPECT_NE(message.find("inverted"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos);
  }
  EXPECT_EQ(mesh.nodes(), before);
  mesh.check_quality();
}

TEST(MeshMotion, MovesAreRelativeToTheReference) {
  Mesh mesh = gap_mesh();
  const std::vector<Vec3> reference = mesh.nodes();
  MeshMotion motion(mesh, {"top"}, {"electrode"});
  const auto d = parabolic(mesh, motion, 0.6);
  motion.move(d);
  const std::vector<Vec3> once = mesh.nodes();
  motion.move(d);
  EXPECT_EQ(mesh.nodes(), once);
  motion.move(std::vector<Vec3>(d.size(), Vec3::Zero()));
  EXPECT_EQ(mesh.nodes(), reference);
  EXPECT_EQ(motion.min_volume_ratio(), 1.0);
}

TEST(MeshMotion, SideNodesSlideAlongTheirWalls) {
  Mesh mesh = gap_mesh();
  MeshMotion motion(mesh, {"top"}, {"electrode"});
  std::vector<Vec3> d;
  for (Index n : motion.moving_nodes()) {
    const Real xi = motion.reference_nodes()[n].x() / L;
    d.emplace_back(0.3 * g * xi, -0.8 * g * xi * xi, 0);  // a tip that also moves along x
  }
  ASSERT_NO_THROW(motion.move(d));
  const auto& ref = motion.reference_nodes();
  Real largest_slide = 0;
  for (const char* side : {"left", "right"})
    for (Index n : mesh.patch_nodes(mesh.find_patch(side))) {
      const bool corner = std::abs(ref[n].y()) < 1e-15 || std::abs(ref[n].y() + g) < 1e-15;
      if (corner) continue;  // the top corners are moving nodes, the bottom ones fixed
      EXPECT_EQ(mesh.nodes()[n].x(), ref[n].x()) << side << " node " << n;
      largest_slide = std::max(largest_slide, std::abs(mesh.nodes()[n].y() - ref[n].y()));
    }
  EXPECT_GT(largest_slide, 0.3 * g);  // the right wall did follow the tip down
  std::printf("cantilever-like move: min volume ratio %.3f\n", motion.min_volume_ratio());
}

TEST(MeshMotion, ExponentialBlendWithGapDecayLengthInvertsAtNinetyPercent) {
  for (Real fraction : {0.5, 0.9}) {
    Mesh mesh = gap_mesh();
    MeshMotionOptions options;
    options.decay_length = g;
    MeshMotion motion(mesh, {"top"}, {"electrode"}, options);
    if (fraction < 0.6) {
      EXPECT_NO_THROW(motion.move(parabolic(mesh, motion, fraction)));
      std::printf("exponential r0 = g, 50 %%: min volume ratio %.3f\n", motion.min_volume_ratio());
    } else {
      EXPECT_THROW(motion.move(parabolic(mesh, motion, fraction)), MeshError);
    }
  }
}

TEST(MeshMotion, BadInputIsInputError) {
  Mesh mesh = gap_mesh();
  EXPECT_THROW(MeshMotion(mesh, {"lid"}, {"electrode"}), InputError);
  EXPECT_THROW(MeshMotion(mesh, {}, {"electrode"}), InputError);
  MeshMotion motion(mesh, {"top"}, {"electrode"});
  EXPECT_THROW(motion.move(std::vector<Vec3>(3, Vec3::Zero())), InputError);
}

}  // namespace
}  // namespace rfmems
