// A seeded fuzz of the case readers: the cases in cases/ mutated at random (a key deleted or
// added, a number made NaN, negative, huge or a string, a unit swapped, a scalar turned into a
// map or a sequence and back) and read by the readers and scene builders each driver uses
// before it solves (never a solve). Every mutant must be read without a crash, within a time
// limit, and either accepted or refused with an InputError (MeshError included): any other
// exception is a reader bug. A failure prints the seed and the mutated case.
//
// Meshes: the memory limit is lowered so that a mutated cell count is refused by the memory
// estimate instead of built; gmsh-meshed cases (a gmsh run per mutant) and the immersed switch
// (its background marked per mutant) are left out of the default run.
// RFMEMS_FUZZ_ITERATIONS (mutants per case) and RFMEMS_FUZZ_ALL=1 (those cases too) make the
// bigger run of the study label (test/CMakeLists.txt).
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "coupling/pull_in_study.hpp"
#include "coupling/switch_scene.hpp"
#include "io/case_file.hpp"
#include "io/input_solve.hpp"
#include "io/probes.hpp"
#include "io/run_limits.hpp"
#include "physics/creep/creep_case.hpp"
#include "physics/gas/kinetic/kinetic_case.hpp"
#include "physics/gas/kinetic/poiseuille_flow_factor.hpp"
#include "physics/structure/structural_analysis.hpp"
#include "physics/structure/structure_from_case.hpp"

namespace rfmems {
namespace {

namespace fs = std::filesystem;

const fs::path kCases = fs::path(RFMEMS_SOURCE_DIR) / "cases";

// A mutant must be read within this (a structure of up to ~30 000 cells on a loaded machine).
constexpr double kSecondsPerMutant = 20;

int env_int(const char* name, int fallback) {
  const char* v = std::getenv(name);
  return v ? std::atoi(v) : fallback;
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Reads the case as the driver that runs it does, up to check_all_used (no solving).
void read_like_driver(const CaseFile& file, const std::string& dir) {
  const CaseNode root = file.root();
  root.get_string("name", "");  // DriverCase's key
  if (root.has("creep")) {
    read_creep_case(root, dir);
  } else if (root.has("pull_in")) {
    const SwitchScene scene = build_switch_scene(root, dir);
    read_pull_in_settings(root, scene);
  } else if (root.has("flow_factor")) {  // rfmems-flow-factor: its points, then the channel
    read_flow_factor_points(root.child("flow_factor"));
    read_with_input_solves(root, "gas state", [&] { return build_kinetic_scene(root, dir); });
  } else if (root.has("velocity_grid")) {
    read_with_input_solves(root, "gas state", [&] { return build_kinetic_scene(root, dir); });
  } else {
    root.child_or_empty("solver").get_bool("distributed", false);
    const AnalysisType type = read_analysis_type(root);
    const std::unique_ptr<StructuralModel> model = build_structure(root, dir, type);
    read_analysis_settings(root, *model);
    read_probes(root.child_or_empty("probes"), model->structure_mesh());
  }
  file.check_all_used();
}

// Every node of the document with a way back to it from the root.
struct Site {
  YAML::Node parent;  // map or sequence holding it (a null node for the root)
  YAML::Node key;     // key in a map, or the index as a scalar in a sequence
  YAML::Node node;
};

void collect(const YAML::Node& parent, const YAML::Node& key, const YAML::Node& node,
             std::vector<Site>& out) {
  out.push_back({parent, key, node});
  if (node.IsMap()) {
    for (auto it = node.begin(); it != node.end(); ++it) collect(node, it->first, it->second, out);
  } else if (node.IsSequence()) {
    for (std::size_t i = 0; i < node.size(); ++i)
      collect(node, YAML::Node(static_cast<int>(i)), node[i], out);
  }
}

class Mutator {
 public:
  explicit Mutator(unsigned seed) : rng_(seed) {}

  // Applies 1 to 3 random mutations to the document.
  void mutate(YAML::Node& root) {
    const int n = 1 + pick(3);
    for (int k = 0; k < n; ++k) mutate_once(root);
  }

 private:
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }
  template <class T>
  const T& one_of(const std::vector<T>& v) {
    return v[pick(static_cast<int>(v.size()))];
  }

  std::string number_text() {
    static const std::vector<std::string> numbers = {
        "nan",  ".nan",  "-1",   "0",   "1e300", "-1e300", "1e-300",  "inf",
        ".inf", "-.inf", "abc",  "",    "3",     "0.5",    "1000000", "2147483648",
        "-0",   "1e15",  "9e18", "1 2", "~",     "true"};
    return one_of(numbers);
  }

  std::string with_unit(const std::string& scalar) {
    static const std::vector<std::string> units = {
        "m", "um", "Pa", "GPa", "s", "ms", "h", "d", "V", "kg/m^3", "N", "K", "parsec", "", "%"};
    // The number (if any) of the scalar kept, its unit replaced.
    std::size_t end = 0;
    while (end < scalar.size() && (std::isdigit(static_cast<unsigned char>(scalar[end])) ||
                                   std::string("+-.eE").find(scalar[end]) != std::string::npos))
      ++end;
    const std::string number = end > 0 ? scalar.substr(0, end) : number_text();
    return number + " " + one_of(units);
  }

  YAML::Node structure() {
    switch (pick(5)) {
      case 0:
        return YAML::Load("{a: 1}");
      case 1:
        return YAML::Load("[1, 2]");
      case 2:
        return YAML::Load("[]");
      case 3:
        return YAML::Load("{}");
      default:
        return YAML::Node(YAML::NodeType::Null);
    }
  }

  void replace(Site s, const YAML::Node& value) {
    if (s.parent.IsMap())
      s.parent[s.key] = value;
    else if (s.parent.IsSequence())
      s.parent[s.key.as<int>()] = value;
  }

  void mutate_once(YAML::Node& root) {
    std::vector<Site> sites;
    collect(YAML::Node(), YAML::Node(), root, sites);
    Site s = sites[pick(static_cast<int>(sites.size()))];
    switch (pick(7)) {
      case 0:  // delete a key or an item
        if (s.parent.IsMap())
          s.parent.remove(s.key);
        else if (s.parent.IsSequence())
          s.parent.remove(s.key.as<int>());
        break;
      case 1:
      case 2:  // a number: NaN, negative, huge, a string
        if (s.node.IsScalar()) replace(s, YAML::Node(number_text()));
        break;
      case 3:  // a unit swapped
        if (s.node.IsScalar()) replace(s, YAML::Node(with_unit(s.node.Scalar())));
        break;
      case 4:  // wrong nesting
        replace(s, structure());
        break;
      case 5:  // a key nobody reads, or a map's value moved one level down
        if (s.node.IsMap())
          s.node["unknown_key_" + std::to_string(pick(3))] = number_text();
        else if (s.parent.IsMap()) {
          YAML::Node wrapped(YAML::NodeType::Map);
          wrapped["value"] = YAML::Clone(s.node);
          replace(s, wrapped);
        }
        break;
      default:  // a sequence item duplicated or a sequence turned into a scalar
        if (s.node.IsSequence() && s.node.size() > 0)
          s.node.push_back(YAML::Clone(s.node[0]));
        else if (s.node.IsSequence())
          replace(s, YAML::Node(number_text()));
        break;
    }
  }

  std::mt19937 rng_;
};

struct FuzzCase {
  std::string name;
  fs::path dir;
  std::string text;
};

std::vector<FuzzCase> fuzz_cases() {
  const bool all = env_int("RFMEMS_FUZZ_ALL", 0) != 0;
  std::vector<FuzzCase> out;
  for (const auto& entry : fs::directory_iterator(kCases)) {
    const fs::path file = entry.path() / "case.yaml";
    if (!fs::is_regular_file(file)) continue;
    const std::string text = read_text(file);
    const YAML::Node doc = YAML::Load(text);
    const bool gmsh = doc["mesh"] && doc["mesh"].IsMap() && doc["mesh"]["type"] &&
                      doc["mesh"]["type"].as<std::string>() == "gmsh";
    const bool immersed = doc["actuation"] && doc["actuation"].IsMap() &&
                          doc["actuation"]["electrostatics"] &&
                          doc["actuation"]["electrostatics"].as<std::string>() == "immersed";
    if ((immersed || gmsh) && !all) continue;
    out.push_back({entry.path().filename().string(), entry.path(), text});
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  return out;
}

class CaseFuzz : public ::testing::Test {
 protected:
  void SetUp() override { set_memory_limit(1ull << 30); }
  void TearDown() override { set_memory_limit(0); }
};

TEST_F(CaseFuzz, MutatedCasesAreReadOrRefusedWithAnInputError) {
  const std::vector<FuzzCase> cases = fuzz_cases();
  ASSERT_GE(cases.size(), 10u) << "cases/ not found under " << kCases;
  const int iterations = env_int("RFMEMS_FUZZ_ITERATIONS", 200);
  int accepted = 0, refused = 0;
  for (std::size_t c = 0; c < cases.size(); ++c) {
    const FuzzCase& fc = cases[c];
    // The unmutated case reads cleanly: the fuzz starts from valid input.
    ASSERT_NO_THROW(
        read_like_driver(CaseFile::parse(fc.text, fc.name + "/case.yaml"), fc.dir.string()))
        << fc.name;
    for (int i = 0; i < iterations; ++i) {
      const unsigned seed = static_cast<unsigned>(1000 * c + i);
      Mutator mutator(seed);
      YAML::Node doc = YAML::Load(fc.text);
      mutator.mutate(doc);
      YAML::Emitter emitter;
      emitter << doc;
      const std::string mutant = emitter.c_str();
      const auto start = std::chrono::steady_clock::now();
      std::string other;
      try {
        read_like_driver(CaseFile::parse(mutant, fc.name + "/case.yaml"), fc.dir.string());
        ++accepted;
      } catch (const InputError&) {
        ++refused;
      } catch (const std::exception& e) {
        other = std::string(typeid(e).name()) + ": " + e.what();
      } catch (...) {
        other = "a non-standard exception";
      }
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      EXPECT_TRUE(other.empty()) << fc.name << " seed " << seed << ": " << other << "\n" << mutant;
      EXPECT_LT(seconds, kSecondsPerMutant)
          << fc.name << " seed " << seed << " took " << seconds << " s\n"
          << mutant;
    }
  }
  // Both outcomes occur: the mutations reach the checks, and not every one is fatal.
  EXPECT_GT(accepted, 0);
  EXPECT_GT(refused, 0);
  std::printf("%d mutants accepted, %d refused with an InputError\n", accepted, refused);
}

}  // namespace
}  // namespace rfmems
