// Cost of the immersed-boundary building blocks per coupled step, on the thesis's
// cantilever switch geometry (Fig. 6.5): background 75 um x 10 um, beam 45 um x 1.5 um whose
// bottom is 1.5 um above the electrode, anchored in the left wall; the beam's surface is the
// boundary of its 185 x 11 structure mesh (392 faces).
//
// Per background resolution (150 x 50 is the thesis's), CPU seconds of: building the marker
// (R-tree, once), mark() (every step), IbInterpolation (every step), ForceTransfer (every
// step), and applying them (interpolate one field, transfer one load, map one velocity).
// Each figure is the mean over --repeats calls. Also one electrostatic solve at 100 V on the
// undeflected beam (ImmersedElectrostatics) and its force against the parallel plate
// eps V^2 / (2 g^2) L (no fringing). One JSON object per line.
//
//   build/bench/bench_ibm_foundation [--repeats 20] [--scales 1 2 4]
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "bench_support.hpp"
#include "ibm/cell_marking.hpp"
#include "ibm/force_transfer.hpp"
#include "ibm/ib_interpolation.hpp"
#include "ibm/immersed_electrostatics.hpp"
#include "mesh/structured_mesh.hpp"
#include "physics/electrostatics/parallel_plate.hpp"

using namespace rfmems;

int main(int argc, char** argv) {
  CLI::App app{"IBM marking / interpolation / transfer cost on the cantilever switch"};
  int repeats = 20;
  std::vector<int> scales{1, 2, 4};
  app.add_option("--repeats", repeats, "calls averaged per figure");
  app.add_option("--scales", scales, "background refinement factors of 150 x 50");
  CLI11_PARSE(app, argc, argv);

  const Real um = 1e-6;
  BoxSpec beam_spec;
  beam_spec.lower = Vec3(-0.5 * um, 1.5 * um, 0);
  beam_spec.upper = Vec3(45 * um, 3.0 * um, 0);
  beam_spec.n[0] = 185;
  beam_spec.n[1] = 11;
  const Mesh structure = make_structured_mesh(beam_spec);
  const ImmersedSurface beam = ImmersedSurface::from_mesh_boundary(structure);

  for (int scale : scales) {
    BoxSpec bg;
    bg.lower = Vec3(0, 0, 0);
    bg.upper = Vec3(75 * um, 10 * um, 0);
    bg.n[0] = 150 * scale;
    bg.n[1] = 50 * scale;
    const Mesh background = make_structured_mesh(bg);

    double t0 = bench::cpu_now();
    CellMarker marker(background);
    const double t_index = bench::cpu_now() - t0;

    // The tip moving down by up to 0.5 um across the repeats: a fresh marking each call.
    double t_mark = 0, t_interp = 0, t_transfer = 0, t_apply = 0;
    Index n_ib_faces = 0, n_one_sided = 0, n_linear = 0, n_ib_cells = 0;
    std::vector<Real> field(background.n_cells());
    for (Index c = 0; c < background.n_cells(); ++c) field[c] = background.cell_centroid(c).y();
    for (int r = 0; r < repeats; ++r) {
      const ImmersedSurface moved = beam.translated(Vec3(0, -0.5 * um * r / repeats, 0));
      double t = bench::cpu_now();
      const CellMarking m = marker.mark(moved);
      t_mark += bench::cpu_now() - t;
      t = bench::cpu_now();
      const IbInterpolation ib(background, m, moved);
      t_interp += bench::cpu_now() - t;
      t = bench::cpu_now();
      const ForceTransfer transfer(background, m, moved);
      t_transfer += bench::cpu_now() - t;
      t = bench::cpu_now();
      std::vector<Real> wall(moved.n_segments(), 0.0);
      const auto values = ib.interpolate(field, wall);
      const auto loads = transfer.to_surface(
          transfer.ib_face_forces([](const Vec3&, const Vec3& n) -> Vec3 { return 1e4 * n; }));
      const auto velocity =
          transfer.to_ib_faces(std::vector<Vec3>(moved.n_segments(), Vec3(0, -0.1, 0)));
      t_apply += bench::cpu_now() - t;
      n_ib_faces = m.ib_faces.size();
      n_ib_cells = m.count(CellClass::ImmersedBoundary);
      n_one_sided = ib.count_one_sided();
      n_linear = ib.count_degree(1);
      if (values.empty() || loads.empty() || velocity.empty()) return 1;
    }
    // Electrostatics at 100 V on the undeflected beam, against the parallel-plate force.
    const CellMarking m0 = marker.mark(beam);
    const IbInterpolation ib0(background, m0, beam);
    ImmersedElectrostatics es(background, {{"bottom", PotentialBoundary::potential(0.0)},
                                           {"top", PotentialBoundary::zero_flux()},
                                           {"left", PotentialBoundary::zero_flux()},
                                           {"right", PotentialBoundary::zero_flux()}});
    double t = bench::cpu_now();
    es.solve(m0, ib0, 100.0);
    const double t_es = bench::cpu_now() - t;
    Vec3 force = Vec3::Zero();
    for (const Vec3& f : es.ib_face_forces()) force += f;
    const Real plate = ParallelPlateLaw{}.pressure_per_volt2(1.5 * um) * 1e4 * 45 * um;

    nlohmann::json j;
    j["bench"] = "ibm_foundation";
    j["background_cells"] = {bg.n[0], bg.n[1]};
    j["surface_segments"] = beam.n_segments();
    j["ib_cells"] = n_ib_cells;
    j["ib_faces"] = n_ib_faces;
    j["one_sided_faces"] = n_one_sided;
    j["linear_faces"] = n_linear;
    j["repeats"] = repeats;
    j["cpu_s_index_once"] = t_index;
    j["cpu_s_mark"] = t_mark / repeats;
    j["cpu_s_interpolation_build"] = t_interp / repeats;
    j["cpu_s_transfer_build"] = t_transfer / repeats;
    j["cpu_s_apply"] = t_apply / repeats;
    j["cpu_s_electrostatics_solve"] = t_es;
    j["electrostatic_force_N_per_m"] = force.y();
    j["force_over_parallel_plate"] = -force.y() / plate;
    bench::emit(j);
  }
  return 0;
}
