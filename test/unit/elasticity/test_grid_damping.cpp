// The grid damping of the elasticity operator (model.grid_damping, Kelvin-Voigt C = beta K):
// the cubic FV stiffness of the cantilever switch's beam is not symmetric and has complex
// eigenvalue pairs, modes growing from round-off at up to 3e8 1/s near the clamp and the free
// end (docs/immersed_switch.md, "Grid damping"); the default grid damping makes every mode
// decay while the first bending mode's damping ratio stays below 1e-4.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>

#include "core/dense_stiffness.hpp"
#include "core/error.hpp"
#include "io/case_file.hpp"
#include "physics/elasticity/elasticity_scene.hpp"
#include "physics/elasticity/kelvin_voigt_modes.hpp"

namespace rfmems {
namespace {

// The cantilever switch's beam (cases/cantilever_switch) on a coarse 46 x 4 mesh.
ElasticityScene beam(const std::string& model_extra = "") {
  const std::string text =
      "mesh: {type: rectangle, lower: [0 um, 1.5 um], size: [45 um, 1.5 um], cells: [46, 4]}\n"
      "material: {E: 200 GPa, nu: 0.3, density: 8912 kg/m^3}\n"
      "model: {structure: plane, hypothesis: plane_stress" +
      model_extra +
      "}\n"
      "boundaries: {left: {type: fixed}, right: {type: free}, bottom: {type: free},"
      " top: {type: free}}\n";
  const CaseFile cf = CaseFile::parse(text, "beam.yaml");
  return build_elasticity_scene(cf.root(), "", AnalysisType::Transient);
}

struct Spectrum {
  Real fastest = -std::numeric_limits<Real>::infinity();  // max Re s over all modes
  Real first_damping_ratio = 0;                           // of the slowest mode
};

Spectrum spectrum(ElasticityOperator& op) {
  const std::vector<Real> mass = op.mass_diagonal();
  Eigen::MatrixXd A = dense_stiffness(op);
  for (Index i = 0; i < A.rows(); ++i) A.row(i) /= mass[i];
  const Eigen::VectorXcd lambda = Eigen::EigenSolver<Eigen::MatrixXd>(A, false).eigenvalues();
  Spectrum s;
  Index slowest = 0;
  for (Index i = 0; i < lambda.size(); ++i) {
    s.fastest = std::max(s.fastest, kelvin_voigt_growth_rate(lambda[i], op.damping_time()));
    if (std::abs(lambda[i]) < std::abs(lambda[slowest])) slowest = i;
  }
  s.first_damping_ratio = op.damping_time() * std::sqrt(std::abs(lambda[slowest])) / 2;
  return s;
}

TEST(GridDamping, DampingTimeIsZetaTimesTheSmallestSpacingOverThePWaveSpeed) {
  ElasticityScene scene = beam();
  // Plane stress: lambda + 2 mu = E / (1 - nu^2); the smallest spacing is dy = 0.375 um.
  const Real c_p = std::sqrt(200e9 / (1 - 0.09) / 8912);
  EXPECT_NEAR(scene.op->damping_time(), kGridDamping * 0.375e-6 / c_p, 1e-9 * 1e-11);
  EXPECT_EQ(beam(", grid_damping: 0").op->damping_time(), 0.0);
}

TEST(GridDamping, EveryModeOfTheCantileverSwitchBeamDecays) {
  ElasticityScene undamped = beam(", grid_damping: 0");
  const Spectrum without = spectrum(*undamped.op);
  EXPECT_GT(without.fastest, 1e8);  // the defect the damping is for (3.2e8 1/s measured)

  ElasticityScene damped = beam();
  const Spectrum with = spectrum(*damped.op);
  EXPECT_LT(with.fastest, 0.0);
  EXPECT_GT(with.first_damping_ratio, 0.0);
  EXPECT_LT(with.first_damping_ratio, 1e-4);  // 2.7e-5 measured
}

TEST(GridDamping, OutOfRangeIsAnInputError) {
  EXPECT_THROW(beam(", grid_damping: 1.5"), InputError);
  EXPECT_THROW(beam(", grid_damping: -0.1"), InputError);
}

}  // namespace
}  // namespace rfmems
