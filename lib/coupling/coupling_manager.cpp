#include "coupling/coupling_manager.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "core/error.hpp"
#include "coupling/laplace_dynamic_switch.hpp"
#include "coupling/laplace_pull_in.hpp"
#include "coupling/partitioned_switch.hpp"
#include "physics/elasticity/elasticity_scene.hpp"

namespace rfmems {

namespace {

// A field that takes a step voltage only (its runs hold V from t = 0).
Real step_amplitude(const VoltageWaveform& waveform, Real amplitude, const DynamicState* start,
                    const char* field) {
  if (waveform.kind != VoltageWaveform::Kind::Step || start)
    throw InputError(fmt::format("the {} field runs a step voltage from rest only", field));
  return amplitude;
}

// The parallel-plate law: structure, force (and film) with exact Jacobian blocks.
class ParallelPlateManager : public CouplingManager {
 public:
  explicit ParallelPlateManager(SwitchScene& scene)
      : scene_(scene), w_dof_(film_unknowns(scene)), system_(make_switch_system(scene)) {}

  QuasiStaticPullIn quasi_static(const QuasiStaticOptions& options) override {
    return trace_pull_in(*scene_.actuation, scene_.control, options);
  }
  SwitchStatic solve_static(Real) override {
    throw InputError("the parallel-plate field traces its equilibria (quasi_static)");
  }
  DynamicRun run(const VoltageWaveform& waveform, Real amplitude, const DynamicOptions& options,
                 const DynamicState* start) override {
    if (options.coupling.scheme == CouplingScheme::Monolithic)
      return run_dynamic(*system_, scene_.control, waveform.at(amplitude), options, start);
    if (!scene_.film || start)
      throw InputError("a partitioned scheme splits the film from the plate, from rest");
    PartitionedRun r =
        run_partitioned(*scene_.actuation, scene_.structure->quasi_static_components(),
                        *scene_.film, w_dof_, scene_.control, waveform.at(amplitude), options);
    coupling_iterations_ += r.coupling_iterations;
    macro_steps_ += r.macro_steps;
    return std::move(r.run);
  }
  SwitchSystem* switch_system() override { return system_.get(); }
  Json counters() const override {
    if (macro_steps_ == 0) return Json::object();
    return {{"macro_steps", macro_steps_}, {"coupling_iterations", coupling_iterations_}};
  }

 private:
  SwitchScene& scene_;
  std::vector<Index> w_dof_;
  std::unique_ptr<SwitchSystem> system_;
  long coupling_iterations_ = 0, macro_steps_ = 0;
};

// The Laplace field in the gap mesh that follows a plane beam.
class LaplaceManager : public CouplingManager {
 public:
  explicit LaplaceManager(SwitchScene& scene)
      : scene_(scene), beam_(dynamic_cast<ElasticityScene&>(*scene.structure)) {
    LaplaceGapOptions gap;
    gap.gap_cells = scene.laplace_gap_cells;
    switch_ = std::make_unique<LaplaceDynamicSwitch>(*beam_.op, scene.facing_patch, scene.gap,
                                                     scene.electrodes.front(), scene.control, gap);
  }

  QuasiStaticPullIn quasi_static(const QuasiStaticOptions& options) override {
    LaplacePullInOptions o;
    o.sampling = options;
    o.gap_cells = scene_.laplace_gap_cells;
    LaplacePullIn r = trace_pull_in_laplace(beam_, scene_.facing_patch, scene_.gap,
                                            scene_.electrodes.front(), scene_.control, o);
    static_solves_ += r.coupling_iterations;
    return std::move(r.result);
  }
  SwitchStatic solve_static(Real voltage) override {
    LaplaceStatic r = switch_->solve_static(voltage);
    return {std::move(r.u), r.control, r.iterations};
  }
  DynamicRun run(const VoltageWaveform& waveform, Real amplitude, const DynamicOptions& options,
                 const DynamicState* start) override {
    return switch_->run(step_amplitude(waveform, amplitude, start, "laplace"), options);
  }
  Json counters() const override {
    const LaplaceSwitchTimes& t = switch_->times();
    return {{"static_field_solves", static_solves_},
            {"field_solves", t.field_solves},
            {"move_s", t.move},
            {"field_s", t.field},
            {"structure_s", t.structure},
            {"structure_steps", t.structure_steps}};
  }

 private:
  SwitchScene& scene_;
  ElasticityScene& beam_;
  std::unique_ptr<LaplaceDynamicSwitch> switch_;
  long static_solves_ = 0;
};

// The immersed-boundary field and its gas on the background.
class ImmersedManager : public CouplingManager {
 public:
  explicit ImmersedManager(SwitchScene& scene) : field_(*scene.immersed) {}

  QuasiStaticPullIn quasi_static(const QuasiStaticOptions& options) override {
    return field_.sw->trace_quasi_static(options);
  }
  SwitchStatic solve_static(Real voltage) override {
    ImmersedStatic r = field_.sw->solve_static(voltage);
    return {std::move(r.u), r.control, r.iterations};
  }
  DynamicRun run(const VoltageWaveform& waveform, Real amplitude, const DynamicOptions& options,
                 const DynamicState* start) override {
    const Real v = step_amplitude(waveform, amplitude, start, "immersed");
    std::unique_ptr<ImmersedGasModel> gas = field_.make_gas();  // at rest
    DynamicRun r = field_.sw->run(v, options, gas.get());
    if (gas) max_knudsen_ = std::max(max_knudsen_, gas->max_knudsen());
    return r;
  }
  Json counters() const override {
    const ImmersedPhysicsTimes& t = field_.sw->times();
    return {{"move_s", t.move},
            {"marking_s", t.marking},
            {"interpolation_s", t.interpolation},
            {"electrostatics_s", t.electrostatics},
            {"transfer_s", t.transfer},
            {"gas_s", t.gas},
            {"structure_s", t.structure},
            {"load_evaluations", t.load_evaluations},
            {"electrostatic_analyses", t.electrostatic_analyses},
            {"electrostatic_krylov_iterations", t.electrostatic_krylov_iterations},
            {"coupling_iterations", t.coupling_iterations},
            {"max_coupling_iterations", t.max_coupling_iterations},
            {"unconverged_coupling_steps", t.unconverged_steps},
            {"max_coupling_residual", t.max_coupling_residual},
            {"structure_steps", t.structure_steps},
            {"gas_steps", t.gas_steps},
            {"gas_max_knudsen", max_knudsen_}};
  }

 private:
  ImmersedField& field_;
  Real max_knudsen_ = 0;
};

}  // namespace

std::unique_ptr<CouplingManager> make_coupling_manager(SwitchScene& scene) {
  switch (scene.field()) {
    case FieldModel::Laplace:
      return std::make_unique<LaplaceManager>(scene);
    case FieldModel::Immersed:
      return std::make_unique<ImmersedManager>(scene);
    case FieldModel::ParallelPlate:
      break;
  }
  return std::make_unique<ParallelPlateManager>(scene);
}

}  // namespace rfmems
