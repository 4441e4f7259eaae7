// bench_compact_preconditioner: can the plate switch's Jacobian with the linear reconstruction
// (a compact stencil, the thesis's scheme) precondition the one with the cubic reconstruction
// (the scheme solved), as PETSc separates Amat from Pmat? Per mesh: the entries of both
// Jacobians and of their LU factors (KLU), the refactorisation and solve times, and the GMRES
// iterations (solvers/split_preconditioned_gmres.hpp: SPGMR, right-preconditioned, rows weighted
// by their largest entry) to 1e-2, 1e-4 and 1e-8 relative on the cubic Jacobian with the linear
// one's LU as the preconditioner, and with the cubic one's own LU (what round-off in an exact
// factorisation of these ill-conditioned systems leaves GMRES to do).
//
// 1. --section quasi_static: the bordered displacement-control Jacobian at the fold
//    (cases/switch_plate without gas, nx x nx/10; KLU ordered by size, rows equilibrated).
// 2. --section ida: IDA's dF/dy + c_j dF/dy' of the monolithic switch system (plate, parallel
//    plate, Reynolds film; cases/switch_plate) at the state 5 us into a step of 0.9 V_PI, at
//    c_j = 1/h and 10/h of that step (KLU with AMD, as IDA's).
// The right-hand side is A x for a random x in [-1, 1]. On IDA's matrix the row weighting leaves
// GMRES with the cubic Jacobian's own LU far from one iteration (its c_j rows against its
// stiffness rows: 24 at 20 x 2, the iteration cap at 80 x 8), so there only the fill and the
// solve times compare the two; on the bordered static matrix its own LU takes 4-7.
//
// Output: one JSON object per line on stdout.
//   bench_compact_preconditioner [--nx 40 80 160] [--section quasi_static ida]
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <random>

#include "bench_support.hpp"
#include "bench_switch_scene.hpp"
#include "coupling/displacement_control_system.hpp"
#include "coupling/dynamic_pull_in.hpp"
#include "coupling/quasi_static_pull_in.hpp"
#include "coupling/switch_scene.hpp"
#include "coupling/switch_system.hpp"
#include "solvers/klu_factorization.hpp"
#include "solvers/split_preconditioned_gmres.hpp"

using namespace rfmems;
using namespace rfmems::bench;
using json = nlohmann::json;

namespace {

// cases/switch_plate on nx x nx/10 cells with the named reconstruction, with or without gas.
std::unique_ptr<Scene> plate_switch(int nx, bool gas, const std::string& reconstruction) {
  std::vector<std::string> o = {
      "mesh.cells=[" + std::to_string(nx) + "," + std::to_string(nx / 10) + "]",
      "model.reconstruction=" + reconstruction};
  if (!gas) o.push_back("gas.model=none");
  return load_scene(default_cases_dir() + "/switch_plate/case.yaml", o);
}

struct Matrix {
  const CsrPattern& pattern;
  std::vector<Real> values;
};

// Mean CPU seconds of `repeat` calls of f.
template <class F>
double timed(int repeat, F&& f) {
  const double t0 = cpu_now();
  for (int r = 0; r < repeat; ++r) f();
  return (cpu_now() - t0) / repeat;
}

json compare(const Matrix& cubic, const Matrix& linear, KluOrdering ordering, KluSystem system) {
  const Index n = cubic.pattern.n_rows();
  KluFactorization lu_cubic(cubic.pattern, cubic.values, ordering, system);
  KluFactorization lu_linear(linear.pattern, linear.values, ordering, system);
  std::mt19937 rng(1);
  std::uniform_real_distribution<Real> u(-1, 1);
  std::vector<Real> x_exact(n), b(n, 0.0), x(n);
  for (Real& v : x_exact) v = u(rng);
  for (Index i = 0; i < n; ++i)
    for (Index k = cubic.pattern.row_ptr[i]; k < cubic.pattern.row_ptr[i + 1]; ++k)
      b[i] += cubic.values[k] * x_exact[cubic.pattern.col_idx[k]];
  json j{{"unknowns", n},
         {"cubic_matrix_entries", cubic.pattern.nnz()},
         {"linear_matrix_entries", linear.pattern.nnz()},
         {"cubic_lu_entries", lu_cubic.factor_entries()},
         {"linear_lu_entries", lu_linear.factor_entries()},
         {"cubic_refactor_s", timed(3, [&] { lu_cubic.refactor(cubic.values); })},
         {"linear_refactor_s", timed(3, [&] { lu_linear.refactor(linear.values); })},
         {"cubic_solve_s", timed(10,
                                 [&] {
                                   x = b;
                                   lu_cubic.solve(x);
                                 })},
         {"linear_solve_s", timed(10, [&] {
            x = b;
            lu_linear.solve(x);
          })}};
  for (const Real tolerance : {1e-2, 1e-4, 1e-8})
    for (auto [name, lu] :
         {std::pair{"gmres_linear_lu", &lu_linear}, std::pair{"gmres_own_lu", &lu_cubic}}) {
      SplitGmresOptions o;
      o.relative_tolerance = tolerance;
      std::fill(x.begin(), x.end(), 0.0);
      const double t0 = cpu_now();
      const SplitGmresResult r = split_preconditioned_gmres(
          cubic.pattern, cubic.values, [&](std::span<Real> z) { lu->solve(z); }, b, x, o);
      j[name].push_back(json{{"tolerance", tolerance},
                             {"iterations", r.iterations},
                             {"converged", r.converged},
                             {"relative_residual", r.relative_residual},
                             {"cpu_s", cpu_now() - t0}});
    }
  return j;
}

QuasiStaticOptions case_sampling() {
  QuasiStaticOptions o;  // the case's: 40 points to 0.9 g0, the fold to 0.01 V
  o.voltage_tolerance = 0.01;
  return o;
}

void quasi_static(int nx) {
  auto cubic = plate_switch(nx, false, "cubic");
  auto linear = plate_switch(nx, false, "linear");
  ParallelPlateActuation& act = *cubic->scene.actuation;
  const QuasiStaticPullIn fold = trace_pull_in(act, cubic->scene.control, case_sampling());
  const Real k_ref = stiffness_scale(act);
  DisplacementControlSystem sc(act, cubic->scene.control, k_ref);
  DisplacementControlSystem sl(*linear->scene.actuation, linear->scene.control, k_ref);
  sc.set_target(fold.pull_in_displacement);
  sl.set_target(fold.pull_in_displacement);
  const std::vector<Real> zero(sc.size(), 0.0);
  Matrix mc{sc.jacobian_pattern(), std::vector<Real>(sc.jacobian_pattern().nnz())};
  Matrix ml{sl.jacobian_pattern(), std::vector<Real>(sl.jacobian_pattern().nnz())};
  sc.jacobian(0, 0, fold.fold_state, zero, mc.values);
  sl.jacobian(0, 0, fold.fold_state, zero, ml.values);
  json j = compare(mc, ml, KluOrdering::BySize, KluSystem::MixedUnits);
  j["section"] = "quasi_static";
  j["nx"] = nx;
  j["ny"] = nx / 10;
  j["pull_in_voltage"] = fold.pull_in_voltage;
  emit(j);
}

void ida(int nx) {
  auto cubic = plate_switch(nx, true, "cubic");
  auto linear = plate_switch(nx, true, "linear");
  auto dry = plate_switch(nx, false, "cubic");
  const Real v =
      0.9 *
      trace_pull_in(*dry->scene.actuation, dry->scene.control, case_sampling()).pull_in_voltage;
  auto system_cubic = make_switch_system(cubic->scene);
  auto system_linear = make_switch_system(linear->scene);
  DynamicOptions d;  // the case's solver settings
  d.end_time = 5e-6;
  d.ida.rtol = 1e-3;
  d.ida.atol = 1e-4 * cubic->scene.gap;
  d.ida.max_order = 2;
  d.stop_at_turning = false;
  d.contact_gap = 0.02 * cubic->scene.gap;
  const DynamicRun run = run_dynamic(
      *system_cubic, cubic->scene.control, [v](Real) { return v; }, d);
  system_linear->actuation().set_voltage_squared([v](Real) { return v * v; });
  const DynamicState& s = run.final_state;
  for (const Real factor : {1.0, 10.0}) {
    const Real c_j = factor / run.stats.last_step;
    Matrix mc{system_cubic->jacobian_pattern(),
              std::vector<Real>(system_cubic->jacobian_pattern().nnz())};
    Matrix ml{system_linear->jacobian_pattern(),
              std::vector<Real>(system_linear->jacobian_pattern().nnz())};
    system_cubic->jacobian(s.t, c_j, s.y, s.yp, mc.values);
    system_linear->jacobian(s.t, c_j, s.y, s.yp, ml.values);
    json j = compare(mc, ml, KluOrdering::Amd, KluSystem::Uniform);
    j["section"] = "ida";
    j["nx"] = nx;
    j["ny"] = nx / 10;
    j["c_j"] = c_j;
    emit(j);
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"the linear-reconstruction LU as the preconditioner of the cubic plate Jacobian"};
  std::vector<int> nx{40, 80, 160};
  std::vector<std::string> sections{"quasi_static", "ida"};
  app.add_option("--nx", nx, "cells along the switch (nx x nx/10)");
  app.add_option("--section", sections, "quasi_static, ida");
  CLI11_PARSE(app, argc, argv);
  emit(run_header<json>("bench_compact_preconditioner", argc, argv));
  for (const std::string& s : sections)
    for (const int n : nx) {
      if (s == "quasi_static") quasi_static(n);
      if (s == "ida") ida(n);
    }
  return 0;
}
