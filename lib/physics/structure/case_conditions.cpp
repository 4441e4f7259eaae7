#include "physics/structure/case_conditions.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

namespace rfmems {

Real ramp_factor(Real t, Real ramp) { return ramp > 0 ? std::clamp(t / ramp, 0.0, 1.0) : 1.0; }

Real read_ramp(const CaseNode& entry) {
  return entry.get_quantity("ramp", Dimension::Time, 0.0, Range::non_negative());
}

std::vector<CaseNode> patch_entries(const CaseNode& node, const Mesh& mesh) {
  std::vector<std::string> patches;
  for (const Patch& p : mesh.patches()) patches.push_back(p.name);
  const std::vector<std::string> given = node.keys();
  for (const std::string& key : given)
    if (mesh.find_patch(key) < 0)
      node.fail(key, fmt::format("the mesh has no patch '{}' (mesh patches: {})", key,
                                 fmt::join(patches, ", ")));
  std::vector<CaseNode> entries;
  for (const std::string& patch : patches) {
    if (!node.has(patch))
      node.fail(
          patch,
          fmt::format("mesh patch '{}' has no boundary condition (given: {}; mesh "
                      "patches: {})",
                      patch, given.empty() ? "none" : fmt::format("{}", fmt::join(given, ", ")),
                      fmt::join(patches, ", ")));
    entries.push_back(node.child(patch));
  }
  return entries;
}

}  // namespace rfmems
