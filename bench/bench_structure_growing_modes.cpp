// Growing modes of the immersed switch's semi-discrete beam (issue 8's spurious touch-down,
// docs/BENCHMARKS.md section 47). The undamped structure M u'' + K u = f(u) linearised at rest,
// M u'' + (K - J) u = 0 with J = df/du, has the modes u ~ exp(s t), s^2 = -lambda,
// lambda an eigenvalue of M^-1 (K - J). A symmetric positive K gives lambda > 0 and s = +-i
// omega; the cell-centred FV stiffness is not symmetric, and a complex pair lambda = a +- i b
// gives s with real part |Im sqrt(lambda)| > 0 for one of each pair: a mode that grows from
// round-off at that rate unless the integrator damps it.
//
// For the case (--set overrides as rfmems-pullin takes them), one JSON line per operator:
// K of the case's reconstruction degree, of degrees 1-3, and K - J with the electrostatic
// load's Jacobian at rest at --voltage (central differences, 1e-4 of the rest gap): |K - K^T| /
// |K|, the number of complex eigenvalues, and the three fastest-growing modes: growth rate
// [1/s], frequency |sqrt(lambda)| [rad/s], the cell (and component) of the largest amplitude.
//
//   build/bench/bench_structure_growing_modes cases/cantilever_switch/case.yaml --voltage 125
//       --set "mesh.cells=[46,4]" --set "immersed.background.cells=[101,31]"
#include <CLI/CLI.hpp>
#include <Eigen/Eigenvalues>
#include <complex>
#include <nlohmann/json.hpp>

#include "bench_support.hpp"
#include "coupling/immersed_switch_study.hpp"
#include "io/case_file.hpp"

using namespace rfmems;

namespace {

nlohmann::json growth(const std::string& name, const Eigen::MatrixXd& K,
                      const std::vector<Real>& mass) {
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
    modes.push_back({std::abs(std::sqrt(lambda).imag()), std::abs(std::sqrt(lambda)),
                     largest / 2, largest % 2});
  }
  std::sort(modes.begin(), modes.end(), [](auto& a, auto& b) { return a.rate > b.rate; });
  nlohmann::json fastest = nlohmann::json::array();
  for (std::size_t k = 0; k < std::min<std::size_t>(3, modes.size()); ++k)
    fastest.push_back({{"growth_rate", modes[k].rate},
                       {"frequency", modes[k].omega},
                       {"cell", modes[k].cell},
                       {"component", modes[k].component}});
  return {{"operator", name},
          {"asymmetry", (K - K.transpose()).norm() / K.norm()},
          {"complex_eigenvalues", complex_eigenvalues},
          {"fastest_growing", fastest}};
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
  CLI11_PARSE(app, argc, argv);
  sets.push_back("gas.model=none");

  const CaseFile file = CaseFile::load(path, sets);
  const std::string dir = path.substr(0, path.find_last_of('/') + 1);
  ImmersedSwitchCase c = read_immersed_switch_case(file.root(), dir.empty() ? "." : dir);
  ElasticityOperator& op = *c.beam->op;
  const std::vector<Real> mass = op.mass_diagonal();

  const Eigen::MatrixXd K = bench::dense_stiffness(op);
  bench::emit(growth("case", K, mass));
  for (int degree : {1, 2, 3}) {
    ElasticityOperator other(op.mesh(), op.material(), op.boundaries(), op.body_force(), degree);
    bench::emit(growth("degree " + std::to_string(degree), bench::dense_stiffness(other), mass));
  }
  const Index n = op.size();
  const Real delta = 1e-4 * c.scene->rest_gap();
  Eigen::MatrixXd J(n, n);
  std::vector<Real> u(n, 0.0);
  for (Index j = 0; j < n; ++j) {
    u[j] = delta;
    const std::vector<Real> up = c.scene->electrostatic_load(u, voltage).force;
    u[j] = -delta;
    const std::vector<Real> down = c.scene->electrostatic_load(u, voltage).force;
    u[j] = 0;
    for (Index i = 0; i < n; ++i) J(i, j) = (up[i] - down[i]) / (2 * delta);
  }
  nlohmann::json coupled = growth("case, K - J", K - J, mass);
  coupled["voltage"] = voltage;
  coupled["load_asymmetry"] = (J - J.transpose()).norm() / J.norm();
  coupled["load_over_stiffness"] = J.norm() / K.norm();
  bench::emit(coupled);
}
