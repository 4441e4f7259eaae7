// The `mesh:` section of a case file, turned into a Mesh.
//
//   mesh:                              # structured quads (rectangle) or hexahedra (box)
//     type: rectangle                  # rectangle | box | gmsh
//     lower: [0 m, -0.02 m]            # optional, default zeros
//     size: [2 m, 0.04 m]              # lengths, 2 entries (rectangle) or 3 (box)
//     cells: [160, 16]                 # cells per axis
//     grading: [1, 1]                  # optional: last/first cell size per axis
//
//   mesh: {type: gmsh, file: plate_with_hole.geo, parameters: {h: 0.1}, dim: 2}
//     .geo: meshed at run time by gmsh (each parameter passed as -setnumber) in a scratch
//           directory that is removed afterwards; `dim` (2 or 3, default 2) is the mesh
//           dimension. .msh: read directly (MSH 4.1 ASCII; `dim` default: the highest
//           element dimension in the file). A relative `file` is relative to the case file.
//
// Patch names: rectangle left/right/bottom/top, box also back/front (mesh/structured_mesh.hpp);
// gmsh: the physical group names.
//
// Errors are InputErrors naming the case file and key. A problem with the mesh file itself
// (missing, malformed, inverted cells) keeps its type (MeshError stays MeshError) and its
// message, which names the mesh file, prefixed with the case file and key 'mesh.file'.
#pragma once
#include <string>

#include "io/case_file.hpp"
#include "mesh/mesh.hpp"

namespace rfmems {

// case_dir: the directory of the case file (relative mesh files are looked up there).
Mesh mesh_from_case(const CaseNode& mesh_node, const std::string& case_dir);

// The keys mesh_from_case reads (mesh_from_case.keys.yaml; io/case_schema.hpp).
CaseSchema mesh_case_keys();

}  // namespace rfmems
