// Uniaxial creep of a bar under constant stress in the continuum creep model
// (physics/creep/continuum_creep_system.hpp), against the closed form of the hardening law
// (materials/creep_law.hpp, docs/creep.md): eps_p,xx(t) = ((1 + (k+1) B a t)^(1/(k+1)) - 1)/B,
// a = A (sigma/sigma_y0)^m, k = m n.
//
// Plane stress: a 4 x 1 mm strip (8 x 3 cells) pulled by a traction sigma on its right end, the
// left end and the bottom on symmetry planes, the top free: the stress is uniaxial and uniform,
// so every cell creeps as the closed form; the lateral plastic strain is -eps_p,xx/2 and the
// end moves by (sigma/E + eps_p,xx) L. Same for a 3D bar (symmetry on x = 0, y = 0, z = 0).
// IDA (rtol 1e-7) over 500 h, relative error <= 1e-4 at every output.
//
// Volume preservation: in plane strain and 3D the out-of-plane / all normal plastic strains are
// states, tr(eps_p) = 0 is not imposed, and must hold to round-off (a plane-strain strip under
// an end traction has sigma_zz = nu-like and a non-uniaxial flow).
#include <gtest/gtest.h>

#include <cmath>

#include "mesh/structured_mesh.hpp"
#include "physics/creep/continuum_creep_system.hpp"
#include "solvers/ida_integrator.hpp"

using namespace rfmems;
using Kind = ElasticityBoundary::Kind;

namespace {

constexpr Real kHours = 3600.0, kLength = 4e-3;

Mesh bar(int dim) {
  BoxSpec spec;
  spec.dim = dim;
  spec.upper = Vec3(kLength, 1e-3, dim == 3 ? 1e-3 : 0.0);
  spec.n[0] = 8;
  spec.n[1] = 3;
  spec.n[2] = 2;
  spec.grading[0] = 1.5;  // uneven cells: the uniformity is not a symmetry of the mesh
  return make_structured_mesh(spec);
}

std::vector<ElasticityBoundary> pulled(const Mesh& mesh, Real sigma) {
  std::vector<ElasticityBoundary> bcs(mesh.patches().size());
  for (std::size_t p = 0; p < bcs.size(); ++p) {
    const std::string& name = mesh.patches()[p].name;
    if (name == "left" || name == "bottom" || name == "back") bcs[p].kind = Kind::Symmetry;
    if (name == "right") bcs[p].value = [sigma](const Vec3&, Real) { return Vec3(sigma, 0, 0); };
  }
  return bcs;
}

struct UniaxialResult {
  Real worst_strain = 0, worst_lateral = 0, worst_extension = 0, worst_trace = 0;
  long steps = 0;
};

UniaxialResult run_uniaxial(int dim, Hypothesis h, const CreepLaw& law, Real sigma) {
  const Mesh mesh = bar(dim);
  ElasticityOperator op(mesh, LinearElastic{200e9, 0.3, 7854, h}, pulled(mesh, sigma));
  ContinuumCreepSystem system(op, law);
  std::vector<Real> y, yp;
  system.initial_state(0, y, yp);
  IdaOptions options;
  options.rtol = 1e-7;
  options.atol = 1e-16;
  IdaIntegrator ida(system, options);
  ida.initialize(0, y, yp);
  UniaxialResult r;
  for (Real hours : {1.0, 10.0, 100.0, 500.0}) {
    ida.advance(hours * kHours);
    const Real exact = law.uniaxial_strain(sigma, hours * kHours);
    for (Index c = 0; c < mesh.n_cells(); ++c) {
      const Mat3 e = system.plastic_strain(ida.y(), c);
      r.worst_strain = std::max(r.worst_strain, std::abs(e(0, 0) / exact - 1));
      r.worst_lateral = std::max(r.worst_lateral, std::abs(e(1, 1) / (-0.5 * exact) - 1));
      r.worst_trace = std::max(r.worst_trace, std::abs(e.trace()) / exact);
      const Real ux = (sigma / 200e9 + exact) * mesh.cell_centroid(c).x();
      r.worst_extension = std::max(r.worst_extension, std::abs(ida.y()[dim * c] / ux - 1));
    }
  }
  r.steps = ida.stats().steps;
  return r;
}

}  // namespace

TEST(ContinuumCreepUniaxial, PlaneStressStripFollowsTheClosedForm) {
  // The Table 4.1 law (stiff hardening) and the Coble law of sec. 4.6.2.
  for (auto [law, sigma] : {std::pair{CreepLaw{8.33e-6, 1.8e8, 2, 2, 1e9}, 108e6},
                            std::pair{CreepLaw{2.08e-10, 20, 1, 0.5, 0.7e9}, 150e6}}) {
    const UniaxialResult r = run_uniaxial(2, Hypothesis::PlaneStress, law, sigma);
    std::printf(
        "plane stress, m = %g, %g MPa: eps_p,xx rel. error %.2e, eps_p,yy %.2e, "
        "end displacement %.2e (%ld steps)\n",
        law.m, sigma / 1e6, r.worst_strain, r.worst_lateral, r.worst_extension, r.steps);
    EXPECT_LT(r.worst_strain, 1e-4);
    EXPECT_LT(r.worst_lateral, 1e-4);
    EXPECT_LT(r.worst_extension, 1e-4);
  }
}

TEST(ContinuumCreepUniaxial, ThreeDBarFollowsTheClosedFormAndPreservesVolume) {
  const CreepLaw law{8.33e-6, 1.8e8, 2, 2, 1e9};
  const UniaxialResult r = run_uniaxial(3, Hypothesis::ThreeD, law, 108e6);
  std::printf(
      "3D: eps_p,xx rel. error %.2e, eps_p,yy %.2e, end displacement %.2e, "
      "|tr eps_p|/eps %.2e (%ld steps)\n",
      r.worst_strain, r.worst_lateral, r.worst_extension, r.worst_trace, r.steps);
  EXPECT_LT(r.worst_strain, 1e-4);
  EXPECT_LT(r.worst_lateral, 1e-4);
  EXPECT_LT(r.worst_extension, 1e-4);
  EXPECT_LT(r.worst_trace, 1e-10);
}

// Plane strain: eps_zz = 0 makes sigma_zz = nu sigma_xx at t = 0 and relaxes it as eps_p,zz
// grows, so the flow is not uniaxial, but it stays deviatoric: tr(eps_p) stays at round-off of
// the strains while eps_p,zz itself is a sizeable fraction of eps_p,xx.
TEST(ContinuumCreepUniaxial, PlaneStrainPlasticStrainStaysVolumePreserving) {
  const Mesh mesh = bar(2);
  ElasticityOperator op(mesh, LinearElastic{200e9, 0.3, 7854, Hypothesis::PlaneStrain},
                        pulled(mesh, 108e6));
  ContinuumCreepSystem system(op, CreepLaw{8.33e-6, 1.8e8, 2, 2, 1e9});
  std::vector<Real> y, yp;
  system.initial_state(0, y, yp);
  IdaOptions options;
  options.rtol = 1e-7;
  options.atol = 1e-16;
  IdaIntegrator ida(system, options);
  ida.initialize(0, y, yp);
  ida.advance(500 * kHours);
  Real worst_trace = 0, xx = 0, zz = 0;
  for (Index c = 0; c < mesh.n_cells(); ++c) {
    const Mat3 e = system.plastic_strain(ida.y(), c);
    worst_trace = std::max(worst_trace, std::abs(e.trace()));
    xx = std::max(xx, std::abs(e(0, 0)));
    zz = std::max(zz, std::abs(e(2, 2)));
  }
  std::printf("plane strain, 500 h: eps_p,xx %.4e, eps_p,zz %.4e, max |tr eps_p| %.2e\n", xx, zz,
              worst_trace);
  EXPECT_GT(zz, 0.1 * xx);
  EXPECT_LT(worst_trace, 1e-10 * xx);
}
