// Growing modes of the immersed switch's semi-discrete beam (the spurious touch-down,
// docs/immersed_switch.md, "Grid damping"). The undamped structure M u'' + K u = f(u) linearised at
// rest, M u'' + (K - J) u = 0 with J = df/du, has the modes u ~ exp(s t), s^2 = -lambda, lambda an
// eigenvalue of M^-1 (K - J). A symmetric positive K gives lambda > 0 and s = +-i omega; the
// cell-centred FV stiffness is not symmetric, and a complex pair lambda = a +- i b gives s with
// real part |Im sqrt(lambda)| > 0 for one of each pair: a mode that grows from round-off at that
// rate unless the integrator damps it.
//
// For the case (--set overrides as rfmems-pullin takes them; an immersed switch's beam, or the
// FV elasticity structure of any other case, without the load), one JSON line per operator:
// K of the case's reconstruction degree, of degrees 1-3, and K - J with the electrostatic
// load's Jacobian at rest at --voltage (central differences, 1e-4 of the rest gap): |K - K^T| /
// |K|, the number of complex eigenvalues, and the three fastest-growing modes: growth rate
// [1/s], frequency |sqrt(lambda)| [rad/s], the cell (and component) of the largest amplitude.
//
//   build/bench/bench_structure_growing_modes cases/cantilever_switch/case.yaml --voltage 125
//       --set "mesh.cells=[46,4]" --set "actuation.immersed.background.cells=[101,31]"
#include <CLI/CLI.hpp>
#include <Eigen/Eigenvalues>
#include <complex>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>

#include "bench_support.hpp"
#include "coupling/switch_scene.hpp"
#include "io/case_file.hpp"
#include "physics/elasticity/elasticity_scene.hpp"
#include "physics/elasticity/kelvin_voigt_modes.hpp"
#include "physics/structure/structure_from_case.hpp"

using namespace rfmems;

namespace {

// The smallest beta (to 1 %) with every mode decaying: damped_growth <= 0 for all lambda.
Real required_damping_time(const Eigen::VectorXcd& lambdas) {
  auto all_decay = [&](Real beta) {
    for (Index i = 0; i < lambdas.size(); ++i)
      if (kelvin_voigt_growth_rate(lambdas[i], beta) > 1e-9 * std::sqrt(std::abs(lambdas[i])))
        return false;
    return true;
  };
  if (all_decay(0)) return 0;
  Real high = 1e-15;
  while (!all_decay(high)) high *= 2;
  Real low = high / 2;
  while (high - low > 0.01 * high)
    (all_decay(0.5 * (low + high)) ? high : low) = 0.5 * (low + high);
  return high;
}

nlohmann::json growth(const std::string& name, const Eigen::MatrixXd& K,
                      const std::vector<Real>& mass, Real beta) {
  Eigen::VectorXd inverse_mass(K.rows());
  for (Index i = 0; i < K.rows(); ++i) inverse_mass[i] = 1 / mass[i];
  const Eigen::EigenSolver<Eigen::MatrixXd> es(inverse_mass.asDiagonal() * K);
  struct Mode {
    Real rate, omega;
    Index cell, component;
  };
  std::vector<Mode> modes;
  Index complex_eigenvalues = 0;
  for (Index i = 0; i < K.rows(); ++i) {
    const std::complex<Real> lambda = es.eigenvalues()[i];
    if (!(std::abs(lambda.imag()) > 1e-12 * std::abs(lambda)) || lambda.imag() < 0) continue;
    complex_eigenvalues += 2;  // one of each conjugate pair listed
    Index largest = 0;
    es.eigenvectors().col(i).cwiseAbs().maxCoeff(&largest);
    modes.push_back({std::abs(std::sqrt(lambda).imag()), std::abs(std::sqrt(lambda)), largest / 2,
                     largest % 2});
  }
  std::sort(modes.begin(), modes.end(), [](auto& a, auto& b) { return a.rate > b.rate; });
  nlohmann::json fastest = nlohmann::json::array();
  for (std::size_t k = 0; k < std::min<std::size_t>(3, modes.size()); ++k)
    fastest.push_back({{"growth_rate", modes[k].rate},
                       {"frequency", modes[k].omega},
                       {"cell", modes[k].cell},
                       {"component", modes[k].component}});
  // With the damping C = beta K: the fastest rate over all modes (< 0: every mode decays),
  // and the damping ratio of the slowest mode (the first bending mode).
  Real damped = -std::numeric_limits<Real>::infinity();
  Index slowest = 0;
  for (Index i = 0; i < K.rows(); ++i) {
    damped = std::max(damped, kelvin_voigt_growth_rate(es.eigenvalues()[i], beta));
    if (std::abs(es.eigenvalues()[i]) < std::abs(es.eigenvalues()[slowest])) slowest = i;
  }
  const Real omega_1 = std::sqrt(std::abs(es.eigenvalues()[slowest]));
  return {{"operator", name},
          {"asymmetry", (K - K.transpose()).norm() / K.norm()},
          {"complex_eigenvalues", complex_eigenvalues},
          {"fastest_growing", fastest},
          {"required_damping_time", required_damping_time(es.eigenvalues())},
          {"damping_time", beta},
          {"damped_fastest_rate", damped},
          {"first_frequency", omega_1},
          {"first_damping_ratio", beta * omega_1 / 2}};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"growing modes of the immersed switch's semi-discrete beam"};
  std::string path;
  std::vector<std::string> sets;
  double voltage = 125;
  app.add_option("case", path)->required();
  app.add_option("--set", sets, "key=value overrides");
  app.add_option("--voltage", voltage);
  bool all_degrees = true, with_load = true;
  app.add_flag("!--case-only", all_degrees, "only the case's reconstruction degree");
  app.add_flag("!--no-load", with_load, "skip K - J");
  CLI11_PARSE(app, argc, argv);
  const std::string dir = path.substr(0, path.find_last_of('/') + 1);
  // The immersed switch's beam, with its load; or any elasticity case's structure (no load).
  const bool immersed = CaseFile::load(path, sets)
                            .root()
                            .child_or_empty("actuation")
                            .get_string("electrostatics", "") == "immersed";
  if (immersed) sets.push_back("gas.model=none");
  const CaseFile file = CaseFile::load(path, sets);
  std::optional<SwitchScene> c;
  std::unique_ptr<StructuralModel> structure;
  ElasticityOperator* beam = nullptr;
  if (immersed) {
    c = build_switch_scene(file.root(), dir.empty() ? "." : dir);
    beam = dynamic_cast<ElasticityScene&>(*c->structure).op.get();
  } else {
    structure = build_structure(file.root(), dir.empty() ? "." : dir, AnalysisType::Transient);
    if (auto* scene = dynamic_cast<ElasticityScene*>(structure.get())) beam = scene->op.get();
    if (!beam) {
      std::cerr << path << ": the structure is not FV elasticity\n";
      return 2;
    }
    with_load = false;
  }
  ElasticityOperator& op = *beam;
  const std::vector<Real> mass = op.mass_diagonal();

  const Real beta = op.damping_time();
  const Eigen::MatrixXd K = dense_stiffness(op);
  bench::emit(growth("case", K, mass, beta));
  if (all_degrees)
    for (int degree : {1, 2, 3}) {
      ElasticityOperator other(op.mesh(), op.material(), op.boundaries(), op.body_force(), degree);
      bench::emit(growth("degree " + std::to_string(degree), dense_stiffness(other), mass, beta));
    }
  if (!with_load) return 0;
  const Index n = op.size();
  const Real delta = 1e-4 * c->immersed->sw->rest_gap();
  Eigen::MatrixXd J(n, n);
  std::vector<Real> u(n, 0.0);
  for (Index j = 0; j < n; ++j) {
    u[j] = delta;
    const std::vector<Real> up = c->immersed->sw->electrostatic_load(u, voltage).force;
    u[j] = -delta;
    const std::vector<Real> down = c->immersed->sw->electrostatic_load(u, voltage).force;
    u[j] = 0;
    for (Index i = 0; i < n; ++i) J(i, j) = (up[i] - down[i]) / (2 * delta);
  }
  nlohmann::json coupled = growth("case, K - J", K - J, mass, beta);
  coupled["voltage"] = voltage;
  coupled["load_asymmetry"] = (J - J.transpose()).norm() / J.norm();
  coupled["load_over_stiffness"] = J.norm() / K.norm();
  bench::emit(coupled);
}
