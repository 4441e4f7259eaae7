#include "coupling/step_voltage_run.hpp"

#include <algorithm>

namespace rfmems {

void StepVoltageEvents::set_roots(IdaIntegrator& ida, Index n, LinearFunctional control,
                                  LinearFunctional velocity, Real contact_gap,
                                  std::function<Real(std::span<const Real>)> min_gap) const {
  ida.set_roots(1 + TurningBack::kRoots,
                [this, n, control = std::move(control), velocity = std::move(velocity), contact_gap,
                 min_gap = std::move(min_gap)](Real, std::span<const Real> yy,
                                               std::span<const Real>, std::span<Real> g) {
                  g[0] = min_gap(yy.subspan(0, n)) - contact_gap;
                  turning_.roots(control(yy), velocity(yy), g.subspan(1));
                });
}

bool StepVoltageEvents::after_step(const IdaIntegrator& ida, IdaIntegrator::Status status, Real t,
                                   Real control, DynamicRun& run) {
  run.extreme_control = std::min(run.extreme_control, control);
  bool stop = status == IdaIntegrator::Status::Reached;
  if (status == IdaIntegrator::Status::Root) {
    const std::vector<int> found = ida.roots_found();
    if (found[0] < 0) {
      ++run.touch_downs;
      run.pulled_in = true;
      run.pull_in_time = t;
      stop = true;
    } else if (turning_.at_root(t, control, found[1], found[2])) {
      run.turning_time = turning_.turning_time();
      stop = stop || stop_at_turning_;
    }
  }
  return stop;
}

bool StepVoltageEvents::after_record(const StepRecord& r, Real voltage, DynamicRun& run) {
  return ends_.at_step(r.t, voltage, r.control, r.velocity, r.gas_force, r.electrostatic_force,
                       run);
}

void finish_step_voltage_run(const IdaIntegrator& ida, const std::vector<StepRecord>& records,
                             Real voltage, Real output_interval, bool through_final_time,
                             DynamicRun& run) {
  run.final_time = ida.time();
  run.final_state = {ida.time(), std::vector<Real>(ida.y().begin(), ida.y().end()),
                     std::vector<Real>(ida.yp().begin(), ida.yp().end())};
  run.stats = ida.stats();

  auto sample = [&](const StepRecord& r) {
    DynamicSample s{r.t, r.control, r.min_gap, r.electrostatic_force, r.gas_force};
    s.voltage = voltage;
    return s;
  };
  if (output_interval <= 0) {
    for (const StepRecord& r : records) run.history.push_back(sample(r));
    return;
  }
  std::size_t j = 0;
  for (Real t = 0; through_final_time ? t <= run.final_time : t < run.final_time;
       t += output_interval) {
    while (j + 2 < records.size() && records[j + 1].t < t) ++j;
    const StepRecord& a = records[j];
    const StepRecord& b = records[std::min(j + 1, records.size() - 1)];
    const Real h = b.t - a.t;
    const Real s = h > 0 ? std::clamp((t - a.t) / h, 0.0, 1.0) : 0.0;
    const Real h00 = 2 * s * s * s - 3 * s * s + 1, h10 = s * s * s - 2 * s * s + s;
    const Real h01 = -2 * s * s * s + 3 * s * s, h11 = s * s * s - s * s;
    run.history.push_back(
        sample({t, h00 * a.control + h10 * h * a.velocity + h01 * b.control + h11 * h * b.velocity,
                0, (1 - s) * a.min_gap + s * b.min_gap,
                (1 - s) * a.electrostatic_force + s * b.electrostatic_force,
                (1 - s) * a.gas_force + s * b.gas_force}));
  }
  run.history.push_back(sample(records.back()));
}

}  // namespace rfmems
