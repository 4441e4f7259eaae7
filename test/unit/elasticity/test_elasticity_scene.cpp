// Elasticity scenes from case text: boundary types (a pressure equals the traction -p n, a
// ramp scales the load linearly), the patch/boundary matching errors, the model checks, and
// the analysis settings' defaults.
#include <gtest/gtest.h>

#include <functional>

#include "core/error.hpp"
#include "physics/elasticity/elasticity_scene.hpp"
#include "physics/structure/structural_analysis.hpp"

namespace rfmems {
namespace {

// A 1 x 0.2 plate, 10 x 4 cells; `boundaries` and `extra` complete the case.
std::string plate_case(const std::string& boundaries, const std::string& extra = "") {
  return "mesh: {type: rectangle, size: [1 m, 0.2 m], cells: [10, 4]}\n"
         "material: {E: 200 GPa, nu: 0.3, density: 7800}\n"
         "model: {hypothesis: plane_stress}\n"
         "analysis: {type: static}\n"
         "boundaries:\n" +
         boundaries + extra;
}

ElasticityScene scene_of(const std::string& text, AnalysisType type = AnalysisType::Static) {
  const CaseFile cf = CaseFile::parse(text, "s.yaml");
  ElasticityScene scene = build_elasticity_scene(cf.root(), "", type);
  read_analysis_settings(cf.root(), scene);
  cf.check_all_used();
  return scene;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::vector<Real> residual(ElasticityScene& scene, Real t, const std::vector<Real>& u) {
  std::vector<Real> r(scene.op->size());
  scene.op->internal_residual(t, u, r);
  return r;
}

const std::string kSides =
    "  left: {type: fixed}\n  top: {type: free}\n  bottom: {type: symmetry}\n";

TEST(ElasticityScene, PressureIsTractionAgainstTheNormal) {
  ElasticityScene pressure =
      scene_of(plate_case(kSides + "  right: {type: pressure, value: 2 MPa}\n"));
  ElasticityScene traction =
      scene_of(plate_case(kSides + "  right: {type: traction, value: [-2 MPa, 0]}\n"));
  std::vector<Real> u(pressure.op->size());
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = 1e-6 * std::sin(0.7 * static_cast<double>(i));
  const auto rp = residual(pressure, 0, u), rt = residual(traction, 0, u);
  for (std::size_t i = 0; i < rp.size(); ++i)
    EXPECT_NEAR(rp[i], rt[i], 1e-9 * std::abs(rt[i]) + 1e-12);
}

TEST(ElasticityScene, RampScalesTheLoadLinearly) {
  ElasticityScene scene =
      scene_of(plate_case(kSides + "  right: {type: traction, value: [0, -1 kPa], ramp: 20 ms}\n"));
  EXPECT_DOUBLE_EQ(scene.load_time, 0.02);
  const std::vector<Real> zero(scene.op->size(), 0.0);
  const auto r0 = residual(scene, 0.0, zero), r_half = residual(scene, 0.01, zero),
             r_full = residual(scene, 0.02, zero), r_late = residual(scene, 5.0, zero);
  Real norm = 0;
  for (std::size_t i = 0; i < r0.size(); ++i) {
    EXPECT_EQ(r0[i], 0.0);
    EXPECT_NEAR(r_half[i], 0.5 * r_full[i], 1e-12 * std::abs(r_full[i]) + 1e-15);
    EXPECT_EQ(r_late[i], r_full[i]);
    norm += std::abs(r_full[i]);
  }
  EXPECT_NEAR(norm, 1e3 * 0.2, 1e-9);  // the whole load 1 kPa x 0.2 m reaches the cells
}

TEST(ElasticityScene, EveryPatchNeedsExactlyOneEntry) {
  EXPECT_EQ(error_of([] { scene_of(plate_case(kSides)); }),
            "s.yaml: key 'boundaries.right': mesh patch 'right' has no boundary condition "
            "(given: left, top, bottom; mesh patches: left, right, bottom, top)");
  EXPECT_EQ(error_of([] {
              scene_of(plate_case(kSides + "  right: {type: free}\n  hole: {type: free}\n"));
            }),
            "s.yaml: key 'boundaries.hole' = {type: free}: the mesh has no patch 'hole' (mesh "
            "patches: left, right, bottom, top)");
  EXPECT_NE(error_of([] {
              scene_of(plate_case(kSides + "  right: {type: clamp}\n"));
            }).find("'boundaries.right.type' = 'clamp': expected one of"),
            std::string::npos);
  EXPECT_EQ(error_of([] {
              scene_of(plate_case(kSides + "  right: {type: traction, value: [0, 1, 2]}\n"));
            }),
            "s.yaml: key 'boundaries.right.value' = [0, 1, 2]: expected 2 components (the mesh is "
            "2D)");
}

TEST(ElasticityScene, ModelChecks) {
  const std::string bcs = kSides + "  right: {type: free}\n";
  std::string text = plate_case(bcs);
  text.replace(text.find("plane_stress"), 12, "3d");
  EXPECT_EQ(error_of([&] { scene_of(text); }),
            "s.yaml: key 'model.hypothesis' = '3d': needs a 3D mesh, but the mesh is 2D");
  text = plate_case(bcs);
  text.replace(text.find("200 GPa"), 7, "-1 GPa");
  EXPECT_EQ(error_of([&] { scene_of(text); }), "s.yaml: key 'material.E' = '-1 GPa': must be > 0");
  text = plate_case(bcs);
  text.replace(text.find("{hypothesis: plane_stress}"), 26,
               "{hypothesis: plane_stress, stress: segregated}");
  EXPECT_NE(error_of([&] {
              scene_of(text, AnalysisType::Transient);
            }).find("the segregated method is for static analyses only"),
            std::string::npos);
  EXPECT_EQ(scene_of(text).stress, StressMethod::Segregated);
}

TEST(AnalysisSettings, TransientDefaults) {
  std::string text = plate_case(kSides + "  right: {type: free}\n");
  text.replace(text.find("{type: static}"), 14,
               "{type: transient, end_time: 10 ms, output_interval: 1 ms}");
  const CaseFile cf = CaseFile::parse(text, "s.yaml");
  ElasticityScene scene = build_elasticity_scene(cf.root(), "", AnalysisType::Transient);
  const AnalysisSettings s = read_analysis_settings(cf.root(), scene);
  EXPECT_EQ(s.type, AnalysisType::Transient);
  EXPECT_DOUBLE_EQ(s.end_time, 0.01);
  EXPECT_DOUBLE_EQ(s.output_interval, 0.001);
  EXPECT_DOUBLE_EQ(s.ida.rtol, 1e-6);
  EXPECT_DOUBLE_EQ(s.ida.atol, 1e-6 * 1e-4 * 1.0);  // rtol x 1e-4 x the 1 m plate
  EXPECT_EQ(s.ida.max_order, 2);                    // BDF1-2 for undamped structural dynamics
  EXPECT_EQ(s.ida.fixed_step, 0.0);
  cf.check_all_used();
}

}  // namespace
}  // namespace rfmems
