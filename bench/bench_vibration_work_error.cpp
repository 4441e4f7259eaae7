// bench_vibration_work_error: work against error of the time integrators on the cantilever
// vibration of test/regression/test_cantilever_vibration.cpp (plane stress, L = 2 m,
// h = 0.04 m, E = 200 GPa, nu = 0.31, rho = 7854 kg/m^3, 80 x 8 cells, left end clamped, end
// shear traction -1000 Pa ramped linearly over 0.02 s then held).
//
// The quantity: the tip deflection w(t*) at a fixed time t* (0.453 s by default, 3.7 periods
// of the 8.2 Hz first mode; why this time: see main), mean of u_y over the two cells touching
// (L, 0). Also the largest error over the output times (every t*/50), independent of t*.
//
// The reference: the semi-discrete system is linear, M u'' + K u = s(t) f with s the ramp, so
// its solution is a modal superposition: with M^-1 K = V diag(lambda) V^-1 (dense, complex,
// since the FV K is not symmetric), g = V^-1 M^-1 f, c = g / lambda, omega = sqrt(lambda),
//   q(t) = c (t/T - sin(omega t)/(omega T))                              t <= T
//   q(t) = c (1 - (sin(omega t) - sin(omega (t - T)))/(omega T))        t >  T
// and w = tip . V q. One caveat, measured and reported: K has complex eigenvalues (on
// 80 x 8 cubic: 118 of 1280, all with |omega| > 2.5e5 rad/s, growth rates |Im omega| up to
// ~1e4 1/s; the linear scheme has a few, ~70 1/s), so the undamped semi-discrete system has
// exponentially growing high modes and its exact solution at t* is meaningless. No integrator
// here sees them: BDF1/2 damp |omega| h >> 1 (from BDF2's stability region, it would resolve
// that growth only for h < ~1e-6 s). The reference therefore takes the growing modes
// (|Im omega| t* > 1e-3) quasi-statically, q = c s(t), exactly as a damped integrator does,
// and every other mode exactly; it reports the bound 2 |tip . V_j c_j| / (|omega_j| T) on what
// their dynamic part could be were they stable (the reference's uncertainty), the static limit V c
// against solve_static, and the Richardson extrapolation of the two finest fixed-step BDF2 runs
// (see below) as an independent check. This is more accurate than the references the plan allowed:
// IDA at rtol 1e-10 would take ~2e6 steps (extrapolated from the ~3.4x more steps per decade
// measured up to rtol 1e-6, and at such steps BDF2 would start to resolve the growing modes), and
// BDF2 with Richardson extrapolation is limited by its O(dt^3) remainder at the dt one can afford.
//
// The integrators (each timed from construction to w(t*), output every t*/50 so that a wall
// time cap can be enforced; IDA's steps do not depend on the output times, only its first
// step guess does, identically for all runs):
//   ida          IDA adaptive, BDF orders 1-2 (max_order 2; see the vibration test's banner:
//                BDF3-5 are not A-stable and collapse the step on undamped dynamics), at
//                rtol 1e-3 ... 1e-8, atol = rtol * 1e-4 m (the tip deflection is ~1e-4 m).
//   ida_order5   the same with max_order 5 at one tolerance, to show the step collapse.
//   be, bdf2     fixed step dt (IdaOptions.fixed_step: hmin = hmax = dt, tolerances so large
//                that the error test never rejects) with max_order 1 (backward Euler) and 2
//                (BDF2). IDA still chooses the order itself up to max_order (it starts at
//                order 1 and raises it when its estimates say so), so "bdf2" is "IDA at a fixed
//                step with orders <= 2": the order found at each output time is reported.
//   bdf2_exact   fixed-step BDF2 in the bench's own loop (one BE step, then BDF2), each step
//                solved exactly with KLU: a check of IDA's fixed-step mode, which after its
//                switch to order 2 keeps the order-1 Jacobian and accepts one Newton iteration
//                (see bdf2_own_loop).
// For each: |w - w_ref| / |w_ref|, wall time, steps, residual and Jacobian evaluations. A run
// predicted (from the previous one) to take longer than --cap seconds is skipped; a run that
// passes the cap is stopped and reported incomplete.
//
// Output: one JSON object per line on stdout (python/plot_work_error.py plots them); progress
// on stderr.
#include <CLI/CLI.hpp>
#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench_support.hpp"
#include "core/structural_systems.hpp"
#include "mesh/structured_mesh.hpp"
#include "physics/elasticity/elasticity_operator.hpp"
#include "solvers/ida_integrator.hpp"
#include "solvers/klu_factorization.hpp"
#include "solvers/static_solve.hpp"

using namespace rfmems;
using Json = nlohmann::ordered_json;

namespace {

using namespace rfmems::bench;

constexpr double kLength = 2.0, kHeight = 0.04, kE = 200e9, kNu = 0.31, kRho = 7854,
                 kTraction = -1000.0, kRamp = 0.02;

std::string fmt_cutoff(double c) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0e", c);
  return buf;
}

// Built in place: the operator keeps a reference to the mesh.
struct Cantilever {
  Cantilever(int nx, int ny, int degree) {
    BoxSpec spec;
    spec.lower = Vec3(0, -kHeight / 2, 0);
    spec.upper = Vec3(kLength, kHeight / 2, 0);
    spec.n[0] = nx;
    spec.n[1] = ny;
    mesh = make_structured_mesh(spec);
    std::vector<ElasticityBoundary> bcs(mesh.patches().size());
    for (std::size_t p = 0; p < bcs.size(); ++p) {
      const std::string& name = mesh.patches()[p].name;
      if (name == "left")
        bcs[p] = {ElasticityBoundary::Kind::Fixed, {}};
      else if (name == "right")
        bcs[p] = {ElasticityBoundary::Kind::Traction, [](const Vec3&, double t) {
                    return Vec3(0, kTraction * std::min(t / kRamp, 1.0), 0);
                  }};
      else
        bcs[p] = {ElasticityBoundary::Kind::Traction, {}};
    }
    op = std::make_unique<ElasticityOperator>(
        mesh, LinearElastic{kE, kNu, kRho, Hypothesis::PlaneStress}, bcs, VectorField{}, degree);
    // The tip probe: the cells touching (L, 0) (two when ny is even).
    for (Index c = 0; c < mesh.n_cells(); ++c) {
      const Vec3& x = mesh.cell_centroid(c);
      if (x.x() > kLength - kLength / nx && std::abs(x.y()) < kHeight / ny) tip_cells.push_back(c);
    }
  }
  Cantilever(const Cantilever&) = delete;
  Cantilever& operator=(const Cantilever&) = delete;

  double tip(std::span<const double> u) const {
    double w = 0;
    for (Index c : tip_cells) w += u[2 * c + 1];
    return w / static_cast<double>(tip_cells.size());
  }

  Mesh mesh;
  std::unique_ptr<ElasticityOperator> op;
  std::vector<Index> tip_cells;
};

// Runs predicted within 10 % of the cap are skipped too (the prediction is rough and a run
// stopped at the cap is wasted time).
constexpr double kSafety = 1.1;

// Modes with |Im omega| t* above this grow by more than 0.1 % over the run.
constexpr double kGrowthThreshold = 1e-3;

struct ModalReference {
  double w = 0;               // w(t*)
  double w_static = 0;        // V (g / lambda) at the tip, all modes
  double imag_over_real = 0;  // of w(t*): rounding in the complex arithmetic
  double rcond_v = 0;         // reciprocal condition estimate of the eigenvector matrix
  long n_complex = 0;         // eigenvalues of M^-1 K with a nonzero imaginary part
  double max_growth = 0;      // max |Im omega| [1/s]: growth rate of the worst mode
  long n_filtered = 0;        // growing modes taken quasi-statically
  double min_filtered_omega = std::numeric_limits<double>::infinity();
  double filtered_static = 0;  // sum |their static tip contributions| / |w_static|
  double filtered_bound = 0;   // bound of their dynamic part had they been stable / |w|
  double linearity = 0;        // ||R(t, x) - R(t, 0) - K x|| / ||K x|| for a random x
  double seconds = 0;
  // (cutoff omega, w(t*) with every mode above it quasi-static): how much of w_ref is
  // high-frequency ringing that a damped integrator cannot be expected to reproduce.
  std::vector<std::pair<double, double>> lowpass;

  // The modes' tip contributions tip . V_j c_j, frequencies, and which are taken quasi-statically.
  std::vector<std::complex<double>> tip_c, omega;
  std::vector<bool> growing;
  // w_ref(t) for any t (the modal sum above, at another time).
  double at(double t) const {
    using C = std::complex<double>;
    const double T = kRamp, s = std::min(t / T, 1.0);
    C w = 0;
    for (std::size_t j = 0; j < tip_c.size(); ++j) {
      const C o = omega[j];
      C phi = growing[j] ? C(s)
              : t <= T   ? t / T - std::sin(o * t) / (o * T)
                         : 1.0 - (std::sin(o * t) - std::sin(o * (t - T))) / (o * T);
      w += tip_c[j] * phi;
    }
    return w.real();
  }
};

ModalReference modal_reference(Cantilever& cl, double t_star) {
  double t0 = now();
  ElasticityOperator& op = *cl.op;
  const Index n = op.size();
  std::vector<double> zero(n, 0.0), mass = op.mass_diagonal();
  const Eigen::MatrixXd K = dense_stiffness(op);
  // R(t, u) = K u - s(t) f: f = -R(T, 0) (s(T) = 1).
  std::vector<double> r0(n), r1(n);
  op.internal_residual(kRamp, zero, r0);
  Eigen::VectorXd f = -Eigen::Map<Eigen::VectorXd>(r0.data(), n);

  ModalReference ref;
  {
    Eigen::VectorXd x = Eigen::VectorXd::Random(n) * 1e-4;
    std::vector<double> xs(x.data(), x.data() + n);
    op.internal_residual(kRamp, xs, r1);
    Eigen::VectorXd kx = K * x;
    Eigen::VectorXd d = Eigen::Map<Eigen::VectorXd>(r1.data(), n) + f - kx;
    ref.linearity = d.norm() / kx.norm();
  }

  Eigen::MatrixXd A = K;
  Eigen::VectorXd b = f;
  for (Index i = 0; i < n; ++i) {
    A.row(i) /= mass[i];
    b[i] /= mass[i];
  }
  Eigen::EigenSolver<Eigen::MatrixXd> es(A);
  if (es.info() != Eigen::Success) throw std::runtime_error("modal reference: EigenSolver failed");
  const Eigen::VectorXcd lambda = es.eigenvalues();
  const Eigen::MatrixXcd V = es.eigenvectors();
  Eigen::PartialPivLU<Eigen::MatrixXcd> lu(V);
  ref.rcond_v = lu.rcond();
  const Eigen::VectorXcd g = lu.solve(b.cast<std::complex<double>>());

  using C = std::complex<double>;
  // The tip deflection as a linear functional of u, and of each mode.
  Eigen::VectorXd tip_row = Eigen::VectorXd::Zero(n);
  for (Index c : cl.tip_cells) tip_row[2 * c + 1] = 1.0 / static_cast<double>(cl.tip_cells.size());
  const Eigen::VectorXcd tip_mode = V.transpose() * tip_row.cast<C>();
  const double T = kRamp;
  const double s_star = std::min(t_star / T, 1.0);
  C w = 0, w_static = 0;
  Eigen::VectorXcd q(n);
  const std::vector<double> cutoffs{1e3, 1e4, 1e5, 1e6};
  std::vector<C> w_low(cutoffs.size(), 0.0);
  for (Index j = 0; j < n; ++j) {
    const C omega = std::sqrt(lambda[j]);
    const C c = g[j] / lambda[j];
    w_static += tip_mode[j] * c;
    ref.tip_c.push_back(tip_mode[j] * c);
    ref.omega.push_back(omega);
    ref.growing.push_back(std::abs(omega.imag()) * t_star > kGrowthThreshold);
    if (lambda[j].imag() != 0) ++ref.n_complex;
    ref.max_growth = std::max(ref.max_growth, std::abs(omega.imag()));
    if (std::abs(omega.imag()) * t_star > kGrowthThreshold) {
      // A growing mode: taken quasi-statically (what every damped integrator here does; see
      // the banner). If it were a stable oscillation its dynamic part would be bounded by
      // 2 |c| / (|omega| T): that bound, summed, is the reference's uncertainty.
      q[j] = c * s_star;
      ++ref.n_filtered;
      ref.min_filtered_omega = std::min(ref.min_filtered_omega, std::abs(omega));
      ref.filtered_static += std::abs(tip_mode[j] * c);
      ref.filtered_bound += std::abs(tip_mode[j] * c) * 2 / (std::abs(omega) * T);
    } else {
      q[j] = t_star <= T ? c * (t_star / T - std::sin(omega * t_star) / (omega * T))
                         : c * (1.0 - (std::sin(omega * t_star) - std::sin(omega * (t_star - T))) /
                                          (omega * T));
    }
    w += tip_mode[j] * q[j];
    for (std::size_t k = 0; k < cutoffs.size(); ++k)
      w_low[k] += tip_mode[j] * (std::abs(omega) > cutoffs[k] ? c * s_star : q[j]);
  }
  for (std::size_t k = 0; k < cutoffs.size(); ++k)
    ref.lowpass.emplace_back(cutoffs[k], w_low[k].real());
  ref.w = w.real();
  ref.w_static = w_static.real();
  ref.imag_over_real = std::abs(w.imag()) / std::abs(w.real());
  ref.filtered_static /= std::abs(ref.w_static);
  ref.filtered_bound /= std::abs(ref.w);
  ref.seconds = now() - t0;
  return ref;
}

struct Run {
  bool completed = true;
  double t_reached = 0, w = 0, seconds = 0;
  std::vector<std::pair<double, double>> samples;  // (t, w) at the output times
  IntegratorStats stats;
  std::map<int, int> orders;  // order at each output time -> count
};

Run integrate(Cantilever& cl, const IdaOptions& options, double t_star, double cap,
              int outputs = 50) {
  Run run;
  const double t0 = now();
  FirstOrderSystem system(*cl.op);
  IdaIntegrator ida(system, options);
  std::vector<double> y0(system.size(), 0.0), yp0(system.size(), 0.0);
  ida.initialize(0.0, y0, yp0);
  for (int k = 1; k <= outputs; ++k) {
    ida.advance(t_star * k / outputs);
    ++run.orders[ida.stats().last_order];
    run.samples.emplace_back(ida.time(), cl.tip(ida.y().subspan(0, cl.op->size())));
    if (now() - t0 > cap && k < outputs) {
      run.completed = false;
      break;
    }
  }
  run.t_reached = ida.time();
  run.w = cl.tip(ida.y().subspan(0, cl.op->size()));
  run.seconds = now() - t0;
  run.stats = ida.stats();
  return run;
}

// Fixed-step BDF2 in our own loop, as a check of IDA's fixed-step mode: one backward Euler
// step, then BDF2 at constant h, each step solved exactly. A step sets Y' = c Y + d (c = 1/h
// for BE, 3/(2h) for BDF2; d from the history) in F(t, Y, Y') = 0; F is linear, so one Newton
// step with the exact iteration matrix dF/dY + c dF/dY' (factorised once per c, KLU) from
// any start solves the step equations exactly. IDA's fixed-step mode instead
// keeps the Jacobian it built at order 1 (c = 1/h) after it moves to order 2 (c = 1.5/h; a
// c ratio under 5/3 does not trigger a new setup) and accepts one Newton iteration (its
// tolerances are huge), so its "BDF2" steps are not solved exactly. Requires t* = N h.
Run bdf2_own_loop(Cantilever& cl, double h, double t_star, double cap) {
  Run run;
  const double t0 = now();
  FirstOrderSystem system(*cl.op);
  const Index n = system.size();
  const long steps = std::lround(t_star / h);
  const CsrPattern& pattern = system.jacobian_pattern();
  std::vector<double> y_prev(n, 0.0), y(n, 0.0), yp(n), r(n), values(pattern.nnz());
  auto factorise = [&](double c) {
    std::fill(values.begin(), values.end(), 0.0);
    system.jacobian(0.0, c, y, yp, values);  // constant: the system is linear
    return std::make_unique<KluFactorization>(pattern, values);
  };
  const double c_be = 1 / h, c_bdf2 = 1.5 / h;
  auto lu_be = factorise(c_be), lu_bdf2 = factorise(c_bdf2);
  const long every = std::max(1L, steps / 50);
  for (long k = 1; k <= steps; ++k) {
    const double t = k * h;
    const bool first = k == 1;
    const double c = first ? c_be : c_bdf2;
    // Y' = c Y + d with d from the history; start the Newton step at Y_n.
    std::vector<double> y_new = y;
    for (Index i = 0; i < n; ++i)
      yp[i] = c * y_new[i] - (first ? y[i] / h : (4 * y[i] - y_prev[i]) / (2 * h));
    system.residual(t, y_new, yp, r);
    for (double& x : r) x = -x;
    (first ? lu_be : lu_bdf2)->solve(r);
    for (Index i = 0; i < n; ++i) y_new[i] += r[i];
    y_prev = std::move(y);
    y = std::move(y_new);
    ++run.stats.steps;
    ++run.stats.residual_evals;
    ++run.orders[first ? 1 : 2];
    if (k % every == 0 || k == steps)
      run.samples.emplace_back(t, cl.tip(std::span<const double>(y).subspan(0, cl.op->size())));
    if (now() - t0 > cap && k < steps) {
      run.completed = false;
      break;
    }
  }
  run.stats.jacobian_evals = 2;
  run.stats.newton_iters = run.stats.steps;
  run.stats.last_order = 2;
  run.stats.last_step = h;
  run.t_reached = run.stats.steps * h;
  run.w = cl.tip(std::span<const double>(y).subspan(0, cl.op->size()));
  run.seconds = now() - t0;
  return run;
}

// Errors of one run: at t* (the headline figure), and the largest over the output times
// (every t*/50, relative to the largest |w_ref| there), which sees phase and amplitude errors
// alike wherever t* happens to fall in the oscillation.
Json describe(const Run& run, const ModalReference& ref, double w_static) {
  Json j;
  j["completed"] = run.completed;
  j["t_reached"] = run.t_reached;
  j["w_m"] = run.w;
  if (run.completed) {
    j["error"] = std::abs(run.w - ref.w) / std::abs(ref.w);
    j["error_over_static"] = std::abs(run.w - ref.w) / std::abs(w_static);
    j["error_max_over_outputs"] = max_relative_error(run.samples, ref);
  }
  j["wall_s"] = run.seconds;
  add_integrator_stats(j, run.stats);
  j["mean_step_s"] = run.t_reached / std::max(1L, run.stats.steps);
  j["last_step_s"] = run.stats.last_step;
  Json orders = Json::object();
  for (auto [order, count] : run.orders) orders[std::to_string(order)] = count;
  j["order_at_outputs"] = orders;
  return j;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Work against error of IDA and fixed-step BDF on the cantilever vibration (JSON lines)"};
  int nx = 80, ny = 8, degree = 3;
  // t* = 0.453 s (3.7 periods): on 80 x 8 the tip is there half-way (45 degrees of phase)
  // between its lowest point (0.438 s) and its crossing of the static deflection (0.468 s),
  // so that both phase errors (the dominant BDF error on oscillations) and amplitude errors
  // (backward Euler's damping) enter w(t*) at first order, and |w_ref| ~ 1.7 |w_static| does
  // not inflate relative errors. At 0.5 s, a turning point (w_ref ~ 0.07 w_static), phase
  // errors would be second order and relative errors inflated ~14x; at the crossing,
  // amplitude errors would be second order. error_max_over_outputs does not depend on t*.
  double t_star = 0.453, cap = 60;
  bool quick = false;
  std::vector<double> rtols{1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8};
  std::vector<double> dts{1e-3, 5e-4, 2e-4, 1e-4, 5e-5, 2e-5, 1e-5, 5e-6, 2e-6, 1e-6};
  double order5_rtol = 1e-6;
  std::vector<std::string> methods{"ida", "ida_order5", "be", "bdf2", "bdf2_exact"};
  app.add_option("--nx", nx, "cells along the cantilever");
  app.add_option("--ny", ny, "cells through the thickness");
  app.add_option("--degree", degree, "reconstruction degree (3 cubic, 1 linear)");
  app.add_option("--t-star", t_star, "time of the tip deflection compared [s]");
  app.add_option("--cap", cap, "skip or stop runs longer than this [s]");
  app.add_option("--rtols", rtols, "IDA relative tolerances (max_order 2)");
  app.add_option("--dts", dts, "fixed steps for backward Euler and BDF2 [s]");
  app.add_option("--order5-rtol", order5_rtol, "tolerance of the max_order 5 run (0: skip)");
  app.add_option("--methods", methods, "which of ida, ida_order5, be, bdf2, bdf2_exact to run");
  app.add_flag("--quick", quick, "smoke run: 40 x 4 cells, t* = 0.1 s, few runs");
  CLI11_PARSE(app, argc, argv);
  if (quick) {
    nx = 40;
    ny = 4;
    t_star = 0.1;
    cap = 10;
    rtols = {1e-3, 1e-4, 1e-5};
    dts = {1e-3, 5e-4, 2e-4};
    order5_rtol = 1e-4;
  }

  auto wanted = [&](const std::string& m) {
    return std::find(methods.begin(), methods.end(), m) != methods.end();
  };
  Cantilever cl(nx, ny, degree);
  Json common{{"bench", "vibration_work_error"},
              {"nx", nx},
              {"ny", ny},
              {"degree", degree},
              {"t_star", t_star}};
  const double w_static = cl.tip(solve_static(*cl.op, 1.0).y);

  std::fprintf(stderr, "modal reference (%lld unknowns, dense eigensolver) ...\n",
               static_cast<long long>(cl.op->size()));
  ModalReference ref = modal_reference(cl, t_star);
  {
    Json j = common;
    j["variant"] = "reference";
    j["method"] = "modal superposition; growing modes quasi-static (see banner)";
    j["w_ref_m"] = ref.w;
    j["w_static_m"] = w_static;
    j["modal_static_rel_diff"] = std::abs(ref.w_static / w_static - 1);
    j["imag_over_real"] = ref.imag_over_real;
    j["rcond_eigenvectors"] = ref.rcond_v;
    j["n_modes"] = cl.op->size();
    j["n_complex_eigenvalues"] = ref.n_complex;
    j["max_growth_rate_per_s"] = ref.max_growth;
    j["n_growing_modes_quasi_static"] = ref.n_filtered;
    j["min_omega_growing_rad_s"] = ref.n_filtered ? Json(ref.min_filtered_omega) : Json(nullptr);
    j["growing_static_share"] = ref.filtered_static;
    j["growing_dynamic_bound_rel"] = ref.filtered_bound;
    j["linearity_check"] = ref.linearity;
    Json low = Json::object();
    for (auto [cut, w] : ref.lowpass) low[fmt_cutoff(cut)] = (w - ref.w) / std::abs(ref.w);
    j["rel_change_if_modes_above_omega_quasi_static"] = low;
    j["wall_s"] = ref.seconds;
    emit(j);
  }
  std::fprintf(stderr, "  w_ref = %.12e m (static %.6e m), %.1f s\n", ref.w, w_static, ref.seconds);

  // Unit costs, to read the work counts below: one residual and one Jacobian of the
  // first-order system [y' - v; M v' + R(t, y)] (best of 20 and of 5).
  {
    FirstOrderSystem system(*cl.op);
    const Index n2 = system.size();
    std::vector<double> y(n2, 1e-6), yp(n2, 0.0), r(n2), jac(system.jacobian_pattern().nnz());
    double t_res = 1e300, t_jac = 1e300;
    for (int i = 0; i < 20; ++i) {
      double t1 = now();
      system.residual(0.1, y, yp, r);
      t_res = std::min(t_res, now() - t1);
    }
    for (int i = 0; i < 5; ++i) {
      std::fill(jac.begin(), jac.end(), 0.0);
      double t1 = now();
      system.jacobian(0.1, 1e4, y, yp, jac);
      t_jac = std::min(t_jac, now() - t1);
    }
    Json j = common;
    j["variant"] = "costs";
    j["unknowns_first_order"] = n2;
    j["jacobian_nnz"] = system.jacobian_pattern().nnz();
    j["t_residual_eval_s"] = t_res;
    j["t_jacobian_eval_s"] = t_jac;
    emit(j);
  }

  auto report = [&](const std::string& method, Json params, const Run& run) {
    Json j = common;
    j["variant"] = "run";
    j["method"] = method;
    j.update(params);
    j.update(describe(run, ref, w_static));
    emit(j);
    std::fprintf(stderr, "  %-10s %s: error %.3e, %.2f s, %ld steps%s\n", method.c_str(),
                 params.dump().c_str(), std::abs(run.w - ref.w) / std::abs(ref.w), run.seconds,
                 run.stats.steps, run.completed ? "" : " (stopped at the cap)");
  };
  auto skip = [&](const std::string& method, Json params, double predicted) {
    Json j = common;
    j["variant"] = "skipped";
    j["method"] = method;
    j.update(params);
    j["predicted_wall_s"] = predicted;
    emit(j);
    std::fprintf(stderr, "  %-10s %s: skipped (predicted %.0f s)\n", method.c_str(),
                 params.dump().c_str(), predicted);
  };

  // ---- IDA adaptive, orders <= 2 --------------------------------------------------------
  if (wanted("ida")) {
    double last_time = 0;
    long last_steps = 0, before_steps = 0;
    for (double rtol : rtols) {
      Json params{{"rtol", rtol}, {"atol", rtol * 1e-4}, {"max_order", 2}};
      // Work grows geometrically as the tolerance shrinks: extrapolate the step count from
      // the last two runs (steps, not seconds: the machine's load makes times noisy).
      const double predicted =
          before_steps > 0 ? last_time * static_cast<double>(last_steps) / before_steps : last_time;
      if (predicted * kSafety > cap) {
        skip("ida", params, predicted);
        continue;
      }
      IdaOptions o;
      o.rtol = rtol;
      o.atol = rtol * 1e-4;
      o.max_order = 2;
      o.max_steps = 10000000;
      Run run = integrate(cl, o, t_star, cap);
      report("ida", params, run);
      before_steps = last_steps;
      last_steps = run.stats.steps;
      last_time = run.seconds;
    }
  }
  // ---- IDA adaptive, orders <= 5 (one tolerance) ---------------------------------------
  if (order5_rtol > 0 && wanted("ida_order5")) {
    IdaOptions o;
    o.rtol = order5_rtol;
    o.atol = order5_rtol * 1e-4;
    o.max_order = 5;
    o.max_steps = 10000000;
    // Capped at half the budget: the point is the step size it settles at, not w(t*).
    // Fine outputs so that the cap can stop it (it does not change IDA's steps).
    Run run = integrate(cl, o, t_star, cap / 2, 5000);
    report("ida_order5", Json{{"rtol", o.rtol}, {"atol", o.atol}, {"max_order", 5}}, run);
  }
  // ---- fixed steps: backward Euler and BDF2 --------------------------------------------
  std::map<double, double> bdf2_w;  // completed BDF2 runs: dt -> w
  std::map<double, double> be_w;
  for (int order : {1, 2}) {
    const std::string method = order == 1 ? "be" : "bdf2";
    if (!wanted(method)) continue;
    double last_time = 0, last_dt = 0;
    for (double dt : dts) {
      Json params{{"dt", dt}, {"max_order", order}};
      const double predicted = last_dt > 0 ? last_time * last_dt / dt : 0;  // cost ~ 1/dt
      if (predicted * kSafety > cap) {
        skip(method, params, predicted);
        continue;
      }
      IdaOptions o;
      o.max_order = order;
      o.fixed_step = dt;
      o.max_steps = 10000000;
      Run run = integrate(cl, o, t_star, cap);
      report(method, params, run);
      last_time = run.seconds;
      last_dt = dt;
      if (run.completed) (order == 1 ? be_w : bdf2_w)[dt] = run.w;
    }
  }
  // ---- BDF2, own loop with exact step solves (a check of IDA's fixed-step mode) --------
  if (wanted("bdf2_exact")) {
    double last_time = 0, last_dt = 0;
    for (double dt : dts) {
      Json params{{"dt", dt}, {"max_order", 2}};
      const double predicted = last_dt > 0 ? last_time * last_dt / dt : 0;
      if (predicted * kSafety > cap) {
        skip("bdf2_exact", params, predicted);
        continue;
      }
      if (std::abs(std::lround(t_star / dt) * dt - t_star) > 1e-9 * t_star) {
        skip("bdf2_exact", params, 0);  // t* is not a whole number of steps
        continue;
      }
      Run run = bdf2_own_loop(cl, dt, t_star, cap);
      report("bdf2_exact", params, run);
      last_time = run.seconds;
      last_dt = dt;
    }
  }
  // ---- Richardson check of the reference -------------------------------------------------
  // From the two finest completed runs of each fixed-step method, dt_c = r dt_f:
  //   w_R = (r^p w_f - w_c) / (r^p - 1),   p = the method's order.
  for (int order : {1, 2}) {
    const auto& runs = order == 1 ? be_w : bdf2_w;
    if (runs.size() < 2) continue;
    auto fine = runs.begin(), coarse = std::next(runs.begin());
    const double r = coarse->first / fine->first, rp = std::pow(r, order);
    const double w_rich = (rp * fine->second - coarse->second) / (rp - 1);
    Json j = common;
    j["variant"] = "richardson_check";
    j["method"] = order == 1 ? "be" : "bdf2";
    j["dt_fine"] = fine->first;
    j["dt_coarse"] = coarse->first;
    j["w_fine_m"] = fine->second;
    j["w_richardson_m"] = w_rich;
    j["w_ref_m"] = ref.w;
    j["fine_error"] = std::abs(fine->second - ref.w) / std::abs(ref.w);
    j["richardson_error"] = std::abs(w_rich - ref.w) / std::abs(ref.w);
    // Observed order from three runs if available.
    if (runs.size() >= 3) {
      auto third = std::next(coarse);
      const double e1 = coarse->second - fine->second, e2 = third->second - coarse->second;
      j["observed_order"] = std::log(std::abs(e2 / e1)) / std::log(third->first / coarse->first);
    }
    emit(j);
  }
  return 0;
}
