// The thesis's cantilever switch (Fig. 6.5) as a coarse immersed-boundary scene for the
// coupled immersed-boundary tests: the beam 45 um x 1.5 um, bottom 1.5 um above the electrode,
// clamped at x = 0 (the background's left wall); background 75 um x 10 um; electrode
// [0, electrode_end] on the bottom; plane stress, E = 200 GPa, nu = 0.3, rho = 8912 kg/m^3.
#pragma once
#include <memory>
#include <vector>

#include "coupling/field_coupled_structure.hpp"
#include "ibm/immersed_boundary_field.hpp"
#include "mesh/structured_mesh.hpp"

namespace rfmems::test {

constexpr Real um = 1e-6;
constexpr Real kGap = 1.5 * um, kLength = 45 * um, kThickness = 1.5 * um;

struct Cantilever {
  std::unique_ptr<Mesh> mesh;
  std::unique_ptr<ElasticityOperator> op;
  std::unique_ptr<ImmersedBoundaryField> scene;    // the field
  std::unique_ptr<FieldCoupledStructure> coupled;  // the beam coupled to it
  Cantilever(int bx, int by, int gx, int gy, Real electrode_end = kLength) {
    BoxSpec spec;
    spec.lower = Vec3(0, kGap, 0);
    spec.upper = Vec3(kLength, kGap + kThickness, 0);
    spec.n[0] = bx;
    spec.n[1] = by;
    mesh = std::make_unique<Mesh>(make_structured_mesh(spec));
    const LinearElastic steel{200e9, 0.3, 8912, Hypothesis::PlaneStress};
    std::vector<ElasticityBoundary> bcs(mesh->patches().size());
    bcs[mesh->find_patch("left")].kind = ElasticityBoundary::Kind::Fixed;
    op = std::make_unique<ElasticityOperator>(*mesh, steel, bcs);
    ImmersedBoundaryGeometry g;
    g.background_upper = Vec3(75 * um, 10 * um, 0);
    g.background_cells[0] = gx;
    g.background_cells[1] = gy;
    g.electrode_begin = 0;
    g.electrode_end = electrode_end;
    // The control: u_y at the tip's bottom corner, from the tip cell of the bottom row.
    scene = std::make_unique<ImmersedBoundaryField>(
        *op, g, op->displacement_functional(bx - 1, Vec3(kLength, kGap, 0), 1));
    coupled = std::make_unique<FieldCoupledStructure>(*op, *scene, scene->control());
  }
  void reset_times() {
    scene->reset_times();
    coupled->reset_times();
  }
};

inline DynamicOptions run_options(Real end_time, Real atol_fraction) {
  DynamicOptions o;
  o.end_time = end_time;
  o.contact_gap = 0.2 * kGap;
  o.ida.rtol = 1e-4;
  o.ida.atol = atol_fraction * kGap;
  o.ida.max_order = 2;
  o.coupling.scheme = CouplingScheme::Staggered;
  return o;
}

}  // namespace rfmems::test
