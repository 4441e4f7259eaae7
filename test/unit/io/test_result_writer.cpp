// Result files: write a 2×2 quad mesh with fields, probes and metadata, read everything back
// with the HDF5 C API, and check the atomic-write guarantees (no file after a failed run).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/hdf5_util.hpp"
#include "io/result_writer.hpp"
#include "mesh/mesh.hpp"

namespace rfmems {
namespace {

namespace fs = std::filesystem;

// Unit square split into 2×2 quads (nodes numbered row by row, cells counterclockwise).
Mesh two_by_two() {
  MeshBuilder b(2);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) b.add_node(Vec3(0.5 * i, 0.5 * j, 0.0));
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const Index n0 = 3 * j + i;
      b.add_cell(CellShape::Quad, {n0, n0 + 1, n0 + 4, n0 + 3});
    }
  return b.build("two_by_two");
}

// A triangle and a pentagon, for the "Mixed" topology of other shapes.
Mesh triangle_and_pentagon() {
  MeshBuilder b(2);
  for (const auto& x : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(2, 1, 0), Vec3(1, 1, 0),
                        Vec3(0.5, 1.5, 0)})
    b.add_node(x);
  b.add_cell(CellShape::Triangle, {0, 1, 4});
  b.add_cell(CellShape::Polygon, {1, 2, 3, 5, 4});
  return b.build("mixed");
}

struct Dataset {
  std::vector<hsize_t> shape;
  std::vector<double> doubles;
  std::vector<long long> ints;
};

Dataset read_dataset(hid_t file, const std::string& path) {
  Dataset d;
  H5Handle set(H5Dopen2(file, path.c_str(), H5P_DEFAULT), H5Dclose);
  EXPECT_TRUE(set.valid()) << path;
  if (!set.valid()) return d;
  H5Handle space(H5Dget_space(set.get()), H5Sclose);
  d.shape.resize(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space.get())));
  H5Sget_simple_extent_dims(space.get(), d.shape.data(), nullptr);
  hsize_t n = 1;
  for (auto s : d.shape) n *= s;
  H5Handle type(H5Dget_type(set.get()), H5Tclose);
  if (H5Tget_class(type.get()) == H5T_INTEGER) {
    d.ints.resize(n);
    if (n) H5Dread(set.get(), H5T_NATIVE_LLONG, H5S_ALL, H5S_ALL, H5P_DEFAULT, d.ints.data());
  } else {
    d.doubles.resize(n);
    if (n) H5Dread(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, d.doubles.data());
  }
  return d;
}

double read_double_attribute(hid_t file, const std::string& object, const std::string& name) {
  double v = -1;
  H5Handle attr(H5Aopen_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT),
                H5Aclose);
  EXPECT_TRUE(attr.valid()) << object << " " << name;
  H5Aread(attr.get(), H5T_NATIVE_DOUBLE, &v);
  return v;
}

long long read_int_attribute(hid_t file, const std::string& object, const std::string& name) {
  long long v = -1;
  H5Handle attr(H5Aopen_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT),
                H5Aclose);
  EXPECT_TRUE(attr.valid()) << object << " " << name;
  H5Aread(attr.get(), H5T_NATIVE_LLONG, &v);
  return v;
}

std::string read_string_attribute(hid_t file, const std::string& object, const std::string& name) {
  H5Handle attr(H5Aopen_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT),
                H5Aclose);
  EXPECT_TRUE(attr.valid()) << object << " " << name;
  if (!attr.valid()) return "";
  H5Handle type(H5Aget_type(attr.get()), H5Tclose);
  EXPECT_TRUE(H5Tis_variable_str(type.get()) > 0);
  H5Handle space(H5Aget_space(attr.get()), H5Sclose);
  char* text = nullptr;
  H5Aread(attr.get(), type.get(), &text);
  std::string out = text ? text : "";
  H5Dvlen_reclaim(type.get(), space.get(), H5P_DEFAULT, &text);
  return out;
}

class ResultWriterTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("rfmems_result_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const auto& e : fs::recursive_directory_iterator(dir_))
      names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

  fs::path dir_;
};

TEST_F(ResultWriterTest, WritesMeshFieldsSeriesAndMetadata) {
  const Mesh mesh = two_by_two();
  const std::string out = (dir_ / "run.h5").string();
  const std::string big(200000, 'x');  // larger than HDF5's 64 KiB compact attribute limit
  {
    ResultWriter w(out, mesh);
    EXPECT_EQ(w.xdmf_path(), (dir_ / "run.xdmf").string());
    std::vector<double> u(12), s(24), p = {1, 2, 3, 4};
    for (std::size_t i = 0; i < u.size(); ++i) u[i] = 0.1 * static_cast<double>(i);
    for (std::size_t i = 0; i < s.size(); ++i) s[i] = static_cast<double>(i);
    w.write_cell_field_at(0, 0.0, "displacement", u, 3, {"ux", "uy", "uz"});
    w.write_cell_field_at(0, 0.0, "stress", s, 6);
    w.write_cell_field_at(10, 1e-5, "displacement", u, 3);
    w.write_cell_field_at(10, 1e-5, "pressure", p, 1);
    w.write_time_series("probes", "tip", {0.0, 1e-6, 2e-6}, {{0, 0, 0}, {1, 2, 3}, {4, 5, 6}},
                        {"ux", "uy", "uz"});
    w.write_time_series("stats/solver", "steps", {1.0, 2.0}, {{10}, {20}});
    w.write_metadata({{"case", "mesh: {nx: 2}\n"},
                      {"overrides", "mesh.nx=2"},
                      {"big", big},
                      {"unicode", "4 µm"}},
                     {{"newton_iterations", 42.0}});
    w.write_metadata({{"overrides", "mesh.nx=4"}});  // the last value is kept
    // Nothing at the final name before finish().
    EXPECT_FALSE(fs::exists(out));
    w.finish();
    EXPECT_TRUE(w.finished());
  }
  EXPECT_EQ(files(), (std::vector<std::string>{"run.h5", "run.xdmf"}));  // no temporaries left

  H5Handle file(H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  ASSERT_TRUE(file.valid());
  const hid_t f = file.get();

  const Dataset nodes = read_dataset(f, "/mesh/nodes");
  EXPECT_EQ(nodes.shape, (std::vector<hsize_t>{9, 3}));
  for (Index n = 0; n < 9; ++n)
    for (int k = 0; k < 3; ++k)
      EXPECT_DOUBLE_EQ(nodes.doubles[static_cast<std::size_t>(3 * n + k)],
                       mesh.nodes()[static_cast<std::size_t>(n)][k]);

  const Dataset topology = read_dataset(f, "/mesh/topology");
  std::vector<long long> expected_topology;
  for (Index c = 0; c < 4; ++c) {
    expected_topology.push_back(5);  // XDMF quadrilateral
    for (Index n : mesh.cell_nodes(c)) expected_topology.push_back(n);
  }
  EXPECT_EQ(topology.ints, expected_topology);

  const Dataset centroids = read_dataset(f, "/mesh/cell_centroids");
  const Dataset volumes = read_dataset(f, "/mesh/cell_volumes");
  EXPECT_EQ(centroids.shape, (std::vector<hsize_t>{4, 3}));
  ASSERT_EQ(volumes.doubles.size(), 4u);
  for (Index c = 0; c < 4; ++c) {
    for (int k = 0; k < 3; ++k)
      EXPECT_DOUBLE_EQ(centroids.doubles[static_cast<std::size_t>(3 * c + k)],
                       mesh.cell_centroid(c)[k]);
    EXPECT_DOUBLE_EQ(volumes.doubles[static_cast<std::size_t>(c)], 0.25);
  }
  EXPECT_EQ(read_int_attribute(f, "/mesh", "dim"), 2);
  EXPECT_EQ(read_int_attribute(f, "/mesh", "n_cells"), 4);
  EXPECT_EQ(read_string_attribute(f, "/", "format"), "rfmems-result");

  const Dataset u0 = read_dataset(f, "/fields/000000/displacement");
  EXPECT_EQ(u0.shape, (std::vector<hsize_t>{4, 3}));
  EXPECT_DOUBLE_EQ(u0.doubles[11], 1.1);
  EXPECT_EQ(read_dataset(f, "/fields/000000/stress").shape, (std::vector<hsize_t>{4, 6}));
  EXPECT_EQ(read_dataset(f, "/fields/000010/pressure").doubles, (std::vector<double>{1, 2, 3, 4}));
  EXPECT_DOUBLE_EQ(read_double_attribute(f, "/fields/000010/displacement", "time"), 1e-5);
  EXPECT_EQ(read_string_attribute(f, "/fields/000000/displacement", "units"), "m");
  EXPECT_EQ(read_string_attribute(f, "/fields/000000/stress", "units"), "Pa");
  EXPECT_EQ(read_string_attribute(f, "/fields/000010/pressure", "units"), "Pa");
  EXPECT_DOUBLE_EQ(read_double_attribute(f, "/fields/000010", "time"), 1e-5);
  EXPECT_EQ(read_dataset(f, "/fields/times").doubles, (std::vector<double>{0.0, 1e-5}));
  EXPECT_EQ(read_dataset(f, "/fields/steps").ints, (std::vector<long long>{0, 10}));

  const Dataset tip = read_dataset(f, "/probes/tip/values");
  EXPECT_EQ(tip.shape, (std::vector<hsize_t>{3, 3}));
  EXPECT_EQ(tip.doubles, (std::vector<double>{0, 0, 0, 1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(read_dataset(f, "/probes/tip/time").doubles, (std::vector<double>{0.0, 1e-6, 2e-6}));
  EXPECT_EQ(read_dataset(f, "/stats/solver/steps/values").shape, (std::vector<hsize_t>{2, 1}));

  EXPECT_EQ(read_string_attribute(f, "/metadata", "case"), "mesh: {nx: 2}\n");
  EXPECT_EQ(read_string_attribute(f, "/metadata", "overrides"), "mesh.nx=4");
  EXPECT_EQ(read_string_attribute(f, "/metadata", "big"), big);
  EXPECT_EQ(read_string_attribute(f, "/metadata", "unicode"), "4 µm");
  EXPECT_FALSE(read_string_attribute(f, "/metadata", "git_hash").empty());
  EXPECT_DOUBLE_EQ(read_double_attribute(f, "/metadata", "newton_iterations"), 42.0);

  // The XDMF sidecar references the datasets by path.
  std::ifstream xdmf_in(dir_ / "run.xdmf");
  std::stringstream xdmf;
  xdmf << xdmf_in.rdbuf();
  const std::string x = xdmf.str();
  for (const char* needle :
       {"CollectionType=\"Temporal\"", "TopologyType=\"Mixed\" NumberOfElements=\"4\"",
        "run.h5:/mesh/topology", "Dimensions=\"20\"", "run.h5:/mesh/nodes", "Dimensions=\"9 3\"",
        "run.h5:/fields/000000/displacement", "run.h5:/fields/000000/stress",
        "AttributeType=\"Tensor6\"", "run.h5:/fields/000010/pressure", "AttributeType=\"Scalar\"",
        "AttributeType=\"Vector\" Center=\"Cell\"", "<Time Value=\"1e-05\" />"})
    EXPECT_NE(x.find(needle), std::string::npos) << needle << "\n" << x;
}

TEST_F(ResultWriterTest, MixedTopologyCountsPolygonNodes) {
  const Mesh mesh = triangle_and_pentagon();
  const std::string out = (dir_ / "mixed.h5").string();
  {
    ResultWriter w(out, mesh);
    w.finish();
  }
  H5Handle file(H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  ASSERT_TRUE(file.valid());
  const Dataset topology = read_dataset(file.get(), "/mesh/topology");
  std::vector<long long> expected = {4};
  for (Index n : mesh.cell_nodes(0)) expected.push_back(n);
  expected.push_back(3);  // polygon
  expected.push_back(5);  // its node count
  for (Index n : mesh.cell_nodes(1)) expected.push_back(n);
  EXPECT_EQ(topology.ints, expected);
  // A static result without fields: empty time list, a plain grid in the sidecar.
  EXPECT_TRUE(read_dataset(file.get(), "/fields/times").doubles.empty());
  EXPECT_TRUE(fs::exists(dir_ / "mixed.xdmf"));
}

TEST_F(ResultWriterTest, UnfinishedWriterLeavesNothing) {
  const std::string out = (dir_ / "sub" / "run.h5").string();
  {
    ResultWriter w(out, two_by_two());
    w.write_cell_field_at(0, 0.0, "pressure", {1, 2, 3, 4}, 1);
    EXPECT_TRUE(fs::exists(out + ".tmp." + std::to_string(::getpid())));
    // destroyed without finish(), as when an exception unwinds a failed run
  }
  EXPECT_EQ(files(), (std::vector<std::string>{"sub"}));
}

TEST_F(ResultWriterTest, StaleResultIsRemovedAtStart) {
  const std::string out = (dir_ / "run.h5").string();
  std::ofstream(out) << "old";
  std::ofstream(dir_ / "run.xdmf") << "old";
  { ResultWriter w(out, two_by_two()); }
  EXPECT_TRUE(files().empty());
}

TEST_F(ResultWriterTest, MisuseIsRejected) {
  ResultWriter w((dir_ / "run.h5").string(), two_by_two());
  EXPECT_THROW(w.write_cell_field_at(0, 0.0, "u2", std::vector<double>(8), 2),
               std::invalid_argument);
  EXPECT_THROW(w.write_cell_field_at(0, 0.0, "short", std::vector<double>(3), 1),
               std::invalid_argument);
  EXPECT_THROW(w.write_cell_field_at(0, 0.0, "a/b", std::vector<double>(4), 1),
               std::invalid_argument);
  // A field whose name has no unit (io/quantity_units.cpp) is a programming error.
  EXPECT_THROW(w.write_cell_field_at(1, 1.0, "p", std::vector<double>(4), 1),
               std::invalid_argument);
  w.write_cell_field_at(1, 1.0, "pressure", std::vector<double>(4), 1);
  EXPECT_THROW(w.write_cell_field_at(1, 1.0, "pressure", std::vector<double>(4), 1),
               std::invalid_argument);
  EXPECT_THROW(w.write_cell_field_at(1, 2.0, "density", std::vector<double>(4), 1),
               std::invalid_argument);
  EXPECT_THROW(w.write_time_series("probes", "tip", {0.0, 1.0}, {{1.0}}), std::invalid_argument);
  EXPECT_THROW(w.write_time_series("probes", "tip", {0.0, 1.0}, {{1.0}, {1.0, 2.0}}),
               std::invalid_argument);
}

TEST_F(ResultWriterTest, Hdf5ErrorNamesTheFile) {
  const std::string out = (dir_ / "run.h5").string();
  // The temporary's name is taken by a directory: HDF5 cannot create the file.
  fs::create_directories(out + ".tmp." + std::to_string(::getpid()));
  try {
    ResultWriter w(out, two_by_two());
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind(out + ": HDF5 error while creating ", 0), 0u) << msg;
  }
}

}  // namespace
}  // namespace rfmems
