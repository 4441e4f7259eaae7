// Reader of Gmsh meshes in MSH format 4.1, ASCII (what `gmsh -format msh41` writes).
//
// Read: $MeshFormat, $PhysicalNames, $Entities, $Nodes, $Elements; other sections are skipped.
// Cells are the first-order elements of the mesh dimension (2D: triangles and quads in the
// z = 0 plane; 3D: tetrahedra, hexahedra, prisms, pyramids). Elements one dimension lower
// that lie on an entity of a physical group become boundary faces of the patch named after
// the group ("physical_<tag>" if the group has no name). A 2D mesh drawn clockwise is
// reversed. Only nodes used by cells are kept, in file order.
//
// Errors: every problem with the file (missing, MSH 2.2 or binary, truncated, undefined node,
// higher-order element) is an InputError "<path>: <what>"; inverted cells are a MeshError.
#pragma once
#include <string>

#include "mesh/mesh.hpp"

namespace rfmems {

// dim = 0 takes the highest element dimension in the file; otherwise 2 or 3.
Mesh read_gmsh_mesh(const std::string& path, int dim = 0);

}  // namespace rfmems
