// A switch scene loaded from a case file, for the benchmarks that build one from cases/.
#pragma once
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "coupling/switch_scene.hpp"
#include "io/case_file.hpp"

namespace rfmems::bench {

// A switch scene and the case file it was read from (kept alive: the scene's settings are read
// from it later).
struct Scene {
  CaseFile file;
  SwitchScene scene;
};

// The case at `path` with the `--set`-style overrides, built as a switch scene.
inline std::unique_ptr<Scene> load_scene(const std::string& path,
                                         const std::vector<std::string>& overrides) {
  CaseFile cf = CaseFile::load(path, overrides);
  SwitchScene s = build_switch_scene(cf.root(), std::filesystem::path(path).parent_path().string());
  return std::make_unique<Scene>(Scene{std::move(cf), std::move(s)});
}

}  // namespace rfmems::bench
