#include "coupling/switch_scene.hpp"

#include <fmt/format.h>

#include "coupling/squeeze_film_switch_system.hpp"
#include "io/probes.hpp"
#include "physics/structure/structure_from_case.hpp"

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

// `electrode` (one, default: everywhere) or `electrodes` (a list of non-overlapping ones).
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

// The squeeze film under a plate (see the header); null without one.
std::unique_ptr<ReynoldsFilm> read_gas(const CaseNode& root, const SwitchScene& s) {
  if (!root.has("gas")) return nullptr;
  const CaseNode gas = root.child("gas");
  // model: none switches the film off but still checks its keys (a case toggled by --set).
  const bool none = gas.get_choice("model", {"none", "reynolds"}) == "none";
  gas.require(none || s.structure->kind() == "plate", "model",
              "the Reynolds film needs a plate (model.structure: plate)");
  GasProperties g;
  g.ambient_pressure = none ? gas.get_quantity("pressure", Dimension::Pressure, 1.0, Range::positive())
                            : gas.get_quantity("pressure", Dimension::Pressure, Range::positive());
  g.viscosity = gas.get_quantity("viscosity", Dimension::Viscosity, g.viscosity, Range::positive());
  g.mean_free_path =
      gas.get_quantity("mean_free_path", Dimension::Length, g.mean_free_path, Range::positive());
  g.rarefaction = gas.get_choice("rarefaction", {"veijola", "none"}, "veijola") == "veijola"
                      ? Rarefaction::Veijola
                      : Rarefaction::None;
  const Mesh& mesh = s.structure->structure_mesh();
  const CaseNode bcs = root.child("boundaries");
  const CaseNode given = gas.child_or_empty("boundaries");
  for (const std::string& key : given.keys())
    if (mesh.find_patch(key) < 0) given.fail(key, "the mesh has no such patch");
  std::vector<FilmBoundary> film_bcs;
  for (const Patch& p : mesh.patches()) {
    const std::string structural = bcs.child(p.name).get_string("type");
    const std::string fallback = structural == "free" || structural == "load" ? "open" : "wall";
    const std::string kind = given.get_choice(p.name, {"open", "wall"}, fallback);
    film_bcs.push_back({kind == "open" ? FilmBoundary::Kind::Open : FilmBoundary::Kind::Wall});
  }
  if (none) return nullptr;
  return std::make_unique<ReynoldsFilm>(mesh, g, std::move(film_bcs));
}

}  // namespace

std::unique_ptr<SwitchSystem> SwitchScene::make_transient_system() const {
  if (!film) return std::make_unique<ActuatedStructureSystem>(*actuation, structure->quasi_static_components());
  std::vector<Index> w_dof;
  for (Index c = 0; c < film->size(); ++c) w_dof.push_back(3 * c);  // the plate's w
  return std::make_unique<SqueezeFilmSwitchSystem>(*actuation, structure->quasi_static_components(),
                                                   *film, std::move(w_dof));
}

SwitchScene build_switch_scene(const CaseNode& root, const std::string& case_dir,
                               AnalysisType analysis) {
  SwitchScene s;
  s.structure = build_structure(root, case_dir, analysis);
  const bool plate = s.structure->kind() == "plate";
  const Mesh& mesh = s.structure->structure_mesh();
  const CaseNode act = root.child("actuation");
  root.child("model").require(plate || mesh.dim() == 2, "structure",
                              "a switch is a plate or a plane (2D) beam");
  s.gap = act.get_quantity("gap", Dimension::Length, Range::positive());
  s.electrostatics = act.get_choice("electrostatics", {"parallel_plate", "laplace"},
                                    "parallel_plate") == "laplace"
                         ? ElectrostaticsModel::Laplace
                         : ElectrostaticsModel::ParallelPlate;
  act.require(!(plate && s.electrostatics == ElectrostaticsModel::Laplace), "electrostatics",
              "laplace needs a plane beam (model.structure: plane); a plate uses parallel_plate");
  s.electrodes = read_electrodes(act, plate);
  s.electrode = s.electrodes.front();
  act.require(s.electrodes.size() == 1 || s.electrostatics == ElectrostaticsModel::ParallelPlate,
              "electrodes", "laplace electrostatics take one electrode");
  if (!plate) {
    s.facing_patch = act.get_string("facing_patch", "bottom");
    act.require(mesh.find_patch(s.facing_patch) >= 0, "facing_patch", "the mesh has no such patch");
  }
  if (s.electrostatics == ElectrostaticsModel::Laplace)
    s.laplace_gap_cells = static_cast<int>(
        act.child_or_empty("laplace").get_int("gap_cells", 16, Range::closed(2, 10000)));

  ParallelPlateLaw law;
  if (act.has("dielectric")) {
    const CaseNode d = act.child("dielectric");
    law.dielectric_thickness = d.get_quantity("thickness", Dimension::Length, Range::non_negative());
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
  s.control = plate ? 3 * cell : 2 * cell + 1;  // w, or u_y

  const std::vector<GapElement> facing = s.structure->gap_elements(s.facing_patch);
  std::vector<GapElement> elements;
  for (const ElectrodeExtent& electrode : s.electrodes) {
    const std::vector<GapElement> over = elements_over_electrode(facing, electrode, plate);
    elements.insert(elements.end(), over.begin(), over.end());
  }
  act.require(!elements.empty(), "electrode", "no part of the structure lies over the electrode");
  s.actuation = std::make_unique<ParallelPlateActuation>(s.structure->structure(),
                                                         std::move(elements), s.gap, law);
  if (act.has("contact")) {
    const CaseNode c = act.child("contact");
    act.require(s.electrostatics == ElectrostaticsModel::ParallelPlate, "contact",
                "contact is modelled with the parallel-plate law only");
    s.contact.gap = c.get_quantity("gap", Dimension::Length, 0.02 * s.gap,
                                   Range::open(0.0, s.gap));
    s.contact.penetration = c.get_quantity("penetration", Dimension::Length, 0.1 * s.contact.gap,
                                           Range{0.0, 0.2 * s.contact.gap, true, false});
    s.actuation->set_contact(s.contact);
  }
  s.film = read_gas(root, s);
  return s;
}

}  // namespace rfmems
