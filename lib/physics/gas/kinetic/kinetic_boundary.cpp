#include "physics/gas/kinetic/kinetic_boundary.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/error.hpp"
#include "io/case_file.hpp"
#include "io/case_schema_yaml.hpp"
#include "physics/gas/kinetic/equilibrium.hpp"

namespace rfmems {

const char* kinetic_boundary_kind_name(KineticBoundaryKind kind) {
  switch (kind) {
    case KineticBoundaryKind::DiffuseWall:
      return "diffuse_wall";
    case KineticBoundaryKind::SpecularWall:
      return "specular_wall";
    case KineticBoundaryKind::Pressure:
      return "pressure";
    case KineticBoundaryKind::Symmetry:
      return "symmetry";
    case KineticBoundaryKind::Periodic:
      return "periodic";
    case KineticBoundaryKind::External:
      return "external";
  }
  return "?";
}

KineticBoundary KineticBoundary::diffuse_wall(Real T, const Vec3& velocity, Real accommodation) {
  KineticBoundary b;
  b.kind = KineticBoundaryKind::DiffuseWall;
  b.temperature = T;
  b.velocity = velocity;
  b.accommodation = accommodation;
  return b;
}

KineticBoundary KineticBoundary::specular_wall() { return {}; }

KineticBoundary KineticBoundary::symmetry() {
  KineticBoundary b;
  b.kind = KineticBoundaryKind::Symmetry;
  return b;
}

KineticBoundary KineticBoundary::pressure_outlet(Real p, Real T) {
  KineticBoundary b;
  b.kind = KineticBoundaryKind::Pressure;
  b.pressure = p;
  b.temperature = T;
  return b;
}

KineticBoundary KineticBoundary::periodic(const std::string& partner) {
  KineticBoundary b;
  b.kind = KineticBoundaryKind::Periodic;
  b.partner = partner;
  return b;
}

KineticBoundary KineticBoundary::external() {
  KineticBoundary b;
  b.kind = KineticBoundaryKind::External;
  return b;
}

bool KineticBoundary::needs_reflection() const {
  return kind == KineticBoundaryKind::SpecularWall || kind == KineticBoundaryKind::Symmetry ||
         (kind == KineticBoundaryKind::DiffuseWall && accommodation < 1);
}

std::vector<KineticBoundary> kinetic_boundaries_from_case(const CaseNode& boundaries,
                                                          const FaceGraph& graph) {
  std::vector<KineticBoundary> out(graph.patch_names.size());
  std::vector<bool> seen(graph.patch_names.size(), false);
  for (const std::string& name : boundaries.keys()) {
    const int p = graph.find_patch(name);
    if (p < 0) {
      std::string known;
      for (const auto& n : graph.patch_names) known += (known.empty() ? "" : ", ") + n;
      boundaries.fail(name, "no such patch (patches: " + known + ")");
    }
    const CaseNode node = boundaries.child(name);
    const std::string type = node.get_choice(
        "type", {"diffuse_wall", "specular_wall", "pressure", "symmetry", "periodic"});
    KineticBoundary& b = out[p];
    if (type == "diffuse_wall") {
      b = KineticBoundary::diffuse_wall(
          node.get_quantity("T", Dimension::Temperature, Range::positive()),
          node.has("velocity") ? node.get_vec3_quantity("velocity", Dimension::Velocity)
                               : Vec3::Zero(),
          node.get_real("accommodation", 1.0, Range::closed(0, 1)));
    } else if (type == "specular_wall") {
      b = KineticBoundary::specular_wall();
    } else if (type == "symmetry") {
      b = KineticBoundary::symmetry();
    } else if (type == "periodic") {
      const std::string partner = node.get_string("partner");
      if (graph.find_patch(partner) < 0 || partner == name)
        node.fail("partner", "'" + partner + "' is not another patch of the mesh");
      b = KineticBoundary::periodic(partner);
    } else {
      b = KineticBoundary::pressure_outlet(
          node.get_quantity("p", Dimension::Pressure, Range::positive()),
          node.get_quantity("T", Dimension::Temperature, Range::positive()));
    }
    seen[p] = true;
  }
  for (std::size_t p = 0; p < seen.size(); ++p)
    if (!seen[p]) boundaries.fail(graph.patch_names[p], "missing boundary condition for patch");
  for (std::size_t p = 0; p < out.size(); ++p) {
    if (out[p].kind != KineticBoundaryKind::Periodic) continue;
    const KineticBoundary& q = out[graph.find_patch(out[p].partner)];
    if (q.kind != KineticBoundaryKind::Periodic || q.partner != graph.patch_names[p])
      boundaries.child(graph.patch_names[p])
          .fail("partner", "'" + out[p].partner + "' must be periodic with partner '" +
                               graph.patch_names[p] + "'");
  }
  return out;
}

std::vector<Real> boundary_maxwellian(const KineticBoundary& bc, const VelocityGrid& grid,
                                      const KineticGas& gas) {
  std::vector<Real> m;
  if (bc.kind == KineticBoundaryKind::DiffuseWall) {
    m.resize(grid.size());
    const EquilibriumCoefficients a =
        equilibrium(maxwellian_target(1.0, bc.velocity, bc.temperature, gas), gas.model, grid);
    evaluate_equilibrium(a, grid, m);
  } else if (bc.kind == KineticBoundaryKind::Pressure) {
    m.resize(grid.size());
    const Real rho = bc.pressure / (gas.R * bc.temperature);
    const EquilibriumCoefficients a =
        equilibrium(maxwellian_target(rho, Vec3::Zero(), bc.temperature, gas), gas.model, grid);
    evaluate_equilibrium(a, grid, m);
  }
  return m;
}

void fill_boundary_face(const KineticBoundary& bc, const Vec3& area, std::span<const Real> f_owner,
                        const VelocityGrid& grid, std::span<const Index> reflection,
                        std::span<const Real> maxwellian, std::span<Real> f_face) {
  const Index n = grid.size();
  switch (bc.kind) {
    case KineticBoundaryKind::External:
      throw std::logic_error("fill_boundary_face: an external condition has no local rule");
    case KineticBoundaryKind::Periodic:
      throw std::logic_error("fill_boundary_face: a periodic face takes its partner's values");
    case KineticBoundaryKind::SpecularWall:
    case KineticBoundaryKind::Symmetry:
      for (Index k = 0; k < n; ++k)
        f_face[k] = grid.c[k].dot(area) >= 0 ? f_owner[k] : f_owner[reflection[k]];
      return;
    case KineticBoundaryKind::Pressure:
      for (Index k = 0; k < n; ++k)
        f_face[k] = grid.c[k].dot(area) >= 0 ? f_owner[k] : maxwellian[k];
      return;
    case KineticBoundaryKind::DiffuseWall: {
      const Real sigma = bc.accommodation;
      // Mass flux, relative to the wall ((c - u_w) . S), of the outgoing and specularly
      // reflected values and of the unit-density wall Maxwellian over the incoming ordinates.
      // The wall is impermeable in its own frame: the net flux through the (fixed) face is
      // rho_face u_w . S, the gas a normally moving wall pushes or draws (squeeze film).
      const Real wall_flux = bc.velocity.dot(area);
      Real flux_known = 0, flux_maxwellian = 0;
      for (Index k = 0; k < n; ++k) {
        const Real cn = grid.c[k].dot(area);
        const Real relative = (cn - wall_flux) * grid.w[k];
        if (cn >= 0) {
          f_face[k] = f_owner[k];
          flux_known += relative * f_owner[k];
        } else {
          flux_maxwellian += relative * maxwellian[k];
          if (sigma < 1) flux_known += (1 - sigma) * relative * f_owner[reflection[k]];
        }
      }
      // sigma n_w flux_maxwellian + flux_known = 0.
      const Real n_w = sigma > 0 ? -flux_known / (sigma * flux_maxwellian) : 0.0;
      for (Index k = 0; k < n; ++k) {
        if (grid.c[k].dot(area) >= 0) continue;
        Real v = sigma * n_w * maxwellian[k];
        if (sigma < 1) v += (1 - sigma) * f_owner[reflection[k]];
        f_face[k] = v;
      }
      return;
    }
  }
}

CaseSchema kinetic_boundary_case_keys() {
  return embedded_case_schema("physics/gas/kinetic/kinetic_boundary.keys.yaml");
}

}  // namespace rfmems
