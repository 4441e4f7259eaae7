// The plate switch of cases/switch_plate on a coarse 20 x 2 mesh (or `cells`) with the dielectric
// (0.1 um, eps_r = 7.6) and the contact penalty (g_c = 75 nm, delta = 7.5 nm), for the contact
// tests (test/unit/coupling/test_plate_contact.cpp, test/study/test_plate_release.cpp).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "core/structural_systems.hpp"
#include "coupling/dynamic_release.hpp"
#include "coupling/pull_in_study.hpp"
#include "coupling/quasi_static_pull_in.hpp"
#include "coupling/switch_scene.hpp"
#include "coupling/switch_system.hpp"
#include "io/case_file.hpp"
#include "solvers/pseudo_transient_relaxation.hpp"

namespace rfmems::test {

inline constexpr double kContactGap = 75e-9, kPenetration = 7.5e-9;
inline constexpr double kDielectricGap = 0.1e-6 / 7.6;  // t_d / eps_r

struct CoarsePlate {
  CaseFile cf;
  SwitchScene scene;
  explicit CoarsePlate(const std::string& gas = "none", const std::string& cells = "[20, 2]")
      : cf(CaseFile::load(std::string(RFMEMS_SOURCE_DIR) + "/cases/switch_plate/case.yaml",
                          {"mesh.cells=" + cells, "gas.model=" + gas,
                           "actuation.dielectric={thickness: 0.1 um, permittivity: 7.6}",
                           "actuation.contact={gap: 75 nm, penetration: 7.5 nm}"})),
        scene(build_switch_scene(cf.root(),
                                 std::string(RFMEMS_SOURCE_DIR) + "/cases/switch_plate")) {}
  ParallelPlateActuation& act() { return *scene.actuation; }
  // The static solves' residual tolerance (quasi_static_pull_out.hpp): 1e-10 k_ref g0 [N].
  double tolerance() { return 1e-10 * stiffness_scale(act()) * act().initial_gap(); }
};

// The structure's stiffness diagonal at rest (the relaxation's pseudo-mass).
inline std::vector<double> rest_diagonal(ParallelPlateActuation& act) {
  const CsrPattern& k = act.structure().stiffness_pattern();
  std::vector<double> values(k.nnz()), zero(act.size(), 0.0), d(act.size());
  act.structure().stiffness(0.0, zero, values);
  for (Index i = 0; i < act.size(); ++i) d[i] = std::abs(values[k.find(i, i)]);
  return d;
}

// The stable equilibrium at `voltage` reached by the pseudo-transient flow from y (in place).
inline PseudoTransientStats relax_at(ParallelPlateActuation& act, double voltage,
                                     std::vector<double>& y, double tolerance) {
  act.set_voltage_squared([voltage](Real) { return voltage * voltage; });
  StaticSystem system(act);
  PseudoTransientOptions pt;
  pt.tolerance = tolerance;
  return relax_pseudo_transient(system, y, rest_diagonal(act), pt);
}

// The dynamic pull-out from rest in contact (`contact`: structure unknowns, zero velocity;
// with a film, at ambient pressure): the hold voltage bisected in [low, high] between one that
// lifts off (the smallest gap above g_c + 5 % g0) within `window` and one that holds.
inline DynamicPullOut dynamic_pull_out(CoarsePlate& plate, const std::vector<double>& contact,
                                       double low, double high, double tolerance, double window) {
  const std::unique_ptr<SwitchSystem> system = make_switch_system(plate.scene);
  const PullInSettings settings = read_pull_in_settings(plate.cf.root(), plate.scene);
  DynamicState drop;
  system->initial_state(0.0, drop.y, drop.yp);
  std::copy(contact.begin(), contact.end(), drop.y.begin());
  std::fill(drop.yp.begin(), drop.yp.end(), 0.0);
  ReleaseOptions r;
  r.window = window;
  r.lift = 0.05 * plate.act().initial_gap();
  return find_dynamic_pull_out(*system, plate.scene.control, drop, low, high, tolerance,
                               settings.run, r);
}

}  // namespace rfmems::test
