// Reading a creep case (keys in the header): the plate scene and the switch's actuation are
// read by the code the other drivers use (structure_from_case, read_parallel_plate_field); this
// file adds the creep law, the run settings and the hold voltage.
#include "physics/creep/creep_case.hpp"

#include <fmt/format.h>

#include <cmath>

#include "io/case_schema_yaml.hpp"
#include "io/units.hpp"
#include "physics/electrostatics/parallel_plate_field.hpp"
#include "physics/structure/structure_from_case.hpp"

namespace rfmems {

namespace {

// "<number> h" / "<number> d" -> seconds; false if the text has neither unit.
bool parse_long_duration(std::string text, Real& seconds) {
  while (!text.empty() && text.back() == ' ') text.pop_back();
  Real factor = 0;
  if (text.ends_with("h")) factor = 3600;
  if (text.ends_with("d")) factor = 86400;
  if (factor == 0) return false;
  text.pop_back();
  while (!text.empty() && text.back() == ' ') text.pop_back();
  Real x = 0;
  if (!parse_real(text, x)) return false;
  seconds = x * factor;
  return true;
}

CreepLaw read_law(const CaseNode& creep) {
  const CaseNode law = creep.child("law");
  CreepLaw l;
  l.A = law.get_quantity("A", Dimension::Frequency, Range::non_negative());
  l.B = law.get_real("B", Range::non_negative());
  l.m = law.get_real("m", Range{1.0, 20.0, false, false});
  l.n = law.get_real("n", Range::closed(0.0, 20.0));
  l.sigma_y0 = law.get_quantity("sigma_y0", Dimension::Pressure, Range::positive());
  return l;
}

CreepRunSettings read_settings(const CaseNode& creep) {
  CreepRunSettings s;
  s.integration =
      creep.get_choice("integration", {"implicit", "explicit"}, "implicit") == "explicit"
          ? CreepRunSettings::Integration::Explicit
          : CreepRunSettings::Integration::Implicit;
  if (s.integration == CreepRunSettings::Integration::Explicit) {
    s.explicit_dt = read_duration(creep, "dt");
    creep.require(s.explicit_dt > 0, "dt", "must be > 0");
  } else {
    creep.require(!creep.has("dt"), "dt", "a time step is for integration: explicit");
  }
  s.rtol = creep.get_real("rtol", 1e-6, Range{1e-12, 1e-1, false, false});
  s.atol = creep.get_real("atol", 1e-12, Range{1e-20, 1.0, false, false});
  const Real end = read_duration(creep, "end_time");
  creep.require(end > 0, "end_time", "must be > 0");
  const long outputs = creep.get_int("outputs", 50, Range::closed(1, 100000));
  for (long k = 1; k <= outputs; ++k)
    s.output_times.push_back(k == outputs ? end : end * static_cast<Real>(k) / outputs);
  const CaseNode cp = creep.child_or_empty("checkpoint");
  s.checkpoint_every_steps = cp.get_int("every_steps", 0, Range::non_negative());
  s.checkpoint_every_seconds = cp.get_real("every_seconds", 0.0, Range::non_negative());
  return s;
}

}  // namespace

Real read_duration(const CaseNode& node, const std::string& key) {
  Real seconds = 0;
  if (parse_long_duration(node.get_string(key), seconds)) {
    node.require(std::isfinite(seconds) && seconds >= 0, key, "must be a time >= 0");
    return seconds;
  }
  return node.get_quantity(key, Dimension::Time, Range::non_negative());
}

Real read_duration(const CaseNode& node, const std::string& key, Real default_value) {
  return node.has(key) ? read_duration(node, key) : default_value;
}

CreepCase read_creep_case(const CaseNode& root, const std::string& case_dir) {
  CreepCase c;
  const CaseNode model = root.child("model");
  root.require(!root.has("gas"), "gas", "a creep run is quasi-static: no squeeze film");
  root.require(!root.has("analysis"), "analysis", "rfmems-creep runs a creep analysis; remove it");

  c.structure = build_structure(root, case_dir, AnalysisType::Static);
  if (root.has("actuation")) {
    // The hold voltage's field: the parallel-plate law the pull-in study uses.
    const CaseNode act = root.child("actuation");
    act.get_choice("electrostatics", {"parallel_plate"}, "parallel_plate");
    act.require(!act.has("contact"), "contact", "a creep run holds the plate off the dielectric");
    const ParallelPlateField field = read_parallel_plate_field(act, *c.structure);
    c.has_gap = true;
    c.gap_elements = field.actuation->elements();
    c.initial_gap = field.gap;
    c.gap_law = field.actuation->law();
    const Real voltage =
        act.get_quantity("voltage", Dimension::Voltage, 0.0, Range::non_negative());
    if (voltage > 0) c.hold = CreepHoldVoltage{c.gap_elements, c.initial_gap, c.gap_law, voltage};
    if (!root.has("probes")) {
      Probe control;
      control.name = "control";
      control.at = field.control_point;
      control.cell = field.control_cell;
      c.probes.push_back(control);
    }
  }
  c.plate = dynamic_cast<PlateScene*>(c.structure.get());
  if (c.plate == nullptr)
    model.fail("structure", "creep runs need a plate (model.structure: plate)");
  if (root.has("probes")) c.probes = read_probes(root.child("probes"), *c.plate->mesh);

  const CaseNode creep = root.child("creep");
  c.law = read_law(creep);
  const long points = creep.get_int("thickness_points", 21, Range::closed(3, 401));
  creep.require(points % 2 == 1, "thickness_points", "must be odd (Simpson's rule)");
  c.thickness_intervals = static_cast<int>(points - 1);
  c.shear_creep = creep.get_bool("shear_creep", false);
  creep.require(!(c.shear_creep && c.plate->von_karman), "shear_creep",
                "not with model.geometric_nonlinearity (the transverse shear creep is the linear "
                "plate's only)");
  c.settings = read_settings(creep);

  const bool lifetime = creep.has("lifetime");
  const CaseNode life = creep.child_or_empty("lifetime");
  if (lifetime) creep.require(c.has_gap, "lifetime", "needs a gap (the actuation section)");
  if (life.has("gap_threshold")) {
    c.settings.gap_threshold_event = true;
    c.settings.gap_threshold =
        life.get_quantity("gap_threshold", Dimension::Length, Range::non_negative());
    life.require(c.settings.gap_threshold < c.initial_gap, "gap_threshold",
                 "must be below the initial gap actuation.gap");
  }
  c.settings.collapse_event = c.has_gap && life.get_bool("collapse", c.hold.has_value());
  c.settings.collapse_fraction = life.get_real("collapse_fraction", 1e-3, Range::open(0.0, 1.0));
  return c;
}

CaseSchema creep_case_keys() {
  return join_schemas({structure_case_keys(), parallel_plate_case_keys(),
                       embedded_case_schema("physics/creep/creep_case.keys.yaml"),
                       probes_case_keys()});
}

}  // namespace rfmems
