// Small kinetic test problems shared by the COMET tests: the heat-transfer square and the
// lid-driven cavity of the thesis (ch. 5) (argon, walls at 273.15 K; heat transfer:
// top 327.78 K, bottom 273.15 K, specular sides; cavity: all walls diffuse, lid 10 m/s), at
// a Knudsen number set through the density on a 1 cm square, on an n x n mesh with an
// nv^3 velocity grid over +-3.5 sqrt(2 R T0).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "mesh/structured_mesh.hpp"
#include "physics/gas/kinetic/kinetic_operator.hpp"

namespace rfmems::comet_test {

constexpr Real kT0 = 273.15, kTHot = 327.78, kLength = 0.01, kLidSpeed = 10.0;

enum class Case { HeatTransfer, Cavity, SpecularBox };

struct Problem {
  FaceGraph graph;
  std::unique_ptr<KineticOperator> op;
  std::vector<Real> f;  // the initial state: gas at rest, T0, rho0
  Real rho0 = 0;
};

inline std::unique_ptr<Problem> make_problem(Case which, Real kn, int n, int nv,
                                             CollisionModel model = CollisionModel::Esbgk) {
  auto p = std::make_unique<Problem>();
  const KineticGas gas = KineticGas::argon(model);
  p->rho0 = gas.density_for_knudsen(kn, kT0, kLength);
  BoxSpec spec;
  spec.upper = Vec3(kLength, kLength, 0);
  spec.n[0] = spec.n[1] = n;
  p->graph = face_graph_of(make_structured_mesh(spec));
  std::vector<KineticBoundary> bcs;
  for (const std::string& name : p->graph.patch_names) {
    switch (which) {
      case Case::HeatTransfer:
        bcs.push_back(name == "top"      ? KineticBoundary::diffuse_wall(kTHot)
                      : name == "bottom" ? KineticBoundary::diffuse_wall(kT0)
                                         : KineticBoundary::specular_wall());
        break;
      case Case::Cavity:
        bcs.push_back(name == "top" ? KineticBoundary::diffuse_wall(kT0, Vec3(kLidSpeed, 0, 0))
                                    : KineticBoundary::diffuse_wall(kT0));
        break;
      case Case::SpecularBox:
        bcs.push_back(KineticBoundary::specular_wall());
        break;
    }
  }
  VelocityGrid grid = VelocityGrid::uniform(nv, nv, nv, 3.5 * gas.thermal_speed(kT0));
  p->op = std::make_unique<KineticOperator>(p->graph, std::move(grid), gas, std::move(bcs));
  p->f.resize(p->op->size());
  const Real rho0 = p->rho0;
  p->op->initialize(p->f, [rho0](const Vec3&) { return GasState{rho0, Vec3::Zero(), kT0}; });
  return p;
}

}  // namespace rfmems::comet_test
