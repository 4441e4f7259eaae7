// Case-file pieces shared by the structural scenes (elasticity, plate): load ramps and the
// `boundaries` map with one entry per mesh patch.
//
//   boundaries:
//     left:  {type: ..., ...}     # every mesh patch exactly once; an unknown patch name or a
//     right: {type: ..., ...}     # missing one is an InputError listing the mesh's patches
//
// `ramp: T` on a load scales it linearly from 0 at t = 0 to its full value at t = T, then
// holds it.
#pragma once
#include <string>
#include <vector>

#include "io/case_file.hpp"
#include "mesh/mesh.hpp"

namespace rfmems {

// Linear ramp 0 -> 1 over [0, ramp], then 1 (always 1 without a ramp).
Real ramp_factor(Real t, Real ramp);

// The optional `ramp` key of a load entry (time, >= 0, default 0).
Real read_ramp(const CaseNode& entry);

// The entry of each mesh patch, in patch order, from the `boundaries` map.
std::vector<CaseNode> patch_entries(const CaseNode& boundaries, const Mesh& mesh);

}  // namespace rfmems
