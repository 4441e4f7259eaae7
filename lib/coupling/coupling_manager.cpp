#include "coupling/coupling_manager.hpp"

#include <fmt/format.h>

#include "core/error.hpp"
#include "coupling/field_coupled_structure.hpp"
#include "physics/elasticity/elasticity_scene.hpp"
#include "physics/electrostatics/parallel_plate_gap_field.hpp"
#include "physics/gas/film_under_structure.hpp"

namespace rfmems {

namespace {

// A field that takes a step voltage only (its runs hold V from t = 0).
Real step_amplitude(const VoltageWaveform& waveform, Real amplitude, const DynamicState* start,
                    const char* field) {
  if (waveform.kind != VoltageWaveform::Kind::Step || start)
    throw InputError(fmt::format("the {} field runs a step voltage from rest only", field));
  return amplitude;
}

// The parallel-plate law: structure, force (and film) with exact Jacobian blocks in one
// monolithic system; or the film split from the actuated structure (the partitioned schemes, in
// the field-coupled structure's loop).
class ParallelPlateManager : public CouplingManager {
 public:
  explicit ParallelPlateManager(SwitchScene& scene)
      : scene_(scene),
        system_(make_switch_system(scene)),
        film_unknowns_(film_unknowns(scene)),
        field_(*scene.actuation),
        partitioned_({*scene.actuation, scene.structure->quasi_static_components(), film_unknowns_},
                     field_, LinearFunctional::unknown(scene.control)) {}

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
    if (!scene_.film)
      throw InputError("a partitioned scheme splits the film from the plate: the scene has none");
    const Real v = step_amplitude(waveform, amplitude, start, "partitioned parallel_plate");
    scene_.actuation->set_voltage_squared([v](Real) { return v * v; });
    FilmUnderStructure film(*scene_.film, film_unknowns_, scene_.actuation->size(),
                            scene_.actuation->initial_gap());
    return partitioned_.run(v, options, &film);
  }
  SwitchSystem* switch_system() override { return system_.get(); }
  Json counters() const override {
    if (partitioned_.times().structure_steps == 0) return Json::object();
    Json j = partitioned_.times().json();
    j["gas_max_knudsen"] = partitioned_.times().gas_max_knudsen;
    return j;
  }

 private:
  SwitchScene& scene_;
  std::unique_ptr<SwitchSystem> system_;
  std::vector<Index> film_unknowns_;  // the plate's unknown over each film cell
  ParallelPlateGapField field_;
  FieldCoupledStructure partitioned_;
};

// A field that gives no exact Jacobian blocks (the Laplace field in the gap mesh that follows a
// plane beam, the immersed-boundary field and its gas on the background): the field-coupled
// beam's fixed points and time loop.
class LaggedFieldManager : public CouplingManager {
 public:
  LaggedFieldManager(SwitchScene& scene, GapField& field, LinearFunctional control,
                     std::function<std::unique_ptr<StructureGas>()> make_gas = {})
      : field_(field),
        beam_(*dynamic_cast<ElasticityScene&>(*scene.structure).op, field, std::move(control)),
        make_gas_(std::move(make_gas)) {}

  QuasiStaticPullIn quasi_static(const QuasiStaticOptions& options) override {
    QuasiStaticPullIn r = beam_.trace_quasi_static(options);
    static_solves_ += r.solves;
    return r;
  }
  SwitchStatic solve_static(Real voltage) override {
    StructureEquilibrium r = beam_.solve_static(voltage);
    static_solves_ += r.iterations;
    return {std::move(r.u), r.control, r.iterations};
  }
  DynamicRun run(const VoltageWaveform& waveform, Real amplitude, const DynamicOptions& options,
                 const DynamicState* start) override {
    const Real v = step_amplitude(waveform, amplitude, start, field_.name().c_str());
    std::unique_ptr<StructureGas> gas = make_gas_ ? make_gas_() : nullptr;  // at rest
    return beam_.run(v, options, gas.get());
  }
  Json counters() const override {
    Json j = field_.counters();
    j.update(beam_.times().json());
    j["static_field_solves"] = static_solves_;
    if (make_gas_) j["gas_max_knudsen"] = beam_.times().gas_max_knudsen;
    return j;
  }

 private:
  GapField& field_;
  FieldCoupledStructure beam_;
  std::function<std::unique_ptr<StructureGas>()> make_gas_;
  long static_solves_ = 0;
};

}  // namespace

std::unique_ptr<CouplingManager> make_coupling_manager(SwitchScene& scene) {
  switch (scene.field()) {
    case FieldModel::Laplace:
      return std::make_unique<LaggedFieldManager>(scene, *scene.laplace,
                                                  LinearFunctional::unknown(scene.control));
    case FieldModel::Immersed: {
      const ImmersedField& immersed = *scene.immersed;
      return std::make_unique<LaggedFieldManager>(scene, *immersed.sw, immersed.sw->control(),
                                                  [&immersed] { return immersed.make_gas(); });
    }
    case FieldModel::ParallelPlate:
      break;
  }
  return std::make_unique<ParallelPlateManager>(scene);
}

}  // namespace rfmems
