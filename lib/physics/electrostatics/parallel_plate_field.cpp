#include "physics/electrostatics/parallel_plate_field.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "io/case_schema_yaml.hpp"
#include "io/probes.hpp"

namespace rfmems {

namespace {

// [a, b] of an electrode extent key, with a < b.
void read_interval(const CaseNode& node, const std::string& key, Real& lo, Real& hi) {
  if (!node.has(key)) return;
  const std::vector<Real> v = node.get_quantities(key, Dimension::Length);
  node.require(v.size() == 2 && v[0] < v[1], key, "expected [begin, end] with begin < end");
  lo = v[0];
  hi = v[1];
}

ElectrodeExtent read_electrode(const CaseNode& e, bool plate) {
  ElectrodeExtent extent;
  read_interval(e, "x", extent.x_min, extent.x_max);
  read_interval(e, "y", extent.y_min, extent.y_max);
  e.require(plate || !e.has("y"), "y", "only a plate has an electrode extent in y");
  return extent;
}

bool overlap(const ElectrodeExtent& a, const ElectrodeExtent& b) {
  return a.x_min < b.x_max && b.x_min < a.x_max && a.y_min < b.y_max && b.y_min < a.y_max;
}

}  // namespace

std::vector<ElectrodeExtent> read_electrodes(const CaseNode& act, bool plate) {
  if (act.has("electrode")) {
    act.require(!act.has("electrodes"), "electrodes", "give either electrode or electrodes");
    return {read_electrode(act.child("electrode"), plate)};
  }
  if (!act.has("electrodes")) return {ElectrodeExtent{}};
  const CaseNode list = act.child("electrodes");
  act.require(list.size() >= 1, "electrodes", "expected a list of at least one electrode");
  std::vector<ElectrodeExtent> out;
  for (std::size_t i = 0; i < list.size(); ++i) {
    out.push_back(read_electrode(list.item(i), plate));
    for (std::size_t j = 0; j < i; ++j)
      if (overlap(out[j], out[i]))
        list.item(i).fail(fmt::format("overlaps electrode {} (an area would count twice)", j + 1));
  }
  return out;
}

ParallelPlateField read_parallel_plate_field(const CaseNode& act, StructuralModel& structure) {
  ParallelPlateField s;
  const bool plate = structure.kind() == "plate";
  const Mesh& mesh = structure.structure_mesh();
  s.gap = act.get_quantity("gap", Dimension::Length, Range::positive());
  s.electrodes = read_electrodes(act, plate);
  if (!plate) {
    s.facing_patch = act.get_string("facing_patch", "bottom");
    act.require(mesh.find_patch(s.facing_patch) >= 0, "facing_patch", "the mesh has no such patch");
  }
  ParallelPlateLaw law;
  if (act.has("dielectric")) {
    const CaseNode d = act.child("dielectric");
    law.dielectric_thickness =
        d.get_quantity("thickness", Dimension::Length, Range::non_negative());
    law.dielectric_permittivity = d.get_real("permittivity", Range{1.0, 1e4, false, false});
  }
  law.fringing_factor = act.get_real("fringing", 0.0, Range::closed(0.0, 10.0));
  if (law.fringing_factor > 0) {
    act.require(plate, "fringing", "the width of a plane beam is not modelled; use laplace");
    Real lo = 1e300, hi = -1e300;
    for (const Vec3& x : mesh.nodes()) {
      lo = std::min(lo, x.y());
      hi = std::max(hi, x.y());
    }
    law.width = hi - lo;
  }

  const CasePointFinder finder(mesh);
  const auto [point, cell] = finder.find(act, "control", "the control point");
  s.control_point = point;
  s.control_cell = cell;
  s.control = structure.gap_unknown(cell);

  const std::vector<GapElement> facing = structure.gap_elements(s.facing_patch);
  std::vector<GapElement> elements;
  for (const ElectrodeExtent& electrode : s.electrodes) {
    const std::vector<GapElement> over = elements_over_electrode(facing, electrode, plate);
    elements.insert(elements.end(), over.begin(), over.end());
  }
  act.require(!elements.empty(), "electrode", "no part of the structure lies over the electrode");
  s.actuation = std::make_unique<ParallelPlateActuation>(structure.structure(), std::move(elements),
                                                         s.gap, law);
  if (act.has("contact")) {
    const CaseNode c = act.child("contact");
    s.contact.gap = c.get_quantity("gap", Dimension::Length, 0.02 * s.gap, Range::open(0.0, s.gap));
    s.contact.penetration = c.get_quantity("penetration", Dimension::Length, 0.1 * s.contact.gap,
                                           Range{0.0, 0.2 * s.contact.gap, true, false});
    s.actuation->set_contact(s.contact);
  }
  return s;
}

CaseSchema parallel_plate_case_keys() {
  return embedded_case_schema("physics/electrostatics/parallel_plate_field.keys.yaml");
}

}  // namespace rfmems
