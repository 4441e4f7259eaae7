// bench_plate_vs_plane: the same fixed-fixed strip solved with the Mindlin-Reissner plate
// (physics/plate) and with plane-stress elasticity (physics/elasticity), statically and after
// a step load, each at the cheapest mesh that reaches a target accuracy: wall times and their
// ratio (the goal: "the plate >= 100x faster at the same deflection accuracy").
//
// The structure: L = 400 um, h = 4 um (L/h = 100), E = 200 GPa, nu = 0.31, rho = 7854 kg/m^3,
// both short ends clamped, uniform pressure p = 1 kPa pushing down (-z for the plate, -y on the
// top face of the plane model), at rest at t = 0 (step load for the transient).
//   plate   the mid-surface strip [0, L] x [0, b] (b = L/10 by default), long edges free,
//           cubic reconstruction; transient: ReducedInertiaSystem (rotations quasi-static).
//           --plate-grading g grades its meshes towards the clamped ends and the free edges
//           (docs/verification.md, "Plate against plane-stress elasticity"); --plate-degree sets
//           the reconstruction degree.
//   plane   the section [0, L] x [-h/2, h/2] in plane stress (sigma out of plane = 0: the
//           strip's interior bends with free anticlastic curvature, M_yy = 0, so its bending
//           stiffness is E h^3/12 per width, the plane-stress value, not D = E h^3/(12(1-nu^2))
//           of plane strain / cylindrical bending); default cubic reconstruction; transient:
//           FirstOrderSystem (full mass).
// The two models are not the same continuum problem when nu != 0: near a clamped end the plate
// cannot curve anticlastically (beta = 0 along the edge), so over a length ~b it is stiffer (its
// stiffness goes to D); that end zone is O(b/L) of the deflection (measured: --width-study).
// The beam theory both approach for b/L -> 0 and h/L -> 0 (Timoshenko, clamped-clamped, per
// unit width): w = p L^4/(384 E I) + p L^2/(8 k G h), I = h^3/12, k = 5/6.
//
// Accuracy is each model's discretisation error: |Q(mesh) - Q_ref| / |Q_ref| with Q_ref the
// Richardson extrapolation of that model's three finest meshes (both directions doubled each
// time; the observed order is reported; --static-reference finest uses the finest mesh's
// value instead, for when the finest meshes are not asymptotic), because the two models converge to
// values that differ by the model difference above (reported too, against the analytic value).
//   static     Q = w(L/2) on the strip's centre line (plate: mean of the cubic reconstructions
//              of the four cells touching (L/2, b/2)); plane: the section mean of u_y at L/2
//              (column means of the four columns around L/2, cubic Lagrange interpolation,
//              O(dx^4), so that the probe adds no O(dx^2) error of its own).
//              KINSOL, exact Jacobian, one Newton step (linear problem).
//   transient  Q = t_peak, the time of the first extremum of that deflection after the step
//              load (IDA root of its velocity, rising), about half the first period. IDA
//              adaptive BDF, max_order 2 (BDF3-5 are not A-stable on undamped dynamics), KLU,
//              rtol swept, atol = rtol |w_static|; the reference is the Richardson value at the
//              tightest rtol.
// For each target error, the cheapest configuration reaching it counts, where "reaching" means
// it and every finer scanned configuration (more cells in both directions, and for transients
// also a tighter rtol) are within the target: a coarse mesh whose error happens to cross zero
// does not count. Times are CPU seconds of this process (clock_gettime(CLOCK_PROCESS_CPUTIME_ID):
// other processes on a shared machine do not count), the minimum over --repeats runs, measured
// in this run; the wall clock of the same runs is reported as wall_total_s. "setup" is mesh
// plus operator construction, "solve" is solve_static or the IDA integration to t_peak
// (integrator construction included).
//
// Output: one JSON object per line on stdout (one per measurement, then the references, the
// chosen configurations and a final summary line with the ratios); progress on stderr.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "bench_support.hpp"
#include "core/error.hpp"
#include "core/reduced_inertia_system.hpp"
#include "core/structural_systems.hpp"
#include "mesh/structured_mesh.hpp"
#include "physics/elasticity/elasticity_operator.hpp"
#include "physics/plate/plate_operator.hpp"
#include "solvers/ida_integrator.hpp"
#include "solvers/static_solve.hpp"

using namespace rfmems;
using Json = nlohmann::ordered_json;

namespace {

using namespace rfmems::bench;

constexpr double kLength = 400e-6, kThickness = 4e-6, kE = 200e9, kNu = 0.31, kRho = 7854,
                 kPressure = 1e3, kShearFactor = 5.0 / 6.0;

// Timoshenko clamped-clamped beam under uniform load, per unit width (downward positive).
double timoshenko_deflection() {
  const double I = std::pow(kThickness, 3) / 12, G = kE / (2 * (1 + kNu));
  return kPressure * std::pow(kLength, 4) / (384 * kE * I) +
         kPressure * kLength * kLength / (8 * kShearFactor * G * kThickness);
}
double euler_bernoulli_deflection() {
  return kPressure * std::pow(kLength, 4) / (384 * kE * std::pow(kThickness, 3) / 12);
}
// First bending period of the Euler-Bernoulli clamped-clamped beam (E, plane stress).
double euler_bernoulli_period() {
  const double beta = 4.730040744862704;
  const double omega =
      beta * beta / (kLength * kLength) * std::sqrt(kE * kThickness * kThickness / 12 / kRho);
  return 2 * M_PI / omega;
}

// One discretised model: its operator, the mid-span deflection as a linear functional of the
// displacement unknowns, and its first-order system for IDA.
class Model {
 public:
  virtual ~Model() = default;
  virtual SecondOrderOperator& op() = 0;
  // Mid-span deflection (negative: downward) from the displacement unknowns y (size n).
  virtual double deflection(std::span<const double> y) const = 0;
  // The first-order system for IDA, its consistent initial state at rest, and the mid-span
  // deflection rate from its state.
  virtual SystemOperator& system() = 0;
  virtual void initial_state(std::vector<double>& y0, std::vector<double>& yp0) = 0;
  virtual double deflection_rate(std::span<const double> Y) const = 0;
  double deflection_from_state(std::span<const double> Y) const {
    return deflection(Y.subspan(0, n_displacements()));
  }
  virtual Index n_displacements() const = 0;
};

// The plate strip, mid-surface [0, L] x [0, b], nx x ny cells (both even: the centre (L/2, b/2)
// is a vertex shared by four cells).
class PlateStrip : public Model {
 public:
  // grading g in [0, 1): cells graded towards the clamped ends (x) and the free edges (y),
  // x = L (xi - g sin(2 pi xi)/(2 pi)), so the end cells are (1 - g) times the uniform size and
  // the middle ones (1 + g) times (g = 0: uniform).
  PlateStrip(int nx, int ny, double width, double grading = 0, int degree = 3) : width_(width) {
    BoxSpec spec;
    spec.upper = Vec3(kLength, width, 0);
    spec.n[0] = nx;
    spec.n[1] = ny;
    auto graded = [grading](double xi) {
      return xi - grading * std::sin(2 * M_PI * xi) / (2 * M_PI);
    };
    mesh_ =
        grading == 0 ? make_structured_mesh(spec) : make_structured_mesh(spec, [&](const Vec3& x) {
          return Vec3(kLength * graded(x.x() / kLength), width * graded(x.y() / width), 0);
        });
    std::vector<PlateBoundary> bcs(mesh_.patches().size());
    for (std::size_t p = 0; p < bcs.size(); ++p) {
      const std::string& name = mesh_.patches()[p].name;
      bcs[p].kind = name == "left" || name == "right" ? PlateBoundary::Kind::Clamped
                                                      : PlateBoundary::Kind::Free;
    }
    op_ = std::make_unique<PlateOperator>(
        mesh_, PlateSection{kE, kNu, kRho, kThickness}, bcs,
        [](const Vec3&, double) { return -kPressure; }, degree);
    const double dx = (1 + grading) * kLength / nx, dy = (1 + grading) * width / ny;
    for (Index c = 0; c < mesh_.n_cells(); ++c) {
      const Vec3 d = mesh_.cell_centroid(c) - centre();
      if (std::abs(d.x()) < 0.6 * dx && std::abs(d.y()) < 0.6 * dy) centre_cells_.push_back(c);
    }
    if (centre_cells_.size() != 4) throw InputError("plate strip: nx and ny must be even");
  }
  SecondOrderOperator& op() override { return *op_; }
  Index n_displacements() const override { return op_->size(); }
  double deflection(std::span<const double> y) const override {
    double w = 0;
    for (Index c : centre_cells_) w += op_->deflection_at(c, centre(), 0.0, y);
    return w / static_cast<double>(centre_cells_.size());
  }
  SystemOperator& system() override {
    if (!system_)
      system_ = std::make_unique<ReducedInertiaSystem>(*op_, op_->rotation_components());
    return *system_;
  }
  void initial_state(std::vector<double>& y0, std::vector<double>& yp0) override {
    y0.assign(system().size(), 0.0);
    yp0 = system_->consistent_derivative(0.0, y0);  // rotations at rest are in equilibrium
  }
  double deflection_rate(std::span<const double> Y) const override {
    // The deflection functional applied to the w velocities (the clamped edges' data are 0).
    scratch_.assign(op_->size(), 0.0);
    for (Index c = 0; c < mesh_.n_cells(); ++c) scratch_[3 * c] = Y[system_->velocity_index(3 * c)];
    return deflection(scratch_);
  }

 private:
  Vec3 centre() const { return Vec3(kLength / 2, width_ / 2, 0); }
  double width_;
  Mesh mesh_;
  std::unique_ptr<PlateOperator> op_;
  std::unique_ptr<ReducedInertiaSystem> system_;
  std::vector<Index> centre_cells_;
  mutable std::vector<double> scratch_;
};

// The plane-stress section [0, L] x [-h/2, h/2], nx x ny cells (nx even).
class PlaneSection : public Model {
 public:
  // grading_x, grading_y in [0, 1): the plate strip's sinusoidal grading, along the span
  // (towards the clamped ends) and through the thickness (towards the faces).
  PlaneSection(int nx, int ny, double grading_x = 0, double grading_y = 0) {
    BoxSpec spec;
    spec.lower = Vec3(0, -kThickness / 2, 0);
    spec.upper = Vec3(kLength, kThickness / 2, 0);
    spec.n[0] = nx;
    spec.n[1] = ny;
    auto graded = [](double xi, double g) { return xi - g * std::sin(2 * M_PI * xi) / (2 * M_PI); };
    mesh_ = grading_x == 0 && grading_y == 0
                ? make_structured_mesh(spec)
                : make_structured_mesh(spec, [&](const Vec3& x) {
                    const double eta = (x.y() + kThickness / 2) / kThickness;
                    return Vec3(kLength * graded(x.x() / kLength, grading_x),
                                kThickness * (graded(eta, grading_y) - 0.5), 0);
                  });
    std::vector<ElasticityBoundary> bcs(mesh_.patches().size());
    for (std::size_t p = 0; p < bcs.size(); ++p) {
      const std::string& name = mesh_.patches()[p].name;
      if (name == "left" || name == "right")
        bcs[p] = {ElasticityBoundary::Kind::Fixed, {}};
      else if (name == "top")
        bcs[p] = {ElasticityBoundary::Kind::Traction,
                  [](const Vec3&, double) { return Vec3(0, -kPressure, 0); }};
      else
        bcs[p] = {ElasticityBoundary::Kind::Traction, {}};
    }
    op_ = std::make_unique<ElasticityOperator>(
        mesh_, LinearElastic{kE, kNu, kRho, Hypothesis::PlaneStress}, bcs);
    if (nx % 2 != 0 || nx < 4) throw InputError("plane section: nx must be even and >= 4");
    // Section mean of u_y (cell-volume weighted, so graded thickness cells count by their
    // share) in the four columns around L/2, then the cubic Lagrange interpolant at L/2 through
    // the columns' x (uniform columns: (-1, 9, 9, -1)/16).
    std::set<double> xs;
    for (Index c = 0; c < mesh_.n_cells(); ++c) xs.insert(mesh_.cell_centroid(c).x());
    std::vector<double> below, above;
    for (double x : xs) (x < kLength / 2 ? below : above).push_back(x);
    if (below.size() < 2 || above.size() < 2)
      throw InputError("plane section: mid-span columns not found");
    const double column_x[4] = {below[below.size() - 2], below.back(), above[0], above[1]};
    double column_weight[4];
    for (int k = 0; k < 4; ++k) {
      column_weight[k] = 1;
      for (int j = 0; j < 4; ++j)
        if (j != k) column_weight[k] *= (kLength / 2 - column_x[j]) / (column_x[k] - column_x[j]);
    }
    double column_volume[4] = {0, 0, 0, 0};
    std::vector<std::pair<Index, int>> members;
    for (Index c = 0; c < mesh_.n_cells(); ++c)
      for (int k = 0; k < 4; ++k)
        if (std::abs(mesh_.cell_centroid(c).x() - column_x[k]) <= 1e-12 * kLength) {
          members.emplace_back(c, k);
          column_volume[k] += mesh_.cell_volume(c);
        }
    for (auto [c, k] : members)
      weights_.emplace_back(2 * c + 1, column_weight[k] * mesh_.cell_volume(c) / column_volume[k]);
    if (static_cast<int>(weights_.size()) != 4 * ny)
      throw InputError("plane section: mid-span columns not found");
  }
  SecondOrderOperator& op() override { return *op_; }
  Index n_displacements() const override { return op_->size(); }
  double deflection(std::span<const double> y) const override {
    double w = 0;
    for (auto [i, a] : weights_) w += a * y[i];
    return w;
  }
  SystemOperator& system() override {
    if (!system_) system_ = std::make_unique<FirstOrderSystem>(*op_);
    return *system_;
  }
  void initial_state(std::vector<double>& y0, std::vector<double>& yp0) override {
    // At rest, with the consistent acceleration M^-1 (-R(0, 0)) (the step load).
    const Index n = op_->size();
    y0.assign(2 * n, 0.0);
    yp0.assign(2 * n, 0.0);
    std::vector<double> r(n);
    op_->internal_residual(0.0, std::span<const double>(y0).subspan(0, n), r);
    const auto m = op_->mass_diagonal();
    for (Index i = 0; i < n; ++i) yp0[n + i] = -r[i] / m[i];
  }
  double deflection_rate(std::span<const double> Y) const override {
    return deflection(Y.subspan(op_->size()));
  }

 private:
  Mesh mesh_;
  std::unique_ptr<ElasticityOperator> op_;
  std::unique_ptr<FirstOrderSystem> system_;
  std::vector<std::pair<Index, double>> weights_;
};

struct MeshSize {
  int nx, ny;
};

struct Config {
  std::string model;
  MeshSize mesh;
  double rtol = 0;  // transient only
};

// --plate-grading (PlateStrip's grading; 0: uniform meshes) and --plate-degree.
double plate_grading = 0;
int plate_degree = 3;
// --plane-grading, --plane-grading-y (PlaneSection's grading; 0: uniform meshes).
double plane_grading = 0, plane_grading_y = 0;

std::unique_ptr<Model> make_model(const std::string& model, MeshSize m, double width) {
  if (model == "plate")
    return std::make_unique<PlateStrip>(m.nx, m.ny, width, plate_grading, plate_degree);
  return std::make_unique<PlaneSection>(m.nx, m.ny, plane_grading, plane_grading_y);
}

struct Measurement {
  Config config;
  Index unknowns = 0;
  double value = 0;  // w(L/2) [m] or t_peak [s]
  double setup_s = std::numeric_limits<double>::infinity();
  double solve_s = std::numeric_limits<double>::infinity();
  double total_s = std::numeric_limits<double>::infinity();
  double wall_s = std::numeric_limits<double>::infinity();  // wall clock of the same run(s)
  int runs = 0;
  Json details;
  double error = 0;  // against the model's reference, set later
};

// One static solve: build, solve (KINSOL), evaluate. Returns the timings of this run.
void static_run(const std::string& model, MeshSize m, double width, Measurement& out) {
  const double w0 = now(), t0 = cpu_now();
  auto md = make_model(model, m, width);
  const double t1 = cpu_now();
  StaticSolution s = solve_static(md->op(), 0.0);
  const double t2 = cpu_now(), w2 = now();
  out.unknowns = md->op().size();
  out.value = md->deflection(s.y);
  out.setup_s = std::min(out.setup_s, t1 - t0);
  out.solve_s = std::min(out.solve_s, t2 - t1);
  out.total_s = std::min(out.total_s, t2 - t0);
  out.wall_s = std::min(out.wall_s, w2 - w0);
  ++out.runs;
  out.details = Json{{"newton_iters", s.stats.newton_iters},
                     {"linear_iters", s.stats.linear_iters},
                     {"nnz", md->op().stiffness_pattern().nnz()},
                     {"residual_evals", s.stats.residual_evals},
                     {"jacobian_evals", s.stats.jacobian_evals}};
}

// One transient: build, integrate with IDA to the first rising root of the deflection rate.
void transient_run(const std::string& model, MeshSize m, double width, double rtol, double w_scale,
                   Measurement& out) {
  const double w0 = now(), t0 = cpu_now();
  auto md = make_model(model, m, width);
  const double t1 = cpu_now();
  SystemOperator& system = md->system();
  IdaOptions o;
  o.rtol = rtol;
  o.atol = rtol * w_scale;
  o.max_order = 2;
  o.max_steps = 10000000;
  IdaIntegrator ida(system, o);
  std::vector<double> y0, yp0;
  md->initial_state(y0, yp0);
  ida.initialize(0.0, y0, yp0);
  ida.set_roots(1, [&](double, std::span<const double> Y, std::span<const double>,
                       std::span<double> g) { g[0] = md->deflection_rate(Y); });
  const double t_max = euler_bernoulli_period();
  double t_peak = std::numeric_limits<double>::quiet_NaN();
  long falling_roots = 0;
  while (ida.time() < t_max) {
    if (ida.advance(t_max) == IdaIntegrator::Status::Root) {
      if (ida.roots_found()[0] > 0) {
        t_peak = ida.time();
        break;
      }
      ++falling_roots;  // a spurious wiggle before the peak: counted and reported
    }
  }
  const double t2 = cpu_now(), w2 = now();
  out.wall_s = std::min(out.wall_s, w2 - w0);
  out.unknowns = system.size();
  out.value = t_peak;
  out.setup_s = std::min(out.setup_s, t1 - t0);
  out.solve_s = std::min(out.solve_s, t2 - t1);
  out.total_s = std::min(out.total_s, t2 - t0);
  ++out.runs;
  const IntegratorStats st = ida.stats();
  out.details = Json{{"w_at_peak_m", md->deflection_from_state(ida.y())},
                     {"falling_roots_before_peak", falling_roots},
                     {"steps", st.steps},
                     {"residual_evals", st.residual_evals},
                     {"jacobian_evals", st.jacobian_evals},
                     {"error_test_fails", st.error_test_fails},
                     {"newton_fails", st.newton_fails},
                     {"last_order", st.last_order}};
}

struct Reference {
  double value = 0, order = 0, finest = 0;
  bool order_assumed = false;
};

// Richardson extrapolation from three values on meshes refined by 2 in both directions.
Reference richardson(double coarse, double medium, double fine, double assumed_order) {
  Reference r;
  r.finest = fine;
  const double ratio = (coarse - medium) / (medium - fine);
  r.order = ratio > 1 ? std::log(ratio) / std::log(2.0) : 0;
  if (!(r.order > 0.5 && r.order < 8)) {
    r.order = assumed_order;  // not in the asymptotic range: say so in the output
    r.order_assumed = true;
  }
  r.value = fine + (fine - medium) / (std::pow(2.0, r.order) - 1);
  return r;
}

Json config_json(const Config& c) {
  Json j{{"model", c.model}, {"nx", c.mesh.nx}, {"ny", c.mesh.ny}};
  if (c.rtol > 0) j["rtol"] = c.rtol;
  return j;
}

// The cheapest measurement reaching `target` that stays within it on every finer mesh (and
// tighter rtol) scanned.
const Measurement* cheapest_reaching(const std::vector<Measurement>& ms, double target) {
  const Measurement* best = nullptr;
  for (const Measurement& a : ms) {
    if (!(a.error <= target)) continue;
    bool stays = true;
    for (const Measurement& b : ms)
      if (b.config.mesh.nx >= a.config.mesh.nx && b.config.mesh.ny >= a.config.mesh.ny &&
          (a.config.rtol == 0 || b.config.rtol <= a.config.rtol) && !(b.error <= target))
        stays = false;
    if (stays && (!best || a.total_s < best->total_s)) best = &a;
  }
  return best;
}

std::vector<MeshSize> grid(const std::vector<int>& nxs, const std::vector<int>& nys) {
  std::vector<MeshSize> g;
  for (int ny : nys)
    for (int nx : nxs) g.push_back({nx, ny});
  return g;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Plate against plane-stress elasticity on a fixed-fixed strip (JSON lines)"};
  double width = kLength / 10;
  int repeats = 3;
  bool quick = false, width_study = true, do_static = true, do_transient = true;
  std::string static_reference = "richardson";
  double long_run = 2.0;  // static runs longer than this are timed once
  std::vector<double> targets{5e-3, 1e-3};
  // Static scans: full grids; the reference uses the finest diagonal (nx, ny doubled together).
  std::vector<int> plate_nx{20, 40, 80, 160, 320}, plate_ny{2, 4, 8, 16, 32};
  std::vector<int> plane_nx{40, 80, 160, 320}, plane_ny{4, 8, 16, 32, 64};
  // Transient scans: the diagonal families, rtols.
  // The plane model's error is set by the cells through the thickness (nx = 80 is enough for
  // 0.01 % statically), and its transient cost by the smallest cell: refine ny only.
  std::vector<int> plate_tr_nx{20, 40, 80}, plate_tr_ny{2, 4, 8};
  std::vector<int> plane_tr_nx{80, 80, 80}, plane_tr_ny{4, 8, 16};
  std::vector<double> plate_rtols{1e-3, 1e-4}, plane_rtols{1e-3, 1e-4};
  double cap = 120;  // transient runs predicted to take longer are skipped
  app.add_option("--width", width, "plate strip width b [m] (default L/10)");
  app.add_option("--plate-grading", plate_grading,
                 "plate meshes graded towards the clamped ends and the free edges: end cells "
                 "(1 - g) times the uniform size (0: uniform)")
      ->check(CLI::Range(0.0, 0.95));
  app.add_option("--plane-grading", plane_grading,
                 "plane meshes graded along the span towards the clamped ends, as the plate's "
                 "(0: uniform)")
      ->check(CLI::Range(0.0, 0.95));
  app.add_option("--plane-grading-y", plane_grading_y,
                 "plane meshes graded through the thickness towards the faces (0: uniform)")
      ->check(CLI::Range(0.0, 0.95));
  app.add_option("--plate-degree", plate_degree,
                 "plate reconstruction degree: 1 (linear, the thesis's), 2, 3 (cubic, default)")
      ->check(CLI::Range(1, 3));
  app.add_option("--repeats", repeats, "timed runs per configuration (the minimum is kept)");
  app.add_option("--targets", targets, "target relative errors");
  app.add_option("--plate-nx", plate_nx, "static plate meshes: cells along L (even)");
  app.add_option("--plate-ny", plate_ny, "static plate meshes: cells across b (even)");
  app.add_option("--plane-nx", plane_nx, "static plane meshes: cells along L (even)");
  app.add_option("--plane-ny", plane_ny, "static plane meshes: cells through h");
  app.add_option("--plate-tr-nx", plate_tr_nx, "transient plate diagonal family: nx");
  app.add_option("--plate-tr-ny", plate_tr_ny, "transient plate diagonal family: ny");
  app.add_option("--plane-tr-nx", plane_tr_nx, "transient plane diagonal family: nx");
  app.add_option("--plane-tr-ny", plane_tr_ny, "transient plane diagonal family: ny");
  app.add_option("--plate-rtols", plate_rtols, "IDA relative tolerances, plate (transient)");
  app.add_option("--plane-rtols", plane_rtols, "IDA relative tolerances, plane (transient)");
  app.add_option("--cap", cap, "skip transient runs predicted to take longer [s]");
  app.add_option("--static-reference", static_reference,
                 "static reference of each model: richardson (three finest diagonal meshes) or "
                 "finest (the finest mesh's value)")
      ->check(CLI::IsMember({"richardson", "finest"}));
  app.add_option("--width-study", width_study, "plate deflection against b (model difference)");
  app.add_option("--static", do_static, "run the static comparison");
  app.add_option("--transient", do_transient, "run the transient comparison");
  app.add_flag("--quick", quick, "smoke run: small grids, one repeat (a few seconds)");
  CLI11_PARSE(app, argc, argv);
  if (quick) {
    repeats = 1;
    plate_nx = {20, 40, 80};
    plate_ny = {2, 4, 8};
    plane_nx = {40, 80, 160};
    plane_ny = {4, 8, 16};
    plate_tr_nx = {10, 20, 40};
    plate_tr_ny = {2, 2, 4};
    plane_tr_nx = {20, 40, 60};  // not a refinement family: a smoke run only
    plane_tr_ny = {4, 4, 4};
    plate_rtols = {1e-3};
    plane_rtols = {1e-3};
    width_study = false;
  }
  if (plate_tr_nx.size() != plate_tr_ny.size() || plane_tr_nx.size() != plane_tr_ny.size() ||
      plate_tr_nx.size() < 3 || plane_tr_nx.size() < 3 || plate_nx.size() < 3 ||
      plate_ny.size() < 3 || plane_nx.size() < 3 || plane_ny.size() < 3) {
    std::cerr << "need at least three meshes per family, and nx/ny lists of equal length for "
                 "the transient families\n";
    return 2;
  }

  const Json common{{"bench", "plate_vs_plane"},
                    {"L_m", kLength},
                    {"h_m", kThickness},
                    {"b_m", width},
                    {"E_Pa", kE},
                    {"nu", kNu},
                    {"rho", kRho},
                    {"p_Pa", kPressure}};
  const double w_timoshenko = -timoshenko_deflection(), w_eb = -euler_bernoulli_deflection();
  {
    Json j = common;
    j["variant"] = "theory";
    j["w_euler_bernoulli_m"] = w_eb;
    j["w_timoshenko_m"] = w_timoshenko;
    j["w_euler_bernoulli_plane_strain_m"] = w_eb * (1 - kNu * kNu);
    j["period_euler_bernoulli_s"] = euler_bernoulli_period();
    emit(j);
  }

  Json summary = common;
  summary["variant"] = "summary";
  const std::vector<std::string> models{"plate", "plane"};

  auto report = [&](const std::string& analysis, const Measurement& m) {
    Json j = common;
    j["variant"] = "measurement";
    j["analysis"] = analysis;
    j.update(config_json(m.config));
    j["unknowns"] = m.unknowns;
    j[analysis == "static" ? "w_m" : "t_peak_s"] = m.value;
    j["setup_s"] = m.setup_s;
    j["solve_s"] = m.solve_s;
    j["total_s"] = m.total_s;
    j["wall_total_s"] = m.wall_s;
    j["timed_runs"] = m.runs;
    j.update(m.details);
    emit(j);
  };

  // For each analysis, the per-model references, the errors, and the chosen configurations.
  auto compare = [&](const std::string& analysis, std::vector<Measurement>& plate,
                     std::vector<Measurement>& plane, const Reference& ref_plate,
                     const Reference& ref_plane) {
    Json s;
    for (const std::string& model : models) {
      auto& ms = model == "plate" ? plate : plane;
      const Reference& ref = model == "plate" ? ref_plate : ref_plane;
      for (Measurement& m : ms) m.error = std::abs(m.value - ref.value) / std::abs(ref.value);
      Json j = common;
      j["variant"] = "reference";
      j["analysis"] = analysis;
      j["model"] = model;
      j["value"] = ref.value;
      j["kind"] = analysis == "static" ? static_reference : "richardson";
      j["richardson_order"] = ref.order;
      j["order_assumed"] = ref.order_assumed;
      j["finest_vs_reference"] = std::abs(ref.finest / ref.value - 1);
      if (analysis == "static") {
        j["vs_timoshenko"] = ref.value / w_timoshenko - 1;
        j["vs_euler_bernoulli"] = ref.value / w_eb - 1;
      } else {
        j["vs_half_euler_bernoulli_period"] = ref.value / (euler_bernoulli_period() / 2) - 1;
      }
      emit(j);
      for (const Measurement& m : ms) {
        Json e = common;
        e["variant"] = "error";
        e["analysis"] = analysis;
        e.update(config_json(m.config));
        e["error"] = m.error;
        e["total_s"] = m.total_s;
        emit(e);
      }
    }
    s["plate_vs_plane_reference"] = ref_plate.value / ref_plane.value - 1;
    for (double target : targets) {
      const Measurement* a = cheapest_reaching(plate, target);
      const Measurement* b = cheapest_reaching(plane, target);
      Json j = common;
      j["variant"] = "choice";
      j["analysis"] = analysis;
      j["target"] = target;
      for (auto [name, m] : {std::pair{"plate", a}, std::pair{"plane", b}}) {
        if (!m) {
          j[name] = nullptr;
          continue;
        }
        Json c = config_json(m->config);
        c["error"] = m->error;
        c["unknowns"] = m->unknowns;
        c["setup_s"] = m->setup_s;
        c["solve_s"] = m->solve_s;
        c["total_s"] = m->total_s;
        j[name] = c;
      }
      if (a && b) {
        j["ratio_total"] = b->total_s / a->total_s;
        j["ratio_solve"] = b->solve_s / a->solve_s;
      }
      emit(j);
      Json t;
      t["target"] = target;
      t["plate"] = a ? config_json(a->config) : Json(nullptr);
      t["plane"] = b ? config_json(b->config) : Json(nullptr);
      if (a && b) {
        t["plate_total_s"] = a->total_s;
        t["plane_total_s"] = b->total_s;
        t["ratio_total"] = b->total_s / a->total_s;
        t["ratio_solve"] = b->solve_s / a->solve_s;
      }
      s["targets"].push_back(t);
    }
    summary[analysis] = s;
  };

  // ---- static --------------------------------------------------------------------------
  double w_scale = std::abs(w_timoshenko);
  if (do_static) {
    std::vector<Measurement> by_model[2];
    Reference refs[2];
    for (int k = 0; k < 2; ++k) {
      const std::string& model = models[k];
      const auto g = k == 0 ? grid(plate_nx, plate_ny) : grid(plane_nx, plane_ny);
      for (MeshSize m : g) {
        Measurement meas;
        meas.config = {model, m};
        static_run(model, m, width, meas);
        for (int r = 1; r < repeats && meas.total_s < long_run; ++r)
          static_run(model, m, width, meas);
        report("static", meas);
        std::fprintf(stderr, "static %-5s %4d x %3d: w = %.9e m, %.4f s\n", model.c_str(), m.nx,
                     m.ny, meas.value, meas.total_s);
        by_model[k].push_back(meas);
      }
      // The three finest diagonal meshes (the last three nx with the last three ny).
      const auto& nxs = k == 0 ? plate_nx : plane_nx;
      const auto& nys = k == 0 ? plate_ny : plane_ny;
      auto value_at = [&](int nx, int ny) {
        for (const Measurement& m : by_model[k])
          if (m.config.mesh.nx == nx && m.config.mesh.ny == ny) return m.value;
        return std::numeric_limits<double>::quiet_NaN();
      };
      const std::size_t a = nxs.size(), b = nys.size();
      refs[k] = richardson(value_at(nxs[a - 3], nys[b - 3]), value_at(nxs[a - 2], nys[b - 2]),
                           value_at(nxs[a - 1], nys[b - 1]), 2.0);
      // Where the finest meshes are not in the asymptotic range (the plane model's, measured:
      // observed order ~1, growing increments in nx at ny = 64), the finest value instead.
      if (static_reference == "finest") refs[k].value = refs[k].finest;
    }
    compare("static", by_model[0], by_model[1], refs[0], refs[1]);
    w_scale = std::abs(refs[1].value);
  }

  // ---- plate deflection against the width (the model difference) ----------------------
  if (width_study) {
    for (double fraction : {10.0, 20.0, 40.0, 80.0}) {
      const double b = kLength / fraction;
      // Cells about square, and refined twice, for a Richardson value per width.
      std::vector<double> w;
      std::vector<MeshSize> meshes;
      for (int level = 0; level < 3; ++level) {
        const int ny = 4 << level;
        const int nx = std::max(40 << level, static_cast<int>(std::lround(fraction * ny / 4)) * 2);
        meshes.push_back({nx, ny});
        Measurement m;
        static_run("plate", {nx, ny}, b, m);
        w.push_back(m.value);
      }
      const Reference r = richardson(w[0], w[1], w[2], 2.0);
      Json j = common;
      j["variant"] = "width_study";
      j["b_m"] = b;
      j["b_over_L"] = 1 / fraction;
      j["meshes"] = Json::array();
      for (std::size_t i = 0; i < meshes.size(); ++i)
        j["meshes"].push_back({{"nx", meshes[i].nx}, {"ny", meshes[i].ny}, {"w_m", w[i]}});
      j["w_richardson_m"] = r.value;
      j["richardson_order"] = r.order;
      j["order_assumed"] = r.order_assumed;
      j["vs_timoshenko"] = r.value / w_timoshenko - 1;
      emit(j);
      std::fprintf(stderr, "width b = L/%.0f: w = %.9e m (%+.3f %% vs Timoshenko)\n", fraction,
                   r.value, 100 * (r.value / w_timoshenko - 1));
    }
  }

  // ---- transient -----------------------------------------------------------------------
  if (do_transient) {
    std::vector<Measurement> by_model[2];
    Reference refs[2];
    for (int k = 0; k < 2; ++k) {
      const std::string& model = models[k];
      const auto& nxs = k == 0 ? plate_tr_nx : plane_tr_nx;
      const auto& nys = k == 0 ? plate_tr_ny : plane_tr_ny;
      auto rtols = k == 0 ? plate_rtols : plane_rtols;
      std::sort(rtols.rbegin(), rtols.rend());  // loosest first: predictions need them
      std::map<std::pair<std::size_t, double>, double> seconds;  // (mesh, rtol) -> wall
      std::set<std::pair<std::size_t, double>> skipped;
      for (std::size_t r = 0; r < rtols.size(); ++r)
        for (std::size_t i = 0; i < nxs.size(); ++i) {
          const double rtol = rtols[r];
          const MeshSize m{nxs[i], nys[i]};
          // Predicted from the same mesh at the previous rtol, times the growth measured on
          // the coarser mesh between the two rtols (or from the coarser mesh at this rtol,
          // times the growth between the two meshes at the previous rtol).
          // A run whose coarser mesh was skipped at this rtol is skipped too.
          double predicted = 0;
          if (i > 0 && skipped.count({i - 1, rtol}))
            predicted = std::numeric_limits<double>::infinity();
          else if (r > 0 && i > 0 && seconds.count({i, rtols[r - 1]}) &&
                   seconds.count({i - 1, rtol}))
            predicted = seconds[{i, rtols[r - 1]}] * seconds[{i - 1, rtol}] /
                        seconds[{i - 1, rtols[r - 1]}];
          else if (i > 1 && seconds.count({i - 1, rtol}) && seconds.count({i - 2, rtol}))
            predicted = seconds[{i - 1, rtol}] * seconds[{i - 1, rtol}] / seconds[{i - 2, rtol}];
          if (predicted > cap) {
            skipped.insert({i, rtol});
            Json j = common;
            j["variant"] = "skipped";
            j["analysis"] = "transient";
            j.update(config_json({model, m, rtol}));
            j["predicted_s"] = predicted;
            emit(j);
            std::fprintf(stderr, "transient %-5s %4d x %3d rtol %.0e: skipped (predicted %.0f s)\n",
                         model.c_str(), m.nx, m.ny, rtol, predicted);
            continue;
          }
          Measurement meas;
          meas.config = {model, m, rtol};
          transient_run(model, m, width, rtol, w_scale, meas);
          for (int rep = 1; rep < repeats && meas.total_s < long_run; ++rep)
            transient_run(model, m, width, rtol, w_scale, meas);
          seconds[{i, rtol}] = meas.total_s;
          report("transient", meas);
          std::fprintf(stderr, "transient %-5s %4d x %3d rtol %.0e: t_peak = %.9e s, %.4f s\n",
                       model.c_str(), m.nx, m.ny, rtol, meas.value, meas.total_s);
          by_model[k].push_back(meas);
        }
      // Reference: the three finest meshes at the tightest rtol at which all three ran.
      std::optional<double> ref_rtol;
      for (double rtol : rtols) {
        std::vector<double> v(nxs.size(), std::numeric_limits<double>::quiet_NaN());
        for (const Measurement& m : by_model[k])
          for (std::size_t i = 0; i < nxs.size(); ++i)
            if (m.config.rtol == rtol && m.config.mesh.nx == nxs[i] && m.config.mesh.ny == nys[i])
              v[i] = m.value;
        const std::size_t n = v.size();
        if (std::isnan(v[n - 3]) || std::isnan(v[n - 2]) || std::isnan(v[n - 1])) continue;
        refs[k] = richardson(v[n - 3], v[n - 2], v[n - 1], 2.0);
        ref_rtol = rtol;
      }
      if (!ref_rtol) {
        std::fprintf(stderr, "transient %s: no rtol with the three finest meshes\n", model.c_str());
        return 1;
      }
      // How much the values move from the reference's rtol to the loosest: the time part of
      // the reference's own error is below the change to the next tighter rtol, reported
      // where both ran.
      Json j = common;
      j["variant"] = "rtol_effect";
      j["model"] = model;
      j["reference_rtol"] = *ref_rtol;
      j["changes"] = Json::array();
      for (const Measurement& a : by_model[k])
        for (const Measurement& b : by_model[k])
          if (a.config.mesh.nx == b.config.mesh.nx && a.config.mesh.ny == b.config.mesh.ny &&
              b.config.rtol < a.config.rtol &&
              b.config.rtol * 10.5 > a.config.rtol)  // consecutive decades
            j["changes"].push_back({{"nx", a.config.mesh.nx},
                                    {"ny", a.config.mesh.ny},
                                    {"rtol", a.config.rtol},
                                    {"tighter_rtol", b.config.rtol},
                                    {"rel_change", std::abs(a.value / b.value - 1)}});
      emit(j);
    }
    compare("transient", by_model[0], by_model[1], refs[0], refs[1]);
  }
  emit(summary);
  return 0;
}
