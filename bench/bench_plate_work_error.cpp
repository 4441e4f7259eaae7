// bench_plate_work_error: work against error of the time integrators on the undamped
// vibration of the fixed-fixed plate strip of test/regression/test_plate_vibration.cpp (thesis
// sec. 3.6.3): L = 400 um, h = 2 um (L/h = 200), width L/10, E = 200 GPa, nu = 0 (cylindrical
// bending), rho = 7854 kg/m^3, clamped short ends, free long edges, 40 x 4 cells (cubic), at
// rest at t = 0 and then a uniform pressure q = -1 Pa (step load).
//
// Every integrator solves the same semi-discrete system, ReducedInertiaSystem (rotations
// quasi-static; core/reduced_inertia_system.hpp): with rotary inertia the undamped
// thickness-shear branch near 5.5e9 rad/s makes adaptive steps collapse to ~1e-11 s.
//
// The quantity: the centre deflection w(t*) (mean of the cubic reconstructions of the four
// cells touching (L/2, b/2)) at t* = 25 us, the thesis's Table 3.5 instant (1.62 first
// periods; there the strip is about half-way in phase between its lowest point and its
// crossing of the static deflection, so phase and amplitude errors both enter at first
// order), and the largest error over the outputs every t*/50, relative to the largest
// |w_ref| there (independent of where t* falls).
//
// The reference: the system is linear, so w(t) is a modal sum. With the rotations eliminated,
// M_w w'' + K_c w = f,  K_c = K_ww - K_wb K_bb^-1 K_bw (the Schur complement),  and from rest
// under the step load, with M_w^-1 K_c = V diag(lambda) V^-1, c = (V^-1 M_w^-1 f) / lambda:
//   w(t) = V (c (1 - cos(omega t))),  omega = sqrt(lambda).
// Dense and exact to round-off for this size (160 deflection unknowns); checked against the
// static solve (KINSOL) for t -> infinity without the cosines, and its spectrum must be real
// (test/study/test_plate_spectrum.cpp: true for clamped and free edges).
//
// The integrators (IDA, KLU; each timed from the integrator's construction to t*, outputs
// every t*/50):
//   ida         adaptive BDF, max_order 2, rtol 1e-2 ... 1e-8, atol = rtol |w_static|
//   ida_order5  the same with max_order 5 (BDF3-5 are not A-stable; reported as it goes)
//   be, bdf2    IdaOptions::fixed_step dt (the error test never rejects) with max_order 1
//               (backward Euler, the thesis's scheme) and 2 (BDF2; IDA starts at order 1 and
//               raises the order itself: the order at each output is reported).
// Work: residual evaluations (IDA's, including those of its linear solver interface) and wall
// time. A run predicted from the previous one to exceed --cap seconds is skipped; one that
// passes the cap is stopped and reported incomplete. At the end, for each error target, the
// work of each method to reach it (log-log interpolation between the runs that bracket it)
// and the ratios against adaptive IDA.
//
// Output: one JSON object per line on stdout (python/plot_plate_work_error.py plots them);
// progress on stderr.
#include <CLI/CLI.hpp>
#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "bench_support.hpp"
#include "core/reduced_inertia_system.hpp"
#include "mesh/structured_mesh.hpp"
#include "physics/plate/plate_operator.hpp"
#include "solvers/ida_integrator.hpp"
#include "solvers/static_solve.hpp"

using namespace rfmems;
using Json = nlohmann::ordered_json;

namespace {

using namespace rfmems::bench;

constexpr double kLength = 400e-6, kThickness = 2e-6, kE = 200e9, kNu = 0.0, kRho = 7854,
                 kPressure = -1.0;

// Built in place: the operator keeps a reference to the mesh.
struct Strip {
  Strip(int nx, int ny) {
    BoxSpec spec;
    spec.upper = Vec3(kLength, kLength / 10, 0);
    spec.n[0] = nx;
    spec.n[1] = ny;
    mesh = make_structured_mesh(spec);
    std::vector<PlateBoundary> bcs(mesh.patches().size());
    for (std::size_t p = 0; p < bcs.size(); ++p) {
      const std::string& name = mesh.patches()[p].name;
      bcs[p].kind = name == "left" || name == "right" ? PlateBoundary::Kind::Clamped
                                                      : PlateBoundary::Kind::Free;
    }
    op = std::make_unique<PlateOperator>(mesh, PlateSection{kE, kNu, kRho, kThickness}, bcs,
                                         [](const Vec3&, double) { return kPressure; });
    for (Index c = 0; c < mesh.n_cells(); ++c) {
      const Vec3 d = mesh.cell_centroid(c) - centre();
      if (std::abs(d.x()) < 0.6 * kLength / nx && std::abs(d.y()) < 0.6 * kLength / 10 / ny)
        centre_cells.push_back(c);
    }
    if (centre_cells.size() != 4) throw std::runtime_error("nx and ny must be even");
  }
  Strip(const Strip&) = delete;
  Strip& operator=(const Strip&) = delete;

  static Vec3 centre() { return Vec3(kLength / 2, kLength / 20, 0); }
  double centre_deflection(std::span<const double> y) const {
    double w = 0;
    for (Index c : centre_cells) w += op->deflection_at(c, centre(), 0.0, y);
    return w / static_cast<double>(centre_cells.size());
  }

  Mesh mesh;
  std::unique_ptr<PlateOperator> op;
  std::vector<Index> centre_cells;
};

struct ModalReference {
  std::vector<std::complex<double>> tip_c, omega;  // per mode: centre . V_j c_j, sqrt(lambda_j)
  double w_static_modal = 0;
  double max_imag_over_real = 0;  // of lambda: the spectrum should be real
  double min_lambda = 0;
  double rcond_v = 0;
  double seconds = 0;
  double at(double t) const {
    std::complex<double> w = 0;
    for (std::size_t j = 0; j < tip_c.size(); ++j) w += tip_c[j] * (1.0 - std::cos(omega[j] * t));
    return w.real();
  }
};

ModalReference modal_reference(Strip& s) {
  const double t0 = now();
  PlateOperator& op = *s.op;
  const Index n = op.size(), nc = s.mesh.n_cells();
  std::vector<double> zero(n, 0.0), r(n);
  const Eigen::MatrixXd K = dense_stiffness(op);
  op.internal_residual(1.0, zero, r);  // R(t, y) = K y - f
  // Split into deflections (w) and rotations (b).
  std::vector<Index> iw, ib;
  for (Index c = 0; c < nc; ++c) {
    iw.push_back(3 * c);
    ib.push_back(3 * c + 1);
    ib.push_back(3 * c + 2);
  }
  auto block = [&](const std::vector<Index>& rows, const std::vector<Index>& cols) {
    Eigen::MatrixXd B(rows.size(), cols.size());
    for (std::size_t a = 0; a < rows.size(); ++a)
      for (std::size_t b = 0; b < cols.size(); ++b) B(a, b) = K(rows[a], cols[b]);
    return B;
  };
  const Eigen::MatrixXd Kww = block(iw, iw), Kwb = block(iw, ib), Kbw = block(ib, iw),
                        Kbb = block(ib, ib);
  Eigen::VectorXd fw(iw.size()), fb(ib.size());
  for (std::size_t a = 0; a < iw.size(); ++a) fw[a] = -r[iw[a]];
  for (std::size_t a = 0; a < ib.size(); ++a) fb[a] = -r[ib[a]];
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_bb(Kbb);
  const Eigen::MatrixXd Kc = Kww - Kwb * lu_bb.solve(Kbw);
  const Eigen::VectorXd fc = fw - Kwb * lu_bb.solve(fb);  // fb = 0 for a pressure load
  const auto mass = op.mass_diagonal();
  Eigen::MatrixXd A = Kc;
  Eigen::VectorXd b = fc;
  for (Index a = 0; a < nc; ++a) {
    A.row(a) /= mass[iw[a]];
    b[a] /= mass[iw[a]];
  }
  Eigen::EigenSolver<Eigen::MatrixXd> es(A);
  if (es.info() != Eigen::Success) throw std::runtime_error("modal reference: EigenSolver failed");
  const Eigen::VectorXcd lambda = es.eigenvalues();
  const Eigen::MatrixXcd V = es.eigenvectors();
  Eigen::PartialPivLU<Eigen::MatrixXcd> lu(V);
  ModalReference ref;
  ref.rcond_v = lu.rcond();
  const Eigen::VectorXcd g = lu.solve(b.cast<std::complex<double>>());
  // The centre deflection as a linear functional of the deflections (probed: it is linear
  // and the clamped edges' data are zero).
  Eigen::VectorXd centre_row(nc);
  std::vector<double> unit(n, 0.0);
  for (Index a = 0; a < nc; ++a) {
    unit[iw[a]] = 1;
    centre_row[a] = s.centre_deflection(unit);
    unit[iw[a]] = 0;
  }
  const Eigen::VectorXcd centre_mode = V.transpose() * centre_row.cast<std::complex<double>>();
  ref.min_lambda = std::numeric_limits<double>::infinity();
  std::complex<double> w_static = 0;
  for (Index j = 0; j < lambda.size(); ++j) {
    const std::complex<double> c = g[j] / lambda[j];
    ref.tip_c.push_back(centre_mode[j] * c);
    ref.omega.push_back(std::sqrt(lambda[j]));
    w_static += centre_mode[j] * c;
    ref.max_imag_over_real =
        std::max(ref.max_imag_over_real, std::abs(lambda[j].imag()) / std::abs(lambda[j].real()));
    ref.min_lambda = std::min(ref.min_lambda, lambda[j].real());
  }
  ref.w_static_modal = w_static.real();
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

Run integrate(Strip& s, const IdaOptions& options, double t_star, double cap, int outputs) {
  Run run;
  const double t0 = now();
  ReducedInertiaSystem system(*s.op, s.op->rotation_components());
  IdaIntegrator ida(system, options);
  std::vector<double> y0(system.size(), 0.0);
  const std::vector<double> yp0 = system.consistent_derivative(0.0, y0);
  ida.initialize(0.0, y0, yp0);
  const Index n = s.op->size();
  for (int k = 1; k <= outputs; ++k) {
    ida.advance(t_star * k / outputs);
    ++run.orders[ida.stats().last_order];
    run.samples.emplace_back(ida.time(), s.centre_deflection(ida.y().subspan(0, n)));
    if (now() - t0 > cap && k < outputs) {
      run.completed = false;
      break;
    }
  }
  run.t_reached = ida.time();
  run.w = s.centre_deflection(ida.y().subspan(0, n));
  run.seconds = now() - t0;
  run.stats = ida.stats();
  return run;
}

Json describe(const Run& run, const ModalReference& ref, double w_ref) {
  Json j;
  j["completed"] = run.completed;
  j["t_reached"] = run.t_reached;
  j["w_m"] = run.w;
  if (run.completed) {
    j["error"] = std::abs(run.w - w_ref) / std::abs(w_ref);
    j["error_max_over_outputs"] = max_relative_error(run.samples, ref);
  }
  j["wall_s"] = run.seconds;
  add_integrator_stats(j, run.stats);
  j["mean_step_s"] = run.t_reached / std::max(1L, run.stats.steps);
  Json orders = Json::object();
  for (auto [order, count] : run.orders) orders[std::to_string(order)] = count;
  j["order_at_outputs"] = orders;
  return j;
}

// Work to reach `target` along one method's runs: the cheapest run at or below the target,
// and the log-log interpolation between it and the cheaper run before it (in work order).
struct WorkAt {
  double first_run = 0, interpolated = 0;
};
std::optional<WorkAt> work_to_reach(std::vector<std::pair<double, double>> work_error,
                                    double target) {
  std::sort(work_error.begin(), work_error.end());
  for (std::size_t i = 0; i < work_error.size(); ++i) {
    if (!(work_error[i].second <= target)) continue;
    WorkAt w{work_error[i].first, work_error[i].first};
    if (i > 0 && work_error[i - 1].second > target) {
      const auto [w0, e0] = work_error[i - 1];
      const auto [w1, e1] = work_error[i];
      const double s = std::log(target / e0) / std::log(e1 / e0);
      w.interpolated = std::exp(std::log(w0) + s * (std::log(w1) - std::log(w0)));
    }
    return w;
  }
  return std::nullopt;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Work against error of IDA and fixed-step BDF on the plate strip (JSON lines)"};
  int nx = 40, ny = 4;
  double t_star = 25e-6, cap = 60;
  bool quick = false;
  std::vector<double> rtols{1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8};
  std::vector<double> order5_rtols{1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8};
  std::vector<double> dts{2e-7, 1e-7, 5e-8, 2e-8, 1e-8, 5e-9, 2e-9, 1e-9, 5e-10, 2e-10};
  std::vector<double> targets{1e-2, 1e-3};
  std::vector<std::string> methods{"ida", "ida_order5", "be", "bdf2"};
  app.add_option("--nx", nx, "cells along the strip (even)");
  app.add_option("--ny", ny, "cells across the strip (even)");
  app.add_option("--t-star", t_star, "time of the deflection compared [s]");
  app.add_option("--cap", cap, "skip or stop runs longer than this [s]");
  app.add_option("--rtols", rtols, "IDA relative tolerances (max_order 2)");
  app.add_option("--order5-rtols", order5_rtols, "IDA relative tolerances (max_order 5)");
  app.add_option("--dts", dts, "fixed steps for backward Euler and BDF2 [s]");
  app.add_option("--targets", targets, "errors at which the work ratios are reported");
  app.add_option("--methods", methods, "which of ida, ida_order5, be, bdf2 to run");
  app.add_flag("--quick", quick, "smoke run: 20 x 2 cells, few runs, 5 s cap");
  CLI11_PARSE(app, argc, argv);
  if (quick) {
    nx = 20;
    ny = 2;
    cap = 5;
    rtols = {1e-3, 1e-4};
    order5_rtols = {1e-4};
    dts = {2e-8, 1e-8, 5e-9};
  }

  auto wanted = [&](const std::string& m) {
    return std::find(methods.begin(), methods.end(), m) != methods.end();
  };
  Strip strip(nx, ny);
  const Json common{{"bench", "plate_work_error"}, {"nx", nx}, {"ny", ny}, {"t_star", t_star}};
  const double w_static = strip.centre_deflection(solve_static(*strip.op, 1.0).y);

  std::fprintf(stderr, "modal reference (%lld deflection unknowns) ...\n",
               static_cast<long long>(strip.mesh.n_cells()));
  const ModalReference ref = modal_reference(strip);
  const double w_ref = ref.at(t_star);
  {
    double w_max = 0;
    for (int k = 1; k <= 50; ++k) w_max = std::max(w_max, std::abs(ref.at(t_star * k / 50)));
    Json j = common;
    j["variant"] = "reference";
    j["method"] = "modal superposition of the rotation-condensed system (see banner)";
    j["w_ref_m"] = w_ref;
    j["w_static_m"] = w_static;
    j["max_abs_w_ref_over_outputs_m"] = w_max;
    j["modal_static_rel_diff"] = std::abs(ref.w_static_modal / w_static - 1);
    j["max_imag_over_real_lambda"] = ref.max_imag_over_real;
    j["min_lambda"] = ref.min_lambda;
    j["first_frequency_hz"] = [&] {
      double o = std::numeric_limits<double>::infinity();
      for (auto om : ref.omega) o = std::min(o, std::abs(om));
      return o / (2 * M_PI);
    }();
    j["rcond_eigenvectors"] = ref.rcond_v;
    j["wall_s"] = ref.seconds;
    emit(j);
  }
  std::fprintf(stderr, "  w_ref(t*) = %.12e m (static %.6e m), %.2f s\n", w_ref, w_static,
               ref.seconds);

  std::map<std::string, std::vector<Json>> completed;  // method -> described runs
  auto report = [&](const std::string& method, Json params, const Run& run) {
    Json j = common;
    j["variant"] = "run";
    j["method"] = method;
    j.update(params);
    j.update(describe(run, ref, w_ref));
    emit(j);
    if (run.completed) completed[method].push_back(j);
    std::fprintf(stderr, "  %-10s %s: error %.3e, %.2f s, %ld steps, %ld residuals%s\n",
                 method.c_str(), params.dump().c_str(), std::abs(run.w - w_ref) / std::abs(w_ref),
                 run.seconds, run.stats.steps, run.stats.residual_evals,
                 run.completed ? "" : " (stopped at the cap)");
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

  // ---- IDA adaptive ----------------------------------------------------------------------
  for (int max_order : {2, 5}) {
    const std::string method = max_order == 2 ? "ida" : "ida_order5";
    if (!wanted(method)) continue;
    double last_time = 0, ratio = 1;
    bool stopped = false;
    for (double rtol : max_order == 2 ? rtols : order5_rtols) {
      Json params{{"rtol", rtol}, {"atol", rtol * std::abs(w_static)}, {"max_order", max_order}};
      // Work grows geometrically as the tolerance shrinks: extrapolate the last growth.
      const double predicted = last_time * ratio;
      if (stopped || predicted > cap) {
        skip(method, params, stopped ? std::numeric_limits<double>::infinity() : predicted);
        continue;
      }
      IdaOptions o;
      o.rtol = rtol;
      o.atol = rtol * std::abs(w_static);
      o.max_order = max_order;
      o.max_steps = 100000000;
      Run run = integrate(strip, o, t_star, cap, 50);
      report(method, params, run);
      if (last_time > 0) ratio = std::max(1.0, run.seconds / last_time);
      last_time = run.seconds;
      stopped = !run.completed;
    }
  }
  // ---- fixed steps: backward Euler and BDF2 ---------------------------------------------
  for (int order : {1, 2}) {
    const std::string method = order == 1 ? "be" : "bdf2";
    if (!wanted(method)) continue;
    double last_time = 0, last_dt = 0;
    for (double dt : dts) {
      Json params{{"dt", dt}, {"max_order", order}};
      const double predicted = last_dt > 0 ? last_time * last_dt / dt : 0;  // cost ~ 1/dt
      if (predicted > cap) {
        skip(method, params, predicted);
        continue;
      }
      IdaOptions o;
      o.max_order = order;
      o.fixed_step = dt;
      o.max_steps = 100000000;
      Run run = integrate(strip, o, t_star, cap, 50);
      report(method, params, run);
      last_time = run.seconds;
      last_dt = dt;
    }
  }

  // ---- work to reach each target, and ratios against adaptive IDA (order <= 2) ----------
  Json summary = common;
  summary["variant"] = "summary";
  for (const char* measure : {"error", "error_max_over_outputs"}) {
    for (double target : targets) {
      Json t;
      t["error_measure"] = measure;
      t["target"] = target;
      std::map<std::string, std::optional<WorkAt>> evals, walls;
      for (const auto& [method, runs] : completed) {
        std::vector<std::pair<double, double>> by_evals, by_wall;
        for (const Json& r : runs) {
          by_evals.emplace_back(r["residual_evals"].get<double>(), r[measure].get<double>());
          by_wall.emplace_back(r["wall_s"].get<double>(), r[measure].get<double>());
        }
        evals[method] = work_to_reach(by_evals, target);
        walls[method] = work_to_reach(by_wall, target);
        Json m;
        if (evals[method]) {
          m["residual_evals_first_run"] = evals[method]->first_run;
          m["residual_evals_interpolated"] = evals[method]->interpolated;
          m["wall_s_first_run"] = walls[method]->first_run;
          m["wall_s_interpolated"] = walls[method]->interpolated;
        } else {
          m = "not reached";
        }
        t[method] = m;
      }
      if (evals.count("ida") && evals["ida"]) {
        for (const auto& [method, w] : evals) {
          if (method == "ida" || !w) continue;
          t["ratio_to_ida"][method] = {
              {"residual_evals", w->interpolated / evals["ida"]->interpolated},
              {"wall", walls[method]->interpolated / walls["ida"]->interpolated}};
        }
      }
      summary["work_to_reach"].push_back(t);
    }
  }
  emit(summary);
  return 0;
}
