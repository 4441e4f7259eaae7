// Plate scenes from case text (physics/plate/plate_scene.hpp): a point load is the cell force
// it names, ramps scale pressures and edge loads linearly, an edge shear load on a cantilever
// strip gives the Timoshenko-beam tip deflection, and build_structure picks the plate or the
// continuum from model.structure.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "physics/plate/plate_scene.hpp"
#include "physics/structure/structure_from_case.hpp"
#include "solvers/static_solve.hpp"

namespace rfmems {
namespace {

constexpr double E = 200e9, h = 4e-6, L = 400e-6, b = 40e-6;

// A strip L x b, 20 x 2 cells unless given, nu = 0 (cylindrical bending); `rest` completes
// the case.
std::string strip_case(const std::string& rest, const std::string& cells = "[20, 2]") {
  return "mesh: {type: rectangle, size: [400 um, 40 um], cells: " + cells +
         "}\n"
         "material: {E: 200 GPa, nu: 0, density: 7854}\n"
         "model: {structure: plate, thickness: 4 um}\n"
         "" +
         rest;
}

const std::string kCantilever =
    "boundaries:\n  left: {type: clamped}\n  top: {type: free}\n  bottom: {type: free}\n";

PlateScene scene_of(const std::string& text) {
  const CaseFile cf = CaseFile::parse(text, "p.yaml");
  std::unique_ptr<StructuralModel> model = build_structure(cf.root(), "", AnalysisType::Static);
  cf.check_all_used();
  return std::move(dynamic_cast<PlateScene&>(*model));
}

std::vector<double> residual_at_rest(PlateScene& scene, double t) {
  std::vector<double> y(scene.op->size(), 0.0), r(y.size());
  scene.op->internal_residual(t, y, r);
  return r;
}

// Net force along z: the sum of the w rows.
double net_force(const std::vector<double>& r) {
  double sum = 0;
  for (std::size_t i = 0; i < r.size(); i += 3) sum += r[i];
  return sum;
}

TEST(PlateScene, PointLoadActsOnTheNearestCell) {
  PlateScene scene = scene_of(strip_case(
      kCantilever +
      "  right: {type: free}\n"
      "point_loads:\n  - {at: [390 um, 10 um], force: -2 uN, moment: [1 nN*m, 0 N*m]}\n"));
  const auto r = residual_at_rest(scene, 0.0);
  // Cells are 20 um x 20 um: (390, 10) um is the centroid of the last cell of the first row.
  const Index c = 19;
  ASSERT_NEAR(scene.mesh->cell_centroid(c).x(), 390e-6, 1e-12);
  EXPECT_DOUBLE_EQ(r[3 * c], 2e-6);
  EXPECT_DOUBLE_EQ(r[3 * c + 1], -1e-9);
  double others = 0;
  for (std::size_t i = 0; i < r.size(); ++i)
    if (i / 3 != static_cast<std::size_t>(c)) others += std::abs(r[i]);
  EXPECT_EQ(others, 0.0);
}

TEST(PlateScene, RampsScalePressureAndEdgeLoads) {
  PlateScene scene =
      scene_of(strip_case(kCantilever + "  right: {type: load, shear: -100 N/m, ramp: 2 ms}\n"
                                        "pressure: {value: -1 kPa, ramp: 4 ms}\n"));
  EXPECT_DOUBLE_EQ(scene.ramp_end_time(), 4e-3);
  const auto r_full = residual_at_rest(scene, 4e-3), r_late = residual_at_rest(scene, 1.0);
  const auto r_1ms = residual_at_rest(scene, 1e-3);
  const double total_full = net_force(r_full);
  // At full load: the pressure -1 kPa over L b and the shear -100 N/m over b push down.
  EXPECT_NEAR(total_full, 1e3 * L * b + 100 * b, 1e-12 * 1e3 * L * b);
  EXPECT_EQ(r_full, r_late);
  // At 1 ms: half the edge load, a quarter of the pressure.
  const double total_1ms = net_force(r_1ms);
  EXPECT_NEAR(total_1ms, 0.25 * 1e3 * L * b + 0.5 * 100 * b, 1e-12 * 1e3 * L * b);
}

TEST(PlateScene, EdgeShearOnACantileverGivesTheTimoshenkoBeamDeflection) {
  // Tip load P per width: w = P L^3 / (3 D) + P L / (k G h), D = E h^3 / 12 (nu = 0).
  // 10 x 5 cells: the cubic reconstruction needs rows across the strip (then it is exact).
  PlateScene scene =
      scene_of(strip_case(kCantilever + "  right: {type: load, shear: -100 N/m}\n", "[10, 5]"));
  const auto y = solve_static(*scene.op, 0.0).y;
  const double P = -100, D = E * h * h * h / 12, kGh = 5.0 / 6.0 * E / 2 * h;
  const double w_tip = P * L * L * L / (3 * D) + P * L / kGh;
  const Index c = 29;  // the middle cell of the tip edge
  ASSERT_NEAR(scene.mesh->cell_centroid(c).x(), 380e-6, 1e-12);
  EXPECT_NEAR(scene.op->deflection_at(c, Vec3(L, b / 2, 0), 0.0, y) / w_tip, 1.0, 1e-6);
}

TEST(PlateScene, StructureChosenByName) {
  const std::string text = strip_case(kCantilever + "  right: {type: free}\n");
  const CaseFile cf = CaseFile::parse(text, "p.yaml");
  auto model = build_structure(cf.root(), "", AnalysisType::Static);
  EXPECT_EQ(model->kind(), "plate");
  EXPECT_EQ(model->probe_components()[0], "w");

  const CaseFile plane = CaseFile::parse(
      "mesh: {type: rectangle, size: [1 m, 0.1 m], cells: [4, 2]}\n"
      "material: {E: 1 GPa, nu: 0.3}\nmodel: {structure: plane, hypothesis: plane_strain}\n"
      "boundaries: {left: {type: fixed}, right: {type: free}, top: {type: free}, bottom: {type: "
      "free}}\n",
      "q.yaml");
  EXPECT_EQ(build_structure(plane.root(), "", AnalysisType::Static)->kind(), "plane_strain");

  const CaseFile wrong = CaseFile::parse(
      "mesh: {type: rectangle, size: [1 m, 0.1 m], cells: [4, 2]}\n"
      "material: {E: 1 GPa, nu: 0.3}\nmodel: {structure: beam}\n",
      "r.yaml");
  try {
    build_structure(wrong.root(), "", AnalysisType::Static);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "r.yaml: key 'model.structure' = 'beam': expected one of: plane, solid3d, plate");
  }
}

}  // namespace
}  // namespace rfmems
