// Cost per coupled step of the ESBGK gas on the immersed boundary (brief item 5), on
// the thesis's cantilever switch geometry (Fig. 6.5): background 75 um x 10 um (150 x 50 by
// default), beam 45 um x 1.5 um, bottom 1.5 um above the substrate, anchored in the left wall,
// its surface the boundary of a 185 x 11 structure mesh (392 segments); air at 300 K and
// 1.36e4 Pa (rho0 = 0.158 kg/m^3), mu = 1.712e-5 Pa s, omega = 0.74, ESBGK, 10 x 10 x 10
// velocities. Substrate and left (anchor) wall diffuse at 300 K, top and right pressure.
//
// Prescribed motion: the static cantilever shape w(x) = -d(t) (x/L)^2 (3 - x/L) / 2, the tip
// moving down at v_tip (default 0.5 m/s); each step: move the surface, set_body (mark,
// re-build, interpolate), advance(dt) (backward Euler to --tolerance), segment forces.
// Reported per step, CPU seconds of the process: marking (mark + fluid graph + carry-over),
// interpolation (IB fits, force transfer, wall Maxwellians), gas (the sweeps); the sweeps, the
// gas force on the beam, the mass change, and the negative step-(iii) entering values before
// the clip (count and the deepest min/max ratio of a face; step (i) likewise). One JSON object
// per line; the load average is in the last line.
//
//   build/bench/bench_ibm_gas [--steps 3] [--dt 5e-8] [--nx 150] [--ny 50] [--nv 10]
//                             [--tolerance 1e-8] [--stepper sweeps|ida] [--ida-rtol 1e-6]
//                             [--smoother downwind|point|both] [--predictor]
#include <CLI/CLI.hpp>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "bench_support.hpp"
#include "ibm/immersed_kinetic_gas.hpp"
#include "mesh/structured_mesh.hpp"

using namespace rfmems;

int main(int argc, char** argv) {
  CLI::App app{"ESBGK gas on the immersed boundary: cost per step on the cantilever switch"};
  int steps = 3, nx = 150, ny = 50, nv = 10;
  Real dt = 5e-8, v_tip = 0.5, tolerance = 1e-8;
  app.add_option("--steps", steps);
  app.add_option("--dt", dt, "time step, s");
  app.add_option("--nx", nx);
  app.add_option("--ny", ny);
  app.add_option("--nv", nv, "velocities per direction");
  app.add_option("--v-tip", v_tip, "tip speed, m/s (downwards)");
  app.add_option("--tolerance", tolerance, "sweeps: step residual / ||alpha V h / dt||");
  std::string stepper = "sweeps";
  Real ida_rtol = 1e-6;
  app.add_option("--stepper", stepper, "sweeps | ida")->check(CLI::IsMember({"sweeps", "ida"}));
  app.add_option("--ida-rtol", ida_rtol, "IDA relative tolerance");
  std::string smoother = "downwind";
  bool predictor = false;
  app.add_option("--smoother", smoother, "sweeps: downwind | point | both")
      ->check(CLI::IsMember({"downwind", "point", "both"}));
  app.add_flag("--predictor", predictor, "start each step from the linear extrapolation");
  CLI11_PARSE(app, argc, argv);

  const Real um = 1e-6, L = 45 * um, T0 = 300, p0 = 1.36e4;
  BoxSpec beam_spec;
  beam_spec.lower = Vec3(-0.5 * um, 1.5 * um, 0);
  beam_spec.upper = Vec3(L, 3.0 * um, 0);
  beam_spec.n[0] = 185;
  beam_spec.n[1] = 11;
  const Mesh structure = make_structured_mesh(beam_spec);
  const ImmersedSurface rest = ImmersedSurface::from_mesh_boundary(structure);

  BoxSpec bg;
  bg.upper = Vec3(75 * um, 10 * um, 0);
  bg.n[0] = nx;
  bg.n[1] = ny;
  const Mesh background = make_structured_mesh(bg);
  const FaceGraph g = face_graph_of(background);

  KineticGas air;
  air.R = 287.05;
  air.mu_ref = 1.712e-5;
  air.T_ref = T0;
  air.omega = 0.74;
  std::vector<KineticBoundary> bcs(g.patch_names.size());
  bcs[g.find_patch("bottom")] = KineticBoundary::diffuse_wall(T0);
  bcs[g.find_patch("left")] = KineticBoundary::diffuse_wall(T0);
  bcs[g.find_patch("top")] = KineticBoundary::pressure_outlet(p0, T0);
  bcs[g.find_patch("right")] = KineticBoundary::pressure_outlet(p0, T0);
  ImmersedGasOptions options;
  options.ib.wall_temperature = T0;
  options.step_tolerance = tolerance;
  options.stepper = stepper == "ida" ? GasStepper::Ida : GasStepper::Sweeps;
  options.ida_rtol = ida_rtol;
  options.smoother = smoother == "point"  ? GasSmoother::PointCoupled
                     : smoother == "both" ? GasSmoother::Both
                                          : GasSmoother::Downwind;
  options.predictor = predictor;
  ImmersedKineticGas gas(background, bcs,
                         VelocityGrid::uniform(nv, nv, nv, 3.5 * air.thermal_speed(T0)), air,
                         options);

  auto shape = [&](Real x) {
    const Real s = std::clamp(x / L, 0.0, 1.0);
    return s * s * (3 - s) / 2;
  };
  auto surface_at = [&](Real d) {
    std::vector<Vec3> v = rest.vertices();
    for (Vec3& x : v) x.y() -= d * shape(x.x());
    ImmersedSurface s = rest;
    s.set_vertices(v);
    return s;
  };
  auto velocities = [&](const ImmersedSurface& s) {
    std::vector<Vec3> u;
    for (Index k = 0; k < s.n_segments(); ++k)
      u.emplace_back(0, -v_tip * shape(s.midpoint(k).x()), 0);
    return u;
  };

  const double c0 = bench::cpu_now(), w0 = bench::now();
  ImmersedSurface body = surface_at(0);
  gas.set_body(body, velocities(body));
  gas.initialize({p0 / (air.R * T0), Vec3::Zero(), T0});
  bench::emit(nlohmann::json{{"bench", "ibm_gas"},
                             {"phase", "setup"},
                             {"background", {nx, ny}},
                             {"velocities", nv * nv * nv},
                             {"fluid_cells", gas.kinetic().n_cells()},
                             {"ib_faces", gas.marking().ib_faces.size()},
                             {"segments", body.n_segments()},
                             {"ordinate_groups", gas.face_values().n_ordinate_groups()},
                             {"one_sided_fits", gas.face_values().count_one_sided()},
                             {"cpu_s", bench::cpu_now() - c0},
                             {"wall_s", bench::now() - w0}});
  ImmersedGasTimings last = gas.timings();
  for (int n = 1; n <= steps; ++n) {
    const double w1 = bench::now();
    body = surface_at(v_tip * dt * n);
    gas.set_body(body, velocities(body));
    const GasStepReport rep = gas.advance(dt);
    Vec3 force = Vec3::Zero();
    for (const Vec3& f : gas.segment_forces()) force += f;
    const ImmersedGasTimings& t = gas.timings();
    bench::emit(nlohmann::json{
        {"bench", "ibm_gas"},
        {"phase", "step"},
        {"step", n},
        {"tip_deflection_um", v_tip * dt * n / um},
        {"reclassified", gas.last_remark().reclassified},
        {"marking_cpu_s", t.marking - last.marking},
        {"interpolation_cpu_s", t.interpolation - last.interpolation},
        {"gas_cpu_s", t.gas - last.gas},
        {"stepper", stepper},
        {"smoother", smoother},
        {"predicted", rep.predicted},
        {"tolerance", tolerance},
        {"dt", dt},
        {"order", rep.order},
        {"sweeps", rep.sweeps},
        {"newton", rep.newton},
        {"krylov", rep.krylov},
        {"mass_change", rep.mass_after / rep.mass_before - 1},
        {"converged", rep.converged},
        {"residual_ratio", rep.residual_ratio},
        {"force_y_N_per_m", force.y()},
        {"negative_entering", gas.face_values().positivity().negative_entering},
        {"entering_values", gas.face_values().positivity().entering_values},
        {"faces_with_negative", gas.face_values().positivity().faces_with_negative},
        {"most_negative_entering", gas.face_values().positivity().most_negative_entering},
        {"negative_into_solid", gas.face_values().positivity().negative_into_solid},
        {"most_negative_into_solid", gas.face_values().positivity().most_negative_into_solid},
        {"wall_s", bench::now() - w1}});
    last = t;
  }
  double load[3] = {0, 0, 0};
  if (std::FILE* f = std::fopen("/proc/loadavg", "r")) {
    if (std::fscanf(f, "%lf %lf %lf", &load[0], &load[1], &load[2]) != 3) load[0] = -1;
    std::fclose(f);
  }
  bench::emit(nlohmann::json{{"bench", "ibm_gas"}, {"phase", "end"}, {"load_average", load}});
  return 0;
}
