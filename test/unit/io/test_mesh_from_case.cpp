// The `mesh:` section of a case: structured rectangles and boxes, gmsh meshes from a .geo
// (meshed at run time) or a .msh, and the wording of its errors.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <functional>

#include "core/error.hpp"
#include "io/mesh_from_case.hpp"
#include "io/run_limits.hpp"

namespace rfmems {
namespace {

const std::string kKirschDir = std::string(RFMEMS_SOURCE_DIR) + "/cases/kirsch_hole";

Mesh mesh_of(const std::string& yaml, const std::string& case_dir = "") {
  const CaseFile cf = CaseFile::parse(yaml, "m.yaml");
  Mesh mesh = mesh_from_case(cf.root().child("mesh"), case_dir);
  cf.check_all_used();
  return mesh;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(MeshFromCase, Rectangle) {
  const Mesh mesh = mesh_of(
      "mesh: {type: rectangle, lower: [0 um, -4 um], size: [400 um, 8 um], cells: [40, 4]}\n");
  EXPECT_EQ(mesh.dim(), 2);
  EXPECT_EQ(mesh.n_cells(), 160);
  Real area = 0;
  for (Index c = 0; c < mesh.n_cells(); ++c) area += mesh.cell_volume(c);
  EXPECT_NEAR(area, 400e-6 * 8e-6, 1e-20);
  for (const char* name : {"left", "right", "bottom", "top"}) EXPECT_GE(mesh.find_patch(name), 0);
  EXPECT_NEAR(mesh.nodes().front().y(), -4e-6, 1e-18);
}

TEST(MeshFromCase, GradedBox) {
  const Mesh mesh =
      mesh_of("mesh: {type: box, size: [1, 0.1, 0.1], cells: [10, 2, 3], grading: [4, 1, 1]}\n");
  EXPECT_EQ(mesh.dim(), 3);
  EXPECT_EQ(mesh.n_cells(), 60);
  EXPECT_EQ(mesh.patches().size(), 6u);
  EXPECT_NEAR(mesh.max_cell_size() / mesh.min_cell_size(), std::cbrt(4.0), 1e-9);
}

TEST(MeshFromCase, GeoIsMeshedAtRunTime) {
  const Mesh mesh =
      mesh_of("mesh: {type: gmsh, file: plate_with_hole.geo, parameters: {h: 0.4}}\n", kKirschDir);
  EXPECT_EQ(mesh.dim(), 2);
  EXPECT_GT(mesh.n_cells(), 10);
  for (const char* name : {"hole", "right", "top", "symmetry_x", "symmetry_y"})
    EXPECT_GE(mesh.find_patch(name), 0) << name;
}

TEST(MeshFromCase, ErrorsNameTheFileAndKey) {
  EXPECT_EQ(error_of([] { mesh_of("mesh: {type: disc}\n"); }),
            "m.yaml: key 'mesh.type' = 'disc': expected one of: rectangle, box, gmsh");
  EXPECT_EQ(error_of([] { mesh_of("mesh: {type: rectangle, size: [1, 1, 1], cells: [2, 2]}\n"); }),
            "m.yaml: key 'mesh.size' = [1, 1, 1]: expected 2 lengths (one per axis)");
  EXPECT_EQ(error_of([] { mesh_of("mesh: {type: rectangle, size: [1, 0], cells: [2, 2]}\n"); }),
            "m.yaml: key 'mesh.size' = [1, 0]: every length must be > 0");
  EXPECT_EQ(error_of([] { mesh_of("mesh: {type: rectangle, size: [1, 1], cells: [2.5, 2]}\n"); }),
            "m.yaml: key 'mesh.cells' = [2.5, 2]: every cell count must be an integer in [1, "
            "1000000]");
  EXPECT_EQ(error_of([] { mesh_of("mesh: {type: gmsh, file: plate.stl}\n"); }),
            "m.yaml: key 'mesh.file' = 'plate.stl': expected a .geo or .msh file");
  EXPECT_EQ(error_of([] { mesh_of("mesh: {type: gmsh, file: /nonexistent/a.msh}\n"); }),
            "m.yaml: key 'mesh.file' = '/nonexistent/a.msh': /nonexistent/a.msh: no such file");
  EXPECT_NE(error_of([] {
              mesh_of("mesh: {type: gmsh, file: a.msh, parameters: {h: 1}}\n");
            }).find("only for a .geo file"),
            std::string::npos);
}

TEST(MeshFromCase, NoScratchFilesAreLeft) {
  namespace fs = std::filesystem;
  auto count = [] {
    int n = 0;
    for (const auto& entry : fs::directory_iterator(fs::temp_directory_path()))
      n += entry.path().filename().string().starts_with(
          "rfmems-mesh-" + std::to_string(static_cast<long>(::getpid())) + "-");
    return n;
  };
  mesh_of("mesh: {type: gmsh, file: plate_with_hole.geo, parameters: {h: 0.4}}\n", kKirschDir);
  EXPECT_EQ(count(), 0);
}

// A structured mesh's memory estimate (cells x bytes per unknown) is checked against the
// run's limit before the mesh is built: [1e6, 1e6] cells would otherwise allocate until the
// machine runs out.
TEST(MeshFromCase, MeshBeyondTheMemoryLimitIsRefusedBeforeItIsBuilt) {
  const std::string huge = "mesh: {type: rectangle, size: [1, 1], cells: [1000000, 1000000]}\n";
  const std::string e = error_of([&] { mesh_of(huge); });
  EXPECT_NE(e.find("key 'mesh.cells'"), std::string::npos) << e;
  EXPECT_NE(e.find("estimated"), std::string::npos) << e;
  EXPECT_NE(e.find("TiB"), std::string::npos) << e;  // 1e12 cells: terabytes
  EXPECT_NE(e.find("MemAvailable"), std::string::npos) << e;

  set_memory_limit(1 << 20);
  const std::string small = "mesh: {type: rectangle, size: [1, 1], cells: [200, 20]}\n";
  const std::string limited = error_of([&] { mesh_of(small); });
  set_memory_limit(0);
  EXPECT_NE(limited.find("more than the 1 MiB"), std::string::npos) << limited;
  EXPECT_NE(limited.find("--max-memory"), std::string::npos) << limited;
  EXPECT_EQ(mesh_of(small).n_cells(), 4000);  // MemAvailable again: it fits
}

// gmsh ignores a -setnumber name the .geo does not declare, so a typo would mesh with the
// default silently: every parameter must be a name the .geo declares.
TEST(MeshFromCase, GmshParameterTypoIsRefused) {
  const std::string e = error_of([] {
    mesh_of("mesh: {type: gmsh, file: plate_with_hole.geo, parameters: {hh: 0.1}}\n", kKirschDir);
  });
  EXPECT_NE(e.find("key 'mesh.parameters.hh'"), std::string::npos) << e;
  EXPECT_NE(e.find("declares no parameter 'hh'"), std::string::npos) << e;
  // The names it does declare: DefineConstant h and the plain assignments (a, L, h_hole).
  for (const char* name : {"h,", "a,", "L,", "h_hole"})
    EXPECT_NE(e.find(name), std::string::npos) << name << " in " << e;
  EXPECT_EQ(e.find("Name"), std::string::npos) << e;  // inside DefineConstant's braces
}

TEST(MeshFromCase, MeshFileThatIsTheResultIsRefused) {
  set_result_path(kKirschDir + "/../kirsch_hole/plate_with_hole.geo");
  const std::string e = error_of([] {
    mesh_of("mesh: {type: gmsh, file: plate_with_hole.geo, parameters: {h: 0.4}}\n", kKirschDir);
  });
  set_result_path("");
  EXPECT_NE(e.find("key 'mesh.file'"), std::string::npos) << e;
  EXPECT_NE(e.find("result file"), std::string::npos) << e;
}

}  // namespace
}  // namespace rfmems
