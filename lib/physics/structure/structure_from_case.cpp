#include "physics/structure/structure_from_case.hpp"

#include "io/mesh_from_case.hpp"
#include "physics/elasticity/elasticity_scene.hpp"
#include "physics/plate/plate_scene.hpp"

namespace rfmems {

std::unique_ptr<StructuralModel> build_structure(const CaseNode& root, const std::string& case_dir,
                                                 AnalysisType analysis) {
  // The one reader of model.structure; absent, the continuum the mesh's dimension says.
  const CaseNode model = root.child("model");
  const std::string structure =
      model.has("structure") ? model.get_choice("structure", {"plane", "solid3d", "plate"}) : "";
  if (structure == "plate")
    return std::make_unique<PlateScene>(build_plate_scene(root, case_dir, analysis));
  return std::make_unique<ElasticityScene>(
      build_elasticity_scene(root, case_dir, analysis, structure));
}

CaseSchema structure_case_keys() {
  const CaseSchema own = {
      {"model",
       "the structural model",
       {
           {"structure", "choice", "(plane; solid3d on a 3D mesh)", "plane, solid3d, plate",
            "plane (2D continuum), solid3d (3D continuum) or plate (Mindlin-Reissner plate "
            "on a 2D mid-surface mesh)"},
           {"thickness", "length", "(required for a plate)", "> 0", "the plate's thickness"},
           {"shear_correction", "number", "0.8333333333333334", "in (0, 1]",
            "the plate's transverse shear correction factor (5/6)"},
           {"hypothesis", "choice", "(plane_stress; 3d on a 3D mesh)",
            "plane_stress, plane_strain, 3d", "the continuum's kinematic hypothesis"},
           {"stress", "choice", "coupled", "coupled, segregated",
            "continuum statics: one Newton solve of all components (coupled) or the "
            "component-by-component iteration (segregated)"},
           {"reconstruction", "choice", "(cubic for a plate; default: the continuum's own)",
            "default, linear, quadratic, cubic",
            "the polynomial degree of the face gradient reconstruction"},
           {"grid_damping", "number", "0.2", "in [0, 1]",
            "the continuum's damping of grid-scale (checkerboard) modes in transients"},
       }},
      {"material",
       "the structure's linear elastic material",
       {
           {"E", "pressure", kRequiredKey, "> 0", "Young's modulus"},
           {"nu", "number", kRequiredKey, "in (-1, 0.5)", "Poisson's ratio"},
           {"density", "density", "(required in time; else 0 kg/m^3)", "> 0", "mass density"},
       }},
      {"boundaries",
       "a condition on every patch of the mesh, by patch name",
       {
           {"<patch>", "section", kRequiredKey, "", "the condition on this patch"},
           {"<patch>.type", "choice", kRequiredKey,
            "fixed, traction, free, symmetry, pressure, clamped, simply_supported, "
            "simply_supported_soft, displacement, load",
            "continuum: fixed, traction, free, symmetry, pressure; plate: clamped, free, "
            "simply_supported (hard), simply_supported_soft, displacement, load"},
           {"<patch>.value", "vector of length", "(0 on every axis)", "",
            "continuum, fixed: the prescribed displacement"},
           {"<patch>.value", "vector of pressure", kRequiredKey, "",
            "continuum, traction: the traction vector"},
           {"<patch>.value", "pressure", kRequiredKey, "",
            "continuum, pressure: the pressure, pushing along the inward normal"},
           {"<patch>.w", "length", "(required for displacement; else 0 m)", "",
            "plate: the prescribed deflection"},
           {"<patch>.beta", "vector of dimensionless number", "([0, 0])", "",
            "plate: the prescribed rotations (x, y) in radians"},
           {"<patch>.shear", "force per length", "0 N/m", "",
            "plate, load: the shear force per unit edge length"},
           {"<patch>.moment", "vector of force", "([0, 0])", "",
            "plate, load: the bending moment (x, y) per unit edge length"},
           {"<patch>.ramp", "time", "0 s", ">= 0",
            "the value rises linearly from 0 over this time (0: at once)"},
       }},
      {"",
       "loads in the domain",
       {
           {"pressure", "section", "(none)", "", "plate: a uniform pressure along +z"},
           {"pressure.value", "pressure", kRequiredKey, "", "the pressure"},
           {"pressure.ramp", "time", "0 s", ">= 0", "rises linearly from 0 over this time"},
           {"point_loads", "section", "(none)", "", "plate: a list of point loads"},
           {"point_loads[].at", "vector of length", kRequiredKey, "",
            "the point; the load acts on the cell containing it"},
           {"point_loads[].force", "force", "0 N", "", "the force along +z"},
           {"point_loads[].moment", "vector of moment", "([0, 0])", "", "the moment (x, y)"},
           {"point_loads[].ramp", "time", "0 s", ">= 0", "rises linearly from 0 over this time"},
           {"body_force", "vector", "(none)", "",
            "continuum: a body force per unit volume [N/m^3], one component per axis"},
       }},
      {"solver.segregated",
       "the continuum's segregated static iteration (model.stress: segregated)",
       {
           {"diffusivity", "choice", "2mu+lambda", "mu, 2mu+lambda",
            "the implicit diffusion coefficient of each component's equation"},
           {"relaxation", "number", "1", "in (0, 1]", "under-relaxation of each iteration"},
       }},
  };
  return join_schemas({mesh_case_keys(), own});
}

}  // namespace rfmems
