// Tests of pairwise agglomeration (fv/agglomeration.hpp), the coarse levels of COMET's FAS
// multigrid.
//
// Asserted on a structured 32 x 32 rectangle, a skewed graded 24 x 20 rectangle and an
// 8 x 8 x 8 box, for every level of the hierarchy: the total volume and each patch's summed
// area vector are conserved to round-off; every coarse cell is closed (its outward area vectors
// sum to zero, relative 1e-13 to its face areas); every fine cell maps to a coarse cell and
// every coarse cell holds >= 2 fine cells; coarse volumes and centroids are the sums and
// volume-weighted means of their fine cells; no coarse interior face joins a cell to itself and
// no two coarse faces join the same pair; the coarsening ratio per level is in [1.8, 2.2]
// (pairs, few singletons) and the hierarchy stops at the minimum cell count.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <set>
#include <utility>

#include "core/error.hpp"
#include "fv/agglomeration.hpp"
#include "mesh/structured_mesh.hpp"

namespace rfmems {
namespace {

Real total_volume(const FaceGraph& g) {
  Real v = 0;
  for (Real x : g.cell_volume) v += x;
  return v;
}

std::vector<Vec3> patch_areas(const FaceGraph& g) {
  std::vector<Vec3> s(g.patch_names.size(), Vec3::Zero());
  for (Index f = g.n_interior_faces; f < g.n_faces(); ++f) s[g.face_patch[f]] += g.face_area[f];
  return s;
}

void check_level(const FaceGraph& fine, const Agglomeration& a) {
  const FaceGraph& g = a.coarse;
  ASSERT_EQ(static_cast<Index>(a.coarse_of_fine.size()), fine.n_cells());
  EXPECT_NEAR(total_volume(g), total_volume(fine), 1e-13 * total_volume(fine));
  const auto sf = patch_areas(fine), sc = patch_areas(g);
  ASSERT_EQ(sf.size(), sc.size());
  for (std::size_t p = 0; p < sf.size(); ++p)
    EXPECT_LT((sf[p] - sc[p]).norm(), 1e-13 * (sf[p].norm() + 1e-300)) << g.patch_names[p];

  // Membership, volumes, centroids.
  std::vector<Index> count(g.n_cells(), 0);
  std::vector<Real> vol(g.n_cells(), 0);
  std::vector<Vec3> mom(g.n_cells(), Vec3::Zero());
  for (Index c = 0; c < fine.n_cells(); ++c) {
    const Index k = a.coarse_of_fine[c];
    ASSERT_GE(k, 0);
    ASSERT_LT(k, g.n_cells());
    ++count[k];
    vol[k] += fine.cell_volume[c];
    mom[k] += fine.cell_volume[c] * fine.cell_centroid[c];
  }
  for (Index k = 0; k < g.n_cells(); ++k) {
    EXPECT_GE(count[k], 2);
    EXPECT_NEAR(g.cell_volume[k], vol[k], 1e-14 * vol[k]);
    EXPECT_LT((g.cell_centroid[k] - mom[k] / vol[k]).norm(), 1e-12 * std::sqrt(vol[k]));
  }

  // Closed cells and a clean face list.
  std::set<std::pair<Index, Index>> pairs;
  for (Index f = 0; f < g.n_interior_faces; ++f) {
    EXPECT_NE(g.face_owner[f], g.face_neighbour[f]);
    EXPECT_EQ(g.face_patch[f], -1);
    EXPECT_TRUE(pairs.insert({g.face_owner[f], g.face_neighbour[f]}).second);
  }
  for (Index f = g.n_interior_faces; f < g.n_faces(); ++f) {
    EXPECT_EQ(g.face_neighbour[f], -1);
    EXPECT_GE(g.face_patch[f], 0);
    if (f > g.n_interior_faces) {
      EXPECT_LE(g.face_patch[f - 1], g.face_patch[f]);  // grouped by patch
    }
  }
  for (Index k = 0; k < g.n_cells(); ++k) {
    Vec3 sum = Vec3::Zero();
    Real scale = 0;
    for (Index i = g.cell_face_offsets[k]; i < g.cell_face_offsets[k + 1]; ++i) {
      const Index f = g.cell_faces[i];
      sum += g.face_owner[f] == k ? Vec3(g.face_area[f]) : Vec3(-g.face_area[f]);
      scale += g.face_area[f].norm();
    }
    EXPECT_LT(sum.norm(), 1e-13 * scale) << "coarse cell " << k;
  }
}

void check_hierarchy(const FaceGraph& fine, Index min_cells) {
  const auto levels = agglomeration_hierarchy(fine, min_cells);
  ASSERT_GE(levels.size(), 3u);
  const FaceGraph* g = &fine;
  for (const Agglomeration& a : levels) {
    check_level(*g, a);
    const Real ratio = Real(g->n_cells()) / Real(a.coarse.n_cells());
    EXPECT_GE(ratio, 1.8);
    EXPECT_LE(ratio, 2.2);
    EXPECT_GE(a.coarse.n_cells(), min_cells);
    g = &a.coarse;
  }
  std::printf("hierarchy:");
  for (const Agglomeration& a : levels)
    std::printf(" %lld", static_cast<long long>(a.coarse.n_cells()));
  std::printf("\n");
  // It stopped because the next level would be too small (or too little reduction).
  const Agglomeration next = agglomerate(*g);
  EXPECT_TRUE(next.coarse.n_cells() < min_cells || 4 * next.coarse.n_cells() > 3 * g->n_cells());
}

TEST(Agglomeration, StructuredRectangle) {
  BoxSpec spec;
  spec.dim = 2;
  spec.upper = Vec3(1.0, 1.0, 1.0);
  spec.n[0] = spec.n[1] = 32;
  const FaceGraph fine = face_graph_of(make_structured_mesh(spec));
  const Agglomeration a = agglomerate(fine);
  EXPECT_EQ(a.coarse.n_cells(), 512);  // an even structured mesh pairs without singletons
  check_hierarchy(fine, 8);
}

TEST(Agglomeration, SkewedGradedRectangle) {
  BoxSpec spec;
  spec.dim = 2;
  spec.upper = Vec3(2.0, 1.0, 1.0);
  spec.n[0] = 24;
  spec.n[1] = 20;
  spec.grading[0] = 3.0;
  spec.grading[1] = 0.5;
  const FaceGraph fine = face_graph_of(make_structured_mesh(spec, [](const Vec3& x) {
    return Vec3(x.x() + 0.3 * x.y(), x.y() + 0.1 * std::sin(3 * x.x()), x.z());
  }));
  check_hierarchy(fine, 10);
}

TEST(Agglomeration, Box3D) {
  BoxSpec spec;
  spec.dim = 3;
  spec.upper = Vec3(1.0, 2.0, 0.5);
  spec.n[0] = spec.n[1] = spec.n[2] = 8;
  const FaceGraph fine = face_graph_of(make_structured_mesh(spec));
  check_hierarchy(fine, 4);
}

TEST(Agglomeration, GhostCellsRejected) {
  BoxSpec spec;
  spec.n[0] = spec.n[1] = 4;
  FaceGraph fine = face_graph_of(make_structured_mesh(spec));
  fine.n_owned_cells -= 1;
  EXPECT_THROW(agglomerate(fine), InputError);
}

}  // namespace
}  // namespace rfmems
