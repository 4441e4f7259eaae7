#include "physics/creep/continuum_plate_comparison.hpp"

#include <chrono>
#include <ctime>

#include "mesh/structured_mesh.hpp"
#include "physics/creep/continuum_creep_system.hpp"

namespace rfmems {

namespace {

using Clock = std::chrono::steady_clock;

// The process's CPU time [s].
double cpu_now() { return std::clock() / static_cast<double>(CLOCKS_PER_SEC); }

Index nearest_cell(const Mesh& mesh, const Vec3& x) {
  Index best = 0;
  Real distance = 1e300;
  for (Index c = 0; c < mesh.n_cells(); ++c) {
    const Real d = (mesh.cell_centroid(c) - x).norm();
    if (d < distance) distance = d, best = c;
  }
  return best;
}

// Runs IDA from the system's initial state; deflection(state) is the centre deflection.
template <class System, class Deflection>
CreepRunResult integrate(System& system, const IdaOptions& options, Real end_time,
                         Clock::time_point start, double cpu_start, Deflection&& deflection) {
  CreepRunResult r;
  std::vector<Real> y, yp;
  system.initial_state(0, y, yp);
  r.w_elastic = deflection(std::span<const Real>(y));
  r.elastic_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  r.elastic_cpu_seconds = cpu_now() - cpu_start;
  IdaIntegrator ida(system, options);
  ida.initialize(0, y, yp);
  ida.advance(end_time);
  r.w_plastic = deflection(ida.y()) - r.w_elastic;
  r.unknowns = system.size();
  r.stats = ida.stats();
  r.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  r.cpu_seconds = cpu_now() - cpu_start;
  return r;
}

}  // namespace

std::unique_ptr<FixedFixedCreepPlate> make_fixed_fixed_creep_plate(
    const FixedFixedCreepProblem& problem, int nx, int ny, int thickness_intervals) {
  auto p = std::make_unique<FixedFixedCreepPlate>();
  BoxSpec spec;
  spec.upper = Vec3(problem.length, problem.width, 0);
  spec.n[0] = nx;
  spec.n[1] = ny;
  p->mesh = make_structured_mesh(spec);
  PlateSection section;
  section.E = problem.E;
  section.nu = problem.nu;
  section.rho = problem.rho;
  section.thickness = problem.thickness();
  std::vector<PlateBoundary> bcs(p->mesh.patches().size());
  for (std::size_t k = 0; k < bcs.size(); ++k) {
    const std::string& name = p->mesh.patches()[k].name;
    bcs[k].kind = (name == "left" || name == "right") ? PlateBoundary::Kind::Clamped
                                                      : PlateBoundary::Kind::Free;
  }
  const Real q = problem.load;
  p->op =
      std::make_unique<PlateOperator>(p->mesh, section, bcs, [q](const Vec3&, Real) { return -q; });
  p->system = std::make_unique<PlateCreepSystem>(*p->op, problem.law, thickness_intervals,
                                                 problem.plate_shear_creep);
  p->centre = nearest_cell(p->mesh, Vec3(problem.length / 2, problem.width / 2, 0));
  return p;
}

CreepRunResult run_plate_creep(const FixedFixedCreepProblem& problem, int nx, int ny,
                               int thickness_intervals, const IdaOptions& options, Real end_time) {
  const auto start = Clock::now();
  const double cpu_start = cpu_now();
  const auto plate = make_fixed_fixed_creep_plate(problem, nx, ny, thickness_intervals);
  const Index centre = plate->centre;
  IdaOptions o = options;
  if (problem.plate_shear_creep) o.linear_solver = IdaOptions::LinearSolver::Direct;  // no Schur
  return integrate(*plate->system, o, end_time, start, cpu_start,
                   [centre](std::span<const Real> y) { return y[3 * centre]; });
}

ContinuumStrip make_continuum_strip(const FixedFixedCreepProblem& problem, int nx, int nz,
                                    int width_cells) {
  const bool three_d = width_cells > 0;
  BoxSpec spec;
  spec.dim = three_d ? 3 : 2;
  const bool half = problem.continuum_half_length;
  spec.upper = Vec3(half ? problem.length / 2 : problem.length, problem.thickness(),
                    three_d ? problem.width : 0);
  spec.n[0] = nx;
  spec.n[1] = nz;
  if (three_d) spec.n[2] = width_cells;
  ContinuumStrip strip{make_structured_mesh(spec),
                       {},
                       LinearElastic{problem.E, problem.nu, problem.rho,
                                     three_d ? Hypothesis::ThreeD : Hypothesis::PlaneStress}};
  strip.boundaries.resize(strip.mesh.patches().size());
  const Real q = problem.load;
  for (std::size_t k = 0; k < strip.boundaries.size(); ++k) {
    const std::string& name = strip.mesh.patches()[k].name;
    ElasticityBoundary& bc = strip.boundaries[k];
    if (name == "left") bc.kind = ElasticityBoundary::Kind::Fixed;
    if (name == "right")
      bc.kind = half ? ElasticityBoundary::Kind::Symmetry : ElasticityBoundary::Kind::Fixed;
    if (name == "top") bc.value = [q](const Vec3&, Real) { return Vec3(0, -q, 0); };
  }
  strip.centre = Vec3(problem.length / 2, problem.thickness() / 2, three_d ? problem.width / 2 : 0);
  strip.centre_cell = nearest_cell(strip.mesh, strip.centre);
  return strip;
}

ContinuumStripStatics::ContinuumStripStatics(const ContinuumStrip& strip)
    : op(strip.mesh, strip.material, strip.boundaries, {}, 0),
      compact(strip.mesh, strip.material, strip.boundaries, {}, 1),
      load(op.size()),
      stiffness(op.stiffness_pattern().nnz()),
      compact_stiffness(compact.stiffness_pattern().nnz()) {
  const std::vector<Real> zero(op.size(), 0.0);
  op.internal_residual(0, zero, load);
  for (Real& x : load) x = -x;
  op.stiffness(0, zero, stiffness);
  compact.stiffness(0, zero, compact_stiffness);
}

CreepRunResult run_continuum_creep(const FixedFixedCreepProblem& problem, int nx, int nz,
                                   const IdaOptions& options, Real end_time, int width_cells) {
  const auto start = Clock::now();
  const double cpu_start = cpu_now();
  const ContinuumStrip strip = make_continuum_strip(problem, nx, nz, width_cells);
  ElasticityOperator op(strip.mesh, strip.material, strip.boundaries, {},
                        problem.continuum_reconstruction_degree);
  ContinuumCreepSystem system(op, problem.law, problem.continuum_source_degree);
  system.set_creep_stress_mask(problem.continuum_creep_stress);
  system.set_linear_solver(problem.continuum_linear_solver);
  IdaOptions o = options;
  if (system.has_preconditioner()) o.linear_solver = IdaOptions::LinearSolver::Spgmr;
  return integrate(system, o, end_time, start, cpu_start, [&](std::span<const Real> y) {
    const auto G = op.cell_gradients(0, y.first(system.structural_size()));
    return op.displacement_at(strip.centre_cell, strip.centre, y.first(system.structural_size()), G)
        .y();
  });
}

}  // namespace rfmems
