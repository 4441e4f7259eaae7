// A structural model as a case file describes it: the mesh, the operator M y'' + R(t, y) = 0
// (core/system_operator.hpp) and what a run reports about its state. Implemented by the
// continuum (plane stress/strain, 3D: physics/elasticity/elasticity_scene.hpp) and the
// Mindlin-Reissner plate (physics/plate/plate_scene.hpp); the analyses
// (structural_analysis.hpp), the result files (structural_results.hpp) and the coupled
// drivers see only this interface, so a case chooses its structure by name
// (model.structure: plane | solid3d | plate; structure_from_case.hpp).
#pragma once
#include <array>
#include <span>
#include <string>
#include <vector>

#include "core/system_operator.hpp"
#include "io/probes.hpp"
#include "io/result_writer.hpp"
#include "mesh/mesh.hpp"
#include "physics/structure/gap_element.hpp"

namespace rfmems {

enum class AnalysisType { Static, Transient, Modal, Harmonic };
// "static", "transient", "modal", "harmonic"
std::string to_string(AnalysisType type);

struct AnalysisSettings;
struct AnalysisStats;

class StructuralModel {
 public:
  virtual ~StructuralModel() = default;

  // "plane_stress", "plane_strain", "3d" or "plate".
  virtual std::string kind() const = 0;
  virtual const Mesh& structure_mesh() const = 0;
  virtual SecondOrderOperator& structure() = 0;
  const SecondOrderOperator& structure() const {
    return const_cast<StructuralModel*>(this)->structure();
  }
  // The time at which every load ramp has finished (0 without ramps): a static analysis is
  // solved there.
  virtual Real ramp_end_time() const = 0;

  // Components whose inertia a transient neglects (true: quasi-static). Empty: none. The
  // plate neglects its rotary inertia (core/reduced_inertia_system.hpp).
  virtual std::vector<bool> quasi_static_components() const { return {}; }

  // The static method's name for metadata ("newton" unless the model offers another).
  virtual std::string static_method() const { return "newton"; }
  // A static solve other than Newton with KINSOL (the elasticity's segregated method):
  // returns false if the model has none, else fills y and stats.
  virtual bool solve_static_otherwise(Real /*t*/, const AnalysisSettings& /*settings*/,
                                      std::vector<Real>& /*y*/, AnalysisStats& /*stats*/) {
    return false;
  }

  // Cell fields of a state (v empty for a static state) into the result file at one output.
  virtual void write_fields(ResultWriter& writer, int index, Real t, std::span<const Real> y,
                            std::span<const Real> v) const = 0;
  // What a probe records (three components, named by probe_components()): the
  // displacement for a continuum, (w, beta_x, beta_y) for a plate.
  virtual std::array<std::string, 3> probe_components() const = 0;
  virtual std::vector<Vec3> probe_values(const std::vector<Probe>& probes, Real t,
                                         std::span<const Real> y) const = 0;
  // The probe component a transient summary reports the largest |value| of (uy, or w).
  virtual int main_probe_component() const = 0;

  // The surface facing the electrode: a plate's cells (its mid-surface, w), or the faces of
  // the named boundary patch of a continuum (the displacement of their owner cell along the
  // last axis). InputError if the patch does not exist.
  virtual std::vector<GapElement> gap_elements(const std::string& patch) const = 0;
  // The unknown that moves cell c along the gap axis (a plate's w, a continuum's last
  // displacement component): what a switch controls and reports.
  virtual Index gap_unknown(Index cell) const = 0;
};

}  // namespace rfmems
