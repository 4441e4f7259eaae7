// Runs the gmsh executable on a .geo file to write a mesh in MSH 4.1 ASCII, so that tests and
// drivers make their meshes from the committed .geo at run time.
#pragma once
#include <map>
#include <string>

namespace rfmems {

// Meshes `geo_path` in dimension `dim` (2 or 3), passing each entry of `numbers` as
// `-setnumber name value`, and writes `out_msh_path` (its directory is created if missing).
// Returns out_msh_path. Throws InputError if gmsh fails or writes no file; the message carries
// gmsh's first error line.
std::string generate_gmsh_mesh(const std::string& geo_path,
                               const std::map<std::string, double>& numbers,
                               const std::string& out_msh_path, int dim);

}  // namespace rfmems
