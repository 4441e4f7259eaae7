#include "coupling/immersed_field.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "ibm/immersed_reynolds_film.hpp"
#include "io/case_schema_yaml.hpp"
#include "io/input_solve.hpp"
#include "io/probes.hpp"
#include "physics/electrostatics/parallel_plate_field.hpp"
#include "physics/gas/ambient_gas.hpp"
#include "physics/gas/kinetic/equilibrium.hpp"
#include "physics/gas/kinetic/kinetic_case.hpp"

namespace rfmems {

namespace {

ImmersedGasSettings read_immersed_gas(const CaseNode& root, GasModel model) {
  ImmersedGasSettings s;
  s.model = model;
  const CaseNode gas = root.child_or_empty("gas");
  // Keys are read (and checked) even for none, so a case toggled by --set stays valid.
  const AmbientGas ambient = read_ambient_gas(gas, model != GasModel::None);
  s.film = ambient.film;
  // esbgk: the kinetic gas on the background (ibm/immersed_esbgk_gas.hpp), mu(T) from (T0, mu0).
  ImmersedEsbgkSettings& e = s.kinetic;
  e.gas.R = 287.05;
  e.gas.mu_ref = ambient.film.viscosity;
  e.gas.T_ref = ambient.temperature;
  e.gas.omega = ambient.omega;
  e.gas.model = gas.get_choice("collision", {"esbgk", "bgk"}, "esbgk") == "esbgk"
                    ? CollisionModel::Esbgk
                    : CollisionModel::Bgk;
  e.pressure = ambient.film.ambient_pressure;
  e.temperature = ambient.temperature;
  e.velocities = static_cast<int>(gas.get_int("velocities", 10, Range::closed(4, 40)));
  e.velocity_extent = gas.get_real("velocity_extent", 3.5, Range::closed(2.0, 8.0));
  // A 1e-5 step residual keeps the gas force within 0.4 % of a 1e-9 solve; the point-coupled
  // sweep and the predictor cut the sweeps 4x (docs/ibm.md, "Cheaper sweeps").
  e.options.step_tolerance = gas.get_real("step_tolerance", 1e-5, Range::closed(1e-14, 1e-1));
  const std::string smoother = gas.get_choice("smoother", {"point", "downwind", "both"}, "point");
  e.options.smoother = smoother == "point"      ? GasSmoother::PointCoupled
                       : smoother == "downwind" ? GasSmoother::Downwind
                                                : GasSmoother::Both;
  e.options.predictor = gas.get_bool("predictor", true);
  e.options.max_step_sweeps =
      static_cast<int>(gas.get_int("max_step_sweeps", 2000, Range::closed(1, 100000)));
  e.options.transport = read_transport_scheme(gas);
  // How a gas step is solved: sweeps to step_tolerance, or IDA over the step (variable-order
  // BDF at ida_rtol, GMRES with the arrowhead preconditioner of TransientKineticSystem).
  const bool ida = gas.get_choice("stepper", {"sweeps", "ida"}, "sweeps") == "ida";
  e.options.stepper = ida ? GasStepper::Ida : GasStepper::Sweeps;
  e.options.ida_rtol = gas.get_real("ida_rtol", 1e-6, Range::closed(1e-12, 1e-2));
  if (ida && model == GasModel::Esbgk)
    gas.require(Communicator::world().size() == 1, "stepper",
                "the IDA stepper runs on one rank (the sweeps distribute over ranks)");
  // The gas at rest at (p0, T0), and the walls at T0, need a discrete equilibrium on the grid:
  // one that does not exist is a grid too coarse for the state, bad input.
  if (model == GasModel::Esbgk)
    read_with_input_solves(
        gas, "the gas at rest has no discrete equilibrium on its velocity grid (gas.velocities)",
        [&] {
          const GasState rest = e.ambient();
          return equilibrium(maxwellian_target(rest.rho, rest.u, rest.T, e.gas), e.gas.model,
                             e.velocity_grid());
        });
  return s;
}

}  // namespace

std::unique_ptr<StructureGas> ImmersedField::make_gas() const {
  switch (gas.model) {
    case GasModel::None:
      return nullptr;
    case GasModel::Esbgk:
      return sw->surface_gas(std::make_unique<ImmersedEsbgkGas>(sw->background(), gas.kinetic,
                                                                geometry.background_lower.y()));
    case GasModel::Reynolds:
      break;
  }
  Real tip = -1e300;
  for (const Vec3& x : sw->rest_surface().vertices()) tip = std::max(tip, x.x());
  return sw->surface_gas(std::make_unique<ImmersedReynoldsFilm>(
      gas.film, sw->facing_segments(), geometry.background_lower.y(), geometry.background_lower.x(),
      tip));
}

std::unique_ptr<ImmersedField> read_immersed_field(const CaseNode& root, ElasticityScene& beam,
                                                   GasModel gas) {
  auto f = std::make_unique<ImmersedField>();
  const Mesh& mesh = *beam.mesh;
  root.child("model").require(mesh.dim() == 2, "structure",
                              "the immersed field needs a plane beam");
  const CaseNode act = root.child("actuation");
  act.require(!act.has("gap"), "gap",
              "the immersed field's gap is the beam's height above the background's bottom");
  const CaseNode im = act.child("immersed");
  const CaseNode bg = im.child("background");
  ImmersedBoundaryGeometry& g = f->geometry;
  g.background_lower = bg.get_vec3_quantity("lower", Dimension::Length);
  g.background_upper = bg.get_vec3_quantity("upper", Dimension::Length);
  bg.require(g.background_upper.x() > g.background_lower.x() &&
                 g.background_upper.y() > g.background_lower.y(),
             "upper", "must lie above and right of lower");
  const std::vector<Real> cells = bg.get_reals("cells");
  bg.require(cells.size() == 2 && cells[0] >= 4 && cells[1] >= 4 && cells[0] <= 4000 &&
                 cells[1] <= 4000 && cells[0] == std::floor(cells[0]) &&
                 cells[1] == std::floor(cells[1]),
             "cells", "expected [nx, ny], integers in [4, 4000]");
  g.background_cells[0] = static_cast<int>(cells[0]);
  g.background_cells[1] = static_cast<int>(cells[1]);
  // The electrode as every field reads it (parallel_plate_field.hpp), its x extent required.
  const CaseNode electrode = act.child("electrode");
  electrode.require(electrode.has("x"), "x", "the immersed field's electrode needs its extent");
  const ElectrodeExtent extent = read_electrodes(act, false).front();
  g.electrode_begin = extent.x_min;
  g.electrode_end = extent.x_max;
  g.anchor_patch = im.get_string("anchor_patch", "left");
  im.require(mesh.find_patch(g.anchor_patch) >= 0, "anchor_patch",
             "the beam mesh has no such patch");
  g.facing_patch = act.get_string("facing_patch", "bottom");
  act.require(mesh.find_patch(g.facing_patch) >= 0, "facing_patch",
              "the beam mesh has no such patch");
  g.anchor_extension =
      im.get_quantity("anchor_extension", Dimension::Length, 0.0, Range::non_negative());
  for (const Vec3& x : mesh.nodes())
    if (!(x.x() >= g.background_lower.x() - 1e-9 && x.x() <= g.background_upper.x() &&
          x.y() > g.background_lower.y() && x.y() < g.background_upper.y()))
      bg.fail("lower", fmt::format("the beam (node at [{:g}, {:g}] m) is not inside the background",
                                   x.x(), x.y()));
  const CasePointFinder finder(mesh);
  // The reported deflection is u_y at the control point itself (the tip), from its cell's
  // reconstruction, not at the cell's centroid half a cell short of it.
  const auto [control_point, control_cell] = finder.find(act, "control", "the control point");
  f->sw = std::make_unique<ImmersedBoundaryField>(
      *beam.op, g, beam.op->displacement_functional(control_cell, control_point, 1));
  if (immersed_electrostatics_distributed(root))
    f->sw->distribute_electrostatics(Communicator::world());
  f->gas = read_immersed_gas(root, gas);
  return f;
}

bool immersed_electrostatics_distributed(const CaseNode& root) {
  return root.child_or_empty("actuation")
      .child_or_empty("immersed")
      .get_bool("electrostatics_distributed", false);
}

CaseSchema immersed_case_keys() {
  CaseSchema own = embedded_case_schema("coupling/immersed_field.keys.yaml");
  add_transport_scheme_keys(own, "gas");
  return own;
}

}  // namespace rfmems
