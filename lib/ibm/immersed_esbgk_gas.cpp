#include "ibm/immersed_esbgk_gas.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "fv/face_graph.hpp"

namespace rfmems {

VelocityGrid ImmersedEsbgkSettings::velocity_grid() const {
  const int n = velocities;
  return VelocityGrid::uniform(n, n, n, velocity_extent * gas.thermal_speed(temperature));
}

GasState ImmersedEsbgkSettings::ambient() const {
  return {pressure / (gas.R * temperature), Vec3::Zero(), temperature};
}

ImmersedEsbgkGas::ImmersedEsbgkGas(const Mesh& background, ImmersedEsbgkSettings settings,
                                   Real substrate_y)
    : background_(background), settings_(std::move(settings)), substrate_y_(substrate_y) {
  settings_.options.ib.wall_temperature = settings_.temperature;
  settings_.options.comm = settings_.comm;
}

ImmersedEsbgkGas::~ImmersedEsbgkGas() = default;

Real ImmersedEsbgkGas::mean_free_path() const {
  // lambda = mu / p sqrt(pi R T / 2) (thesis eq. 5.30 family, as the Reynolds film's).
  const Real T = settings_.temperature;
  return settings_.gas.viscosity(T) / settings_.pressure *
         std::sqrt(M_PI * settings_.gas.R * T / 2);
}

void ImmersedEsbgkGas::track_gap(const ImmersedSurface& surface) {
  Real gap = 1e300;
  for (const Vec3& x : surface.vertices()) gap = std::min(gap, x.y() - substrate_y_);
  if (gap > 0) max_knudsen_ = std::max(max_knudsen_, mean_free_path() / gap);
}

void ImmersedEsbgkGas::reset(const ImmersedSurface& surface, Real /*t0*/) {
  const FaceGraph g = face_graph_of(background_);
  const Real T0 = settings_.temperature, p0 = settings_.pressure;
  std::vector<KineticBoundary> bcs(g.patch_names.size());
  for (std::size_t p = 0; p < g.patch_names.size(); ++p) {
    const std::string& name = g.patch_names[p];
    if (name == "electrode" || name == "substrate" || name == "left")
      bcs[p] = KineticBoundary::diffuse_wall(T0);
    else if (name == "top" || name == "right")
      bcs[p] = KineticBoundary::pressure_outlet(p0, T0);
    else
      throw InputError("esbgk gas: background patch '" + name + "' has no gas condition");
  }
  gas_ = std::make_unique<ImmersedKineticGas>(
      background_, std::move(bcs), settings_.velocity_grid(), settings_.gas, settings_.options);
  gas_->set_body(surface, std::vector<Vec3>(surface.n_segments(), Vec3::Zero()));
  gas_->initialize(settings_.ambient());
  stats_ = {};
  last_ = {};
  max_knudsen_ = 0;
  track_gap(surface);
}

void ImmersedEsbgkGas::save_checkpoint() {
  if (!gas_) throw InputError("esbgk gas: checkpoint before reset");
  gas_->save_checkpoint();
  saved_max_knudsen_ = max_knudsen_;
}

void ImmersedEsbgkGas::restore_checkpoint() {
  if (!gas_) throw InputError("esbgk gas: restore before reset");
  gas_->restore_checkpoint();
  max_knudsen_ = saved_max_knudsen_;
}

std::vector<Vec3> ImmersedEsbgkGas::advance(const ImmersedSurface& surface,
                                            std::span<const Vec3> segment_velocity, Real /*t*/,
                                            Real dt) {
  if (!gas_) throw InputError("esbgk gas: advance before reset");
  std::vector<Vec3> forces = gas_->step(surface, segment_velocity, dt, &last_);
  ++stats_.steps;
  stats_.sweeps += last_.sweeps;
  if (!last_.converged) ++stats_.unconverged;
  stats_.max_residual_ratio = std::max(stats_.max_residual_ratio, last_.residual_ratio);
  track_gap(surface);
  return forces;
}

}  // namespace rfmems
