// Second-order kinetic transport (second_order_transport.hpp, deferred correction in the
// operator and the downwind sweep):
//  1. observed order: collisionless transport of a smooth inflow through a skewed, graded
//     mesh. Every ordinate's exact steady solution is constant along c_k,
//       f_k(x) = M_k (1 + A sin(2 pi s_k(x) / L)),  s_k = (x c_y - y c_x) / |c_xy|,
//     imposed on every boundary face (an ExternalFaceValues source); the gas is so rarefied
//     (Kn ~ 1e7) that collisions change f by < 1e-6 of itself. Cell errors (L1 over cells and
//     ordinates) on 3 meshes: order ~1 with first order, ~2 with second order (Venkatakrishnan
//     and unlimited);
//  2. the limiter keeps a discontinuous free-molecular profile (a step inflow, f = M_k on one
//     side of a line, 0.2 M_k on the other) within its bounds: Barth-Jespersen exactly,
//     Venkatakrishnan to its e (<= 1 %), while the unlimited reconstruction overshoots;
//  3. conservation: in a closed specular box the second-order residual of a random state
//     sums to zero mass and energy over the cells (the correction is face by face);
//  4. first order is untouched: a first-order operator's residual equals the default one bit
//     for bit, and the correction is empty.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "mesh/structured_mesh.hpp"
#include "physics/gas/kinetic/downwind_ordering.hpp"
#include "physics/gas/kinetic/equilibrium.hpp"
#include "physics/gas/kinetic/external_face_values.hpp"
#include "physics/gas/kinetic/kinetic_operator.hpp"
#include "physics/gas/kinetic/sequential_solver.hpp"

using namespace rfmems;

namespace {

constexpr Real kT0 = 273.15;
constexpr Real kRho = 1e-12;  // kg/m^3: lambda ~ 1e5 m against a 0.02 m box
constexpr Real kWave = 0.01;  // m, the inflow's wavelength

KineticGas gas() { return KineticGas::argon(CollisionModel::Esbgk); }
VelocityGrid grid() { return VelocityGrid::uniform(6, 6, 6, 3.5 * gas().thermal_speed(kT0)); }

FaceGraph skewed_graph(int n) {
  BoxSpec spec;
  spec.upper = Vec3(0.02, 0.01, 0);
  spec.n[0] = 2 * n;
  spec.n[1] = n;
  spec.grading[1] = 1.3;
  return face_graph_of(make_structured_mesh(spec, [](const Vec3& x) {
    return Vec3(x.x() + 0.2 * x.y(), x.y() + 0.05 * std::sin(300 * x.x()) * x.y(), 0);
  }));
}

// The exact collisionless solution: a smooth wave, or a step across the line s_k = s0.
struct Profile {
  bool step = false;
  std::vector<Real> maxwellian;  // M_k
  Real value(const VelocityGrid& g, Index k, const Vec3& x) const {
    const Vec3& c = g.c[k];
    const Real s = (x.x() * c.y() - x.y() * c.x()) / std::hypot(c.x(), c.y());
    if (step) return maxwellian[k] * (s > 0.002 ? 1.0 : 0.2);
    return maxwellian[k] * (1 + 0.5 * std::sin(2 * M_PI * s / kWave));
  }
};

class ExactFaces final : public ExternalFaceValues {
 public:
  ExactFaces(const FaceGraph& g, const VelocityGrid& grid, const Profile& p)
      : g_(g), grid_(grid), p_(p) {}
  void update(std::span<const Real>, std::span<const Real>) override {}
  void fill(Index face, std::span<const Real>, std::span<Real> out) const override {
    for (Index k = 0; k < grid_.size(); ++k) out[k] = p_.value(grid_, k, g_.face_centroid[face]);
  }

 private:
  const FaceGraph& g_;
  const VelocityGrid& grid_;
  const Profile& p_;
};

Profile profile(bool step) {
  Profile p;
  p.step = step;
  p.maxwellian.resize(grid().size());
  sample_maxwellian(kRho, Vec3::Zero(), kT0, gas(), grid(), p.maxwellian);
  return p;
}

struct Solved {
  std::vector<Real> f;
  int sweeps = 0;
  Real ratio = 1;     // ||r|| / ||r_0|| at exit
  Real l1_error = 0;  // sum V |f - f_exact(x_c)| / sum V |f_exact|, over cells and ordinates
};

// Sweeps (first-order inverse, lagged correction) until ||r|| / ||r_0|| <= 1e-10 (or
// max_sweeps; must_converge: expect convergence before).
Solved solve(const FaceGraph& g, const TransportScheme& scheme, const Profile& p,
             int max_sweeps = 200, bool must_converge = true) {
  const VelocityGrid vg = grid();
  std::vector<KineticBoundary> bcs(g.patch_names.size(), KineticBoundary::external());
  KineticOperator op(g, vg, gas(), bcs);
  ExactFaces faces(g, op.grid(), p);
  op.set_external_face_values(&faces);
  op.set_transport(scheme);
  Solved s;
  op.initialize(s.f = std::vector<Real>(op.size()), [](const Vec3&) {
    return GasState{kRho, Vec3::Zero(), kT0};
  });
  const std::vector<DownwindGroup> groups = downwind_groups(g, op.grid());
  std::vector<Real> r(op.size());
  op.residual(s.f, r);
  const Real r0 = op.global_norm(r);
  while (s.sweeps < max_sweeps) {
    downwind_sweep(op, groups, s.f);
    ++s.sweeps;
    op.residual(s.f, r);
    s.ratio = op.global_norm(r) / r0;
    if (s.ratio <= 1e-10) break;
  }
  if (must_converge) EXPECT_LE(s.ratio, 1e-10);
  const Index N = op.n_ordinates();
  Real err = 0, norm = 0;
  for (Index c = 0; c < g.n_cells(); ++c)
    for (Index k = 0; k < N; ++k) {
      const Real exact = p.value(op.grid(), k, g.cell_centroid[c]);
      err += g.cell_volume[c] * op.grid().w[k] * std::abs(s.f[c * N + k] - exact);
      norm += g.cell_volume[c] * op.grid().w[k] * std::abs(exact);
    }
  s.l1_error = err / norm;
  return s;
}

TransportScheme scheme(TransportOrder order, SlopeLimiter limiter) {
  TransportScheme s;
  s.order = order;
  s.limiter = limiter;
  return s;
}

}  // namespace

TEST(SecondOrderTransport, ObservedOrderOnASkewedMesh) {
  const Profile p = profile(false);
  const int sizes[] = {8, 16, 32};
  struct Case {
    const char* name;
    TransportScheme s;
    Real min_order, max_order;
  };
  const Case cases[] = {
      // First order approaches its order 1 from below on these meshes (0.6, 0.75 measured).
      {"first order", scheme(TransportOrder::FirstOrder, SlopeLimiter::None), 0.6, 1.2},
      // Unlimited: 2.35 and 2.47 measured (the errors fall faster than h^2 on these meshes
      // since the outgoing fluxes of the External boundary faces are reconstructed too).
      {"second order, unlimited", scheme(TransportOrder::SecondOrder, SlopeLimiter::None), 1.8,
       2.7},
      {"second order, Venkatakrishnan",
       scheme(TransportOrder::SecondOrder, SlopeLimiter::Venkatakrishnan), 1.6, 2.4},
  };
  Real finest[3];
  int which = 0;
  for (const Case& c : cases) {
    Real e[3];
    for (int i = 0; i < 3; ++i) {
      const Solved s = solve(skewed_graph(sizes[i]), c.s, p);
      e[i] = s.l1_error;
      std::printf("%s, %d x %d cells: L1 error %.4e, %d sweeps\n", c.name, 2 * sizes[i], sizes[i],
                  e[i], s.sweeps);
    }
    const Real order = std::log2(e[1] / e[2]);
    std::printf("%s: observed order %.3f (coarse pair %.3f)\n", c.name, order,
                std::log2(e[0] / e[1]));
    EXPECT_GE(order, c.min_order) << c.name;
    EXPECT_LE(order, c.max_order) << c.name;
    finest[which++] = e[2];
  }
  // On the finest mesh second order is >= 10x more accurate than first order.
  EXPECT_LE(finest[1], 0.1 * finest[0]);
  EXPECT_LE(finest[2], 0.1 * finest[0]);
}

TEST(SecondOrderTransport, LimiterKeepsAStepWithinItsBounds) {
  const Profile p = profile(true);
  const FaceGraph g = skewed_graph(12);
  const VelocityGrid vg = grid();
  const Index N = vg.size();
  // Largest excursion beyond [0.2 M_k, M_k], relative to M_k.
  auto excursion = [&](const std::vector<Real>& f) {
    Real worst = 0;
    for (Index c = 0; c < g.n_cells(); ++c)
      for (Index k = 0; k < N; ++k) {
        const Real v = f[c * N + k] / p.maxwellian[k];
        worst = std::max({worst, v - 1.0, 0.2 - v});
      }
    return worst;
  };
  // Barth-Jespersen's min() makes the lagged iteration chatter at the step (it stalls near
  // 1e-7): its state after 60 sweeps is judged.
  const Solved sbj =
      solve(g, scheme(TransportOrder::SecondOrder, SlopeLimiter::BarthJespersen), p, 60, false);
  const Solved svk =
      solve(g, scheme(TransportOrder::SecondOrder, SlopeLimiter::Venkatakrishnan), p);
  const Solved snone = solve(g, scheme(TransportOrder::SecondOrder, SlopeLimiter::None), p);
  const Real bj = excursion(sbj.f), vk = excursion(svk.f), none = excursion(snone.f);
  std::printf(
      "excursion beyond the step's bounds / M_k: Barth-Jespersen %.3e (%d sweeps, "
      "ratio %.1e), Venkatakrishnan %.3e (%d), unlimited %.3e (%d)\n",
      bj, sbj.sweeps, sbj.ratio, vk, svk.sweeps, none, snone.sweeps);
  EXPECT_LE(bj, 1e-6);
  EXPECT_LE(vk, 1e-2);
  EXPECT_GE(none, 0.02);  // the test can fail: without a limiter the step overshoots
}

TEST(SecondOrderTransport, CorrectionConservesMassAndEnergyInAClosedBox) {
  BoxSpec spec;
  spec.upper = Vec3(0.02, 0.01, 0);
  spec.n[0] = 6;
  spec.n[1] = 5;
  spec.grading[1] = 1.3;
  const FaceGraph g = face_graph_of(make_structured_mesh(spec));
  std::vector<KineticBoundary> bcs(g.patch_names.size(), KineticBoundary::specular_wall());
  KineticOperator op(g, VelocityGrid::uniform(10, 10, 8, 3.5 * gas().thermal_speed(kT0)), gas(),
                     bcs);
  op.set_transport(scheme(TransportOrder::SecondOrder, SlopeLimiter::Venkatakrishnan));
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> noise(-0.2, 0.2);
  const Index N = op.n_ordinates();
  std::vector<Real> f(op.size()), m(N), r(op.size());
  for (Index c = 0; c < op.n_cells(); ++c) {
    sample_maxwellian(9.28e-6 * (1 + noise(rng)), Vec3(50 * noise(rng), 30 * noise(rng), 0),
                      kT0 * (1 + noise(rng)), op.gas(), op.grid(), m);
    for (Index k = 0; k < N; ++k) f[c * N + k] = m[k] * (1 + noise(rng));
  }
  op.residual(f, r);
  Real mass = 0, energy = 0, mass_scale = 0, energy_scale = 0, correction = 0;
  for (Index c = 0; c < op.n_cells(); ++c)
    for (Index k = 0; k < N; ++k) {
      const Real w = op.grid().w[k], e = 0.5 * op.grid().c[k].squaredNorm();
      mass += w * r[c * N + k];
      energy += w * e * r[c * N + k];
      mass_scale += std::abs(w * r[c * N + k]);
      energy_scale += std::abs(w * e * r[c * N + k]);
      correction += std::abs(w * op.transport_correction(c)[k]);
    }
  EXPECT_GT(correction, 1e-3 * mass_scale);  // the correction is not trivially zero
  EXPECT_LE(std::abs(mass) / mass_scale, 1e-13);
  EXPECT_LE(std::abs(energy) / energy_scale, 1e-13);
}

TEST(SecondOrderTransport, FirstOrderIsUnchanged) {
  const FaceGraph g = skewed_graph(4);
  std::vector<KineticBoundary> bcs(g.patch_names.size(), KineticBoundary::diffuse_wall(kT0));
  KineticOperator a(g, grid(), gas(), bcs), b(g, grid(), gas(), bcs);
  b.set_transport(scheme(TransportOrder::SecondOrder, SlopeLimiter::Venkatakrishnan));
  b.set_transport(TransportScheme{});  // back to first order
  std::mt19937 rng(3);
  std::uniform_real_distribution<Real> noise(0.5, 1.5);
  std::vector<Real> f(a.size()), ra(a.size()), rb(a.size());
  for (Real& x : f) x = 1e-12 * noise(rng);
  a.residual(f, ra);
  b.residual(f, rb);
  EXPECT_TRUE(b.transport_correction(0).empty());
  for (std::size_t i = 0; i < f.size(); ++i) ASSERT_EQ(ra[i], rb[i]);
}
