// Tests of the Gmsh MSH 4.1 reader and the gmsh runner: the Kirsch plate-with-hole mesh made
// from cases/kirsch_hole/plate_with_hole.geo at run time, and small hand-written files for
// the 3D path and the error cases.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "core/error.hpp"
#include "mesh/gmsh_reader.hpp"
#include "mesh/gmsh_runner.hpp"

namespace rfmems {
namespace {

namespace fs = std::filesystem;

const std::string kHoleGeo =
    std::string(RFMEMS_SOURCE_DIR) + "/cases/kirsch_hole/plate_with_hole.geo";
const char* const kHolePatches[] = {"hole", "symmetry_y", "right", "top", "symmetry_x"};

// Each test gets its own scratch directory, removed afterwards.
class GmshReader : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("rfmems_gmsh_reader_" + std::to_string(getpid()) + "_" + info->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) const {
    const std::string path = (dir_ / name).string();
    std::ofstream(path) << text;
    return path;
  }

  Mesh hole_mesh(double h) const {
    const std::string out = (dir_ / ("hole_h" + std::to_string(h) + ".msh")).string();
    return read_gmsh_mesh(generate_gmsh_mesh(kHoleGeo, {{"h", h}}, out, 2));
  }

  fs::path dir_;
};

Real total_volume(const Mesh& mesh) {
  Real v = 0.0;
  for (Index c = 0; c < mesh.n_cells(); ++c) v += mesh.cell_volume(c);
  return v;
}

Real patch_area(const Mesh& mesh, const std::string& name) {
  const Patch& p = mesh.patches().at(mesh.find_patch(name));
  Real a = 0.0;
  for (Index f = p.first_face; f < p.first_face + p.n_faces; ++f) a += mesh.face_area(f).norm();
  return a;
}

// The message of the InputError (or MeshError) thrown by read_gmsh_mesh(path).
std::string error_of(const std::string& path) {
  try {
    read_gmsh_mesh(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST_F(GmshReader, HolePlateAreaConvergesToExact) {
  const Real exact = 4.0 - std::numbers::pi * 0.25 / 4.0;
  const Real err_coarse = std::abs(total_volume(hole_mesh(0.2)) - exact) / exact;
  const Real err_fine = std::abs(total_volume(hole_mesh(0.1)) - exact) / exact;
  std::cout << "area rel. error: h=0.2 " << err_coarse << ", h=0.1 " << err_fine << "\n";
  EXPECT_LT(err_coarse, 1e-3);
  EXPECT_LT(err_fine, err_coarse);
}

TEST_F(GmshReader, HolePlatePatches) {
  const Mesh mesh = hole_mesh(0.2);
  EXPECT_EQ(mesh.dim(), 2);
  Index n_tagged = 0;
  for (const char* name : kHolePatches) {
    const int p = mesh.find_patch(name);
    ASSERT_GE(p, 0) << name;
    EXPECT_GT(mesh.patches()[p].n_faces, 0) << name;
    n_tagged += mesh.patches()[p].n_faces;
  }
  // Every boundary face is tagged; the straight outer edges have uniform size h = 0.2.
  EXPECT_EQ(n_tagged, mesh.n_faces() - mesh.n_interior_faces());
  EXPECT_EQ(mesh.patches()[mesh.find_patch("right")].n_faces, 10);
  EXPECT_EQ(mesh.patches()[mesh.find_patch("top")].n_faces, 10);

  const Real quarter_circle = std::numbers::pi * 0.5 / 2.0;
  const Real hole_err = std::abs(patch_area(mesh, "hole") - quarter_circle) / quarter_circle;
  std::cout << "hole length rel. error at h=0.2: " << hole_err << "\n";
  EXPECT_LT(hole_err, 2e-3);
  EXPECT_NEAR(patch_area(mesh, "right"), 2.0, 1e-12);
}

TEST_F(GmshReader, HolePlateCellsAreClosedAndPositive) {
  const Mesh mesh = hole_mesh(0.2);
  for (Index c = 0; c < mesh.n_cells(); ++c) {
    EXPECT_GT(mesh.cell_volume(c), 0.0) << "cell " << c;
    Vec3 sum = Vec3::Zero();
    Real scale = 0.0;
    for (const Index f : mesh.cell_faces(c)) {
      const Vec3 s = mesh.face_owner(f) == c ? mesh.face_area(f) : Vec3(-mesh.face_area(f));
      sum += s;
      scale += s.norm();
    }
    EXPECT_LE(sum.norm(), 1e-12 * scale) << "cell " << c;
  }
}

TEST_F(GmshReader, HolePlateNormalsPointOutward) {
  const Mesh mesh = hole_mesh(0.2);
  const Patch& right = mesh.patches()[mesh.find_patch("right")];
  for (Index f = right.first_face; f < right.first_face + right.n_faces; ++f) {
    const Vec3 n = mesh.face_area(f).normalized();
    EXPECT_NEAR((n - Vec3(1, 0, 0)).norm(), 0.0, 1e-12) << "face " << f;
  }
  // Out of the plate on the hole means toward the hole centre; its nodes lie on the circle.
  const Patch& hole = mesh.patches()[mesh.find_patch("hole")];
  for (Index f = hole.first_face; f < hole.first_face + hole.n_faces; ++f) {
    EXPECT_LT(mesh.face_area(f).dot(mesh.face_centroid(f)), 0.0) << "face " << f;
    for (const Index n : mesh.face_nodes(f)) EXPECT_NEAR(mesh.nodes()[n].norm(), 0.5, 1e-12);
  }
}

// A unit square as two triangles, node tags 10..40 (non-contiguous), boundary lines on a
// physical curve with no name. `triangles` holds the two element lines.
std::string square_msh(const std::string& triangles) {
  return "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
         "$PhysicalNames\n1\n2 1 \"square\"\n$EndPhysicalNames\n"
         "$Entities\n0 1 1 0\n"
         "1 0 0 0 1 1 0 1 7 0\n"
         "1 0 0 0 1 1 0 1 1 0\n"
         "$EndEntities\n"
         "$Nodes\n1 4 10 40\n2 1 0 4\n10\n20\n30\n40\n"
         "0 0 0\n1 0 0\n1 1 0\n0 1 0\n$EndNodes\n"
         "$Elements\n2 6 1 9\n"
         "1 1 1 4\n1 10 20\n2 20 30\n3 30 40\n4 40 10\n"
         "2 1 2 2\n" +
         triangles + "$EndElements\n";
}

TEST_F(GmshReader, ClockwiseMeshIsReversed) {
  const Mesh mesh = read_gmsh_mesh(write("cw.msh", square_msh("7 10 30 20\n9 10 40 30\n")));
  EXPECT_EQ(mesh.n_cells(), 2);
  EXPECT_EQ(mesh.n_nodes(), 4);
  for (Index c = 0; c < mesh.n_cells(); ++c) EXPECT_NEAR(mesh.cell_volume(c), 0.5, 1e-14);
  const int p = mesh.find_patch("physical_7");
  ASSERT_GE(p, 0);
  EXPECT_EQ(mesh.patches()[p].n_faces, 4);
}

TEST_F(GmshReader, MixedOrientationIsMeshError) {
  const std::string path = write("mixed.msh", square_msh("7 10 20 30\n9 10 40 30\n"));
  EXPECT_THROW(read_gmsh_mesh(path), MeshError);
  EXPECT_EQ(error_of(path), path + ": inverted cell 9");
}

TEST_F(GmshReader, UnitHexahedron) {
  const std::string path =
      write("hex.msh",
            "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
            "$PhysicalNames\n1\n2 1 \"walls\"\n$EndPhysicalNames\n"
            "$Entities\n0 0 1 1\n"
            "1 0 0 0 1 1 1 1 1 0\n"
            "1 0 0 0 1 1 1 0 1 1\n"
            "$EndEntities\n"
            "$Nodes\n1 8 1 8\n3 1 0 8\n1\n2\n3\n4\n5\n6\n7\n8\n"
            "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n$EndNodes\n"
            "$Elements\n2 7 1 7\n"
            "2 1 3 6\n1 1 4 3 2\n2 5 6 7 8\n3 1 2 6 5\n4 2 3 7 6\n5 3 4 8 7\n6 4 1 5 8\n"
            "3 1 5 1\n7 1 2 3 4 5 6 7 8\n"
            "$EndElements\n");
  const Mesh mesh = read_gmsh_mesh(path);
  EXPECT_EQ(mesh.dim(), 3);
  ASSERT_EQ(mesh.n_cells(), 1);
  EXPECT_NEAR(mesh.cell_volume(0), 1.0, 1e-14);
  EXPECT_EQ(mesh.n_faces(), 6);
  const int p = mesh.find_patch("walls");
  ASSERT_GE(p, 0);
  EXPECT_EQ(mesh.patches()[p].n_faces, 6);
}

TEST_F(GmshReader, OldFormatIsInputError) {
  const std::string path = write("old.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n");
  EXPECT_THROW(read_gmsh_mesh(path), InputError);
  EXPECT_NE(error_of(path).find(path + ": Gmsh MSH format 2.2"), std::string::npos);
}

TEST_F(GmshReader, BinaryIsInputError) {
  const std::string path = write("bin.msh", "$MeshFormat\n4.1 1 8\n");
  EXPECT_NE(error_of(path).find(path + ": binary"), std::string::npos);
}

TEST_F(GmshReader, MissingFileIsInputError) {
  const std::string path = (dir_ / "nonexistent.msh").string();
  EXPECT_THROW(read_gmsh_mesh(path), InputError);
  EXPECT_EQ(error_of(path), path + ": no such file");
}

TEST_F(GmshReader, TruncatedFileIsInputError) {
  std::string text = square_msh("7 10 20 30\n9 10 30 40\n");
  text.resize(text.find("$Elements"));
  const std::string path = write("truncated.msh", text + "$Elements\n2 6 1 9\n1 1 1 4\n1 10\n");
  const std::string message = error_of(path);
  EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
  EXPECT_NE(message.find("$Elements"), std::string::npos) << message;
}

TEST_F(GmshReader, UndefinedNodeIsInputError) {
  const std::string path = write("undefined.msh", square_msh("7 10 20 30\n9 10 30 99\n"));
  EXPECT_EQ(error_of(path), path + ": element 9 references undefined node 99");
}

TEST_F(GmshReader, SecondOrderIsInputError) {
  std::string text = square_msh("");
  text.replace(text.find("2 1 2 2\n"), 8, "2 1 9 1\n7 10 20 30 10 20 30\n");
  const std::string path = write("order2.msh", text);
  EXPECT_NE(error_of(path).find("element type 9 (6-node triangle) is not supported"),
            std::string::npos);
}

TEST_F(GmshReader, RunnerReportsGmshErrors) {
  const std::string geo = write("bad.geo", "this is not a geo file\n");
  try {
    generate_gmsh_mesh(geo, {}, (dir_ / "bad.msh").string(), 2);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("gmsh failed"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir_ / "bad.msh"));
}

}  // namespace
}  // namespace rfmems
