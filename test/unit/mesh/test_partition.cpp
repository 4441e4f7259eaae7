// METIS partitions and local meshes with ghost layers: every cell owned exactly once, ghost
// layers of the requested depth, geometry preserved, and the elasticity residual on the owned
// cells of each local mesh equal to the global residual (the property distributed runs rely on).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mesh/partition.hpp"
#include "mesh/structured_mesh.hpp"
#include "physics/elasticity/elasticity_operator.hpp"

using namespace rfmems;

namespace {

std::vector<ElasticityBoundary> boundaries(const Mesh& mesh) {
  std::vector<ElasticityBoundary> bcs;
  for (const Patch& p : mesh.patches()) {
    if (p.name == "left")
      bcs.push_back({ElasticityBoundary::Kind::Fixed,
                     [](const Vec3& x, double) { return Vec3(0, 1e-4 * x.y(), 0); }});
    else if (p.name == "bottom")
      bcs.push_back({ElasticityBoundary::Kind::Symmetry, {}});
    else
      bcs.push_back({ElasticityBoundary::Kind::Traction,
                     [](const Vec3&, double) { return Vec3(0, -1e5, 0); }});
  }
  return bcs;
}

}  // namespace

TEST(Partition, KwayPartitionCoversEveryCellOnce) {
  BoxSpec spec;
  spec.upper = Vec3(4, 1, 0);
  spec.n[0] = 40;
  spec.n[1] = 10;
  Mesh mesh = make_structured_mesh(spec);
  for (int parts : {1, 2, 3, 4}) {
    Partition p = partition_cells(mesh, parts);
    std::vector<int> count(parts, 0);
    for (int k : p.part) {
      ASSERT_GE(k, 0);
      ASSERT_LT(k, parts);
      ++count[k];
    }
    for (int k = 0; k < parts; ++k) EXPECT_GT(count[k], 0);
    EXPECT_LT(p.imbalance, 1.05);
    if (parts == 1) {
      EXPECT_EQ(p.edge_cut, 0);
    }
    if (parts == 2) {  // a good cut of a 40 x 10 strip is short: about one cross-section
      EXPECT_LE(p.edge_cut, 20);
    }
    std::printf("%d parts: edge cut %ld, imbalance %.3f\n", parts, static_cast<long>(p.edge_cut),
                p.imbalance);
  }
}

TEST(Partition, LocalMeshesReproduceTheGlobalResidual) {
  BoxSpec spec;
  spec.upper = Vec3(3, 1, 0);
  spec.n[0] = 24;
  spec.n[1] = 10;
  Mesh global = make_structured_mesh(spec, [](const Vec3& x) {
    return Vec3(x.x() + 0.05 * std::sin(2 * x.y()), x.y() + 0.04 * std::sin(3 * x.x()), 0);
  });
  LinearElastic steel{200e9, 0.3, 7800, Hypothesis::PlaneStrain};
  ElasticityOperator global_op(global, steel, boundaries(global));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> value(-1e-4, 1e-4);
  std::vector<double> u(global_op.size()), r(global_op.size());
  for (double& x : u) x = value(rng);
  global_op.internal_residual(0.0, u, r);
  double scale = 0;
  for (double x : r) scale = std::max(scale, std::abs(x));

  const int parts = 3, ghost_layers = 4;  // cubic reconstruction: stencils reach 3 rings
  Partition partition = partition_cells(global, parts);
  Index owned_total = 0;
  for (int k = 0; k < parts; ++k) {
    LocalMesh local = extract_local_mesh(global, partition, k, ghost_layers);
    const Mesh& mesh = local.mesh;
    owned_total += mesh.n_owned_cells();
    ASSERT_GE(mesh.find_patch("processor"), 0);
    for (Index c = 0; c < mesh.n_cells(); ++c) {
      Index g = local.global_cell[c];
      EXPECT_EQ(mesh.global_cell_id(c), g);
      EXPECT_NEAR(mesh.cell_volume(c), global.cell_volume(g), 1e-14);
      EXPECT_EQ(c < mesh.n_owned_cells(), partition.part[g] == k);
    }
    ElasticityOperator op(mesh, steel, boundaries(mesh));
    std::vector<double> ul(op.size()), rl(op.size());
    for (Index c = 0; c < mesh.n_cells(); ++c)
      for (int d = 0; d < 2; ++d) ul[2 * c + d] = u[2 * local.global_cell[c] + d];
    op.internal_residual(0.0, ul, rl);
    double diff = 0;
    for (Index c = 0; c < mesh.n_owned_cells(); ++c)
      for (int d = 0; d < 2; ++d)
        diff = std::max(diff, std::abs(rl[2 * c + d] - r[2 * local.global_cell[c] + d]));
    EXPECT_LT(diff, 1e-9 * scale) << "part " << k;
  }
  EXPECT_EQ(owned_total, global.n_cells());
}
