// Tests of the FAS grid transfers (comet/fas_transfer.hpp) on a skewed graded 12 x 10 mesh
// with blocks of 5 values per cell.
//
// Asserted: restricting a field conserves its volume integral to round-off and maps a uniform
// field to itself exactly; restricting a residual conserves its sum per block entry; the
// injected correction of a coarse field restricts back to that field (R_sol P = identity) to
// round-off.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "mesh/structured_mesh.hpp"
#include "physics/gas/comet/fas_transfer.hpp"

namespace rfmems {
namespace {

FaceGraph skewed_mesh() {
  BoxSpec spec;
  spec.upper = Vec3(1.5, 1.0, 1.0);
  spec.n[0] = 12;
  spec.n[1] = 10;
  spec.grading[0] = 2.0;
  return face_graph_of(make_structured_mesh(
      spec, [](const Vec3& x) { return Vec3(x.x() + 0.2 * x.y() * x.y(), x.y(), x.z()); }));
}

TEST(FasTransfer, ConservationAndInjection) {
  const FaceGraph fine = skewed_mesh();
  const Agglomeration a = agglomerate(fine);
  const Index block = 5, nf = fine.n_cells(), nc = a.coarse.n_cells();
  std::mt19937 rng(11);
  std::uniform_real_distribution<Real> u(0.5, 2.0);
  std::vector<Real> f(nf * block), fc(nc * block);
  for (Real& x : f) x = u(rng);

  restrict_solution(fine, a, block, f, fc);
  for (Index i = 0; i < block; ++i) {
    Real fine_int = 0, coarse_int = 0;
    for (Index c = 0; c < nf; ++c) fine_int += fine.cell_volume[c] * f[c * block + i];
    for (Index k = 0; k < nc; ++k) coarse_int += a.coarse.cell_volume[k] * fc[k * block + i];
    EXPECT_NEAR(coarse_int, fine_int, 1e-14 * fine_int);
  }

  std::vector<Real> uniform(nf * block, 3.25), uc(nc * block);
  restrict_solution(fine, a, block, uniform, uc);
  for (Real x : uc) EXPECT_NEAR(x, 3.25, 1e-15 * 3.25);

  std::vector<Real> rc(nc * block);
  restrict_residual(a, block, f, rc);
  for (Index i = 0; i < block; ++i) {
    Real sf = 0, sc = 0;
    for (Index c = 0; c < nf; ++c) sf += f[c * block + i];
    for (Index k = 0; k < nc; ++k) sc += rc[k * block + i];
    EXPECT_NEAR(sc, sf, 1e-14 * sf);
  }

  std::vector<Real> e(nc * block), zero(nf * block, 0.0), back(nc * block);
  for (Real& x : e) x = u(rng);
  prolong_correction(a, block, e, zero);
  restrict_solution(fine, a, block, zero, back);
  for (Index i = 0; i < nc * block; ++i) EXPECT_NEAR(back[i], e[i], 1e-14 * e[i]);
}

}  // namespace
}  // namespace rfmems
