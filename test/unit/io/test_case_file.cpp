// Case files: typed getters, units, overrides, unknown keys, and the exact wording of every
// error (one line naming file, dotted key and value).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>

#include "core/error.hpp"
#include "io/case_file.hpp"

namespace rfmems {
namespace {

namespace fs = std::filesystem;

// A fresh directory per test, removed afterwards.
class CaseFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("rfmems_case_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) {
    const std::string path = (dir_ / name).string();
    std::ofstream(path) << text;
    return path;
  }

  fs::path dir_;
};

// The message of the InputError f throws ("" if it throws none).
std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Parses text under the file name "x.yaml" (so messages can be compared whole).
CaseFile parse(const std::string& text, const std::vector<std::string>& overrides = {}) {
  return CaseFile::parse(text, "x.yaml", overrides);
}

const char* kCase = R"(
mesh:
  nx: 40
  ny: abc
  lx: 300 um
  grading: [1, 2]
material:
  E: 160 GPa
  nu: 0.7
  rho: 2330 kg/m^3
  name: silicon
  model: linear
solver:
  rtol: 1e-6
  adaptive: yes
  max_steps: 1e6
  half: 1.5
probes:
  - name: tip
    at: [1, 0.5]
  - name: mid
    at: [0.5, 0.5, 0.1]
)";

TEST_F(CaseFileTest, ReadsTypedValues) {
  const CaseFile cf = parse(kCase);
  const CaseNode root = cf.root();
  const CaseNode mesh = root.child("mesh");
  EXPECT_EQ(mesh.get_int("nx"), 40);
  EXPECT_EQ(mesh.path(), "mesh");
  EXPECT_EQ(mesh.key_path("nx"), "mesh.nx");
  EXPECT_DOUBLE_EQ(mesh.get_quantity("lx", Dimension::Length), 300e-6);
  EXPECT_EQ(mesh.get_reals("grading"), (std::vector<double>{1, 2}));
  EXPECT_EQ(mesh.get_int("nz", 7), 7);  // absent: default

  const CaseNode material = root.child("material");
  EXPECT_DOUBLE_EQ(material.get_quantity("E", Dimension::Pressure, Range::positive()), 160e9);
  EXPECT_EQ(material.get_string("name"), "silicon");
  EXPECT_EQ(material.get_choice("model", {"linear", "neo-hookean"}), "linear");
  EXPECT_EQ(material.get_choice("law", {"a", "b"}, "b"), "b");

  const CaseNode solver = root.child("solver");
  EXPECT_DOUBLE_EQ(solver.get_real("rtol"), 1e-6);
  EXPECT_TRUE(solver.get_bool("adaptive"));
  EXPECT_FALSE(solver.get_bool("verbose", false));
  EXPECT_EQ(solver.get_int("max_steps"), 1000000);  // an integral real is an integer
  EXPECT_DOUBLE_EQ(solver.get_real("atol", 1e-9), 1e-9);
  EXPECT_EQ(solver.get_string("method", "bdf"), "bdf");

  const CaseNode probes = root.child("probes");
  ASSERT_EQ(probes.size(), 2u);
  EXPECT_EQ(probes.item(0).path(), "probes[0]");
  EXPECT_EQ(probes.item(0).get_string("name"), "tip");
  EXPECT_EQ(probes.item(0).get_vec3("at"), Vec3(1, 0.5, 0));  // missing z = 0
  EXPECT_EQ(probes.item(1).get_vec3("at"), Vec3(0.5, 0.5, 0.1));
  EXPECT_EQ(root.keys(), (std::vector<std::string>{"mesh", "material", "solver", "probes"}));
}

TEST_F(CaseFileTest, MissingKeyNamesFileAndDottedKey) {
  const CaseFile cf = parse(kCase);
  EXPECT_EQ(error_of([&] { cf.root().child("material").get_real("E2"); }),
            "x.yaml: missing key 'material.E2'");
  EXPECT_EQ(error_of([&] { cf.root().child("boundary"); }), "x.yaml: missing key 'boundary'");
  EXPECT_EQ(error_of([&] { cf.root().child("probes").item(1).get_string("kind"); }),
            "x.yaml: missing key 'probes[1].kind'");
}

TEST_F(CaseFileTest, WrongTypeNamesValue) {
  const CaseFile cf = parse(kCase);
  const CaseNode root = cf.root();
  EXPECT_EQ(error_of([&] { root.child("mesh").get_int("ny"); }),
            "x.yaml: key 'mesh.ny' = 'abc': expected an integer");
  EXPECT_EQ(error_of([&] { root.child("solver").get_int("half"); }),
            "x.yaml: key 'solver.half' = 1.5: expected an integer");
  EXPECT_EQ(error_of([&] { root.child("mesh").get_real("ny"); }),
            "x.yaml: key 'mesh.ny' = 'abc': expected a number");
  EXPECT_EQ(error_of([&] { root.child("material").get_bool("name"); }),
            "x.yaml: key 'material.name' = 'silicon': expected true or false");
  EXPECT_EQ(error_of([&] { root.child("mesh").get_real("grading"); }),
            "x.yaml: key 'mesh.grading' = [1, 2]: expected a number");
  EXPECT_EQ(error_of([&] { root.child("mesh").get_string("grading"); }),
            "x.yaml: key 'mesh.grading' = [1, 2]: expected a string");
  EXPECT_EQ(error_of([&] { root.child("solver").child("rtol"); }),
            "x.yaml: key 'solver.rtol' = 1e-6: expected a map or a sequence");
  EXPECT_EQ(error_of([&] { root.child("mesh").get_vec3("nx"); }),
            "x.yaml: key 'mesh.nx' = 40: expected a sequence of 2 or 3 numbers");
  EXPECT_EQ(error_of([&] { root.child("material").get_reals("name"); }),
            "x.yaml: key 'material.name' = 'silicon': expected a sequence of numbers");
  EXPECT_EQ(
      error_of([&] { root.child("mesh").size(); }),
      "x.yaml: key 'mesh' = {nx: 40, ny: abc, lx: 300 um, grading: [1, 2]}: expected a sequence");
  EXPECT_EQ(error_of([&] { root.child("probes").get_real("x"); }),
            "x.yaml: key 'probes' = [{name: tip, at: [1, 0.5]}, {name: mid, at: [0.5, 0.5, 0.1]}]: "
            "expected a map");
  EXPECT_EQ(error_of([&] {
              root.child("material").get_choice("model", {"neo-hookean", "svk"});
            }),
            "x.yaml: key 'material.model' = 'linear': expected one of: neo-hookean, svk");
}

TEST_F(CaseFileTest, RangeErrors) {
  const CaseFile cf = parse(kCase);
  const CaseNode material = cf.root().child("material");
  EXPECT_EQ(error_of([&] {
              material.get_real("nu", Range{-1, 0.5, true, true});
            }),
            "x.yaml: key 'material.nu' = 0.7: must be in (-1, 0.5)");
  EXPECT_EQ(error_of([&] { material.get_real("nu", 0.3, Range::closed(0, 0.5)); }),
            "x.yaml: key 'material.nu' = 0.7: must be in [0, 0.5]");
  EXPECT_EQ(error_of([&] {
              cf.root().child("solver").get_real("rtol", Range{-1e300, 0, false, true});
            }),
            "x.yaml: key 'solver.rtol' = 1e-6: must be in [-1e+300, 0)");
  EXPECT_EQ(error_of([&] {
              material.get_quantity("E", Dimension::Pressure, Range{0, 1e9});
            }),
            "x.yaml: key 'material.E' = '160 GPa': must be in [0, 1000000000]");
  EXPECT_EQ(error_of([&] { cf.root().child("mesh").get_int("nx", Range{.min = 50}); }),
            "x.yaml: key 'mesh.nx' = 40: must be >= 50");
  EXPECT_EQ(Range::positive().describe(), "must be > 0");
  EXPECT_EQ(Range::non_negative().describe(), "must be >= 0");
  EXPECT_EQ((Range{.max = 1, .max_open = true}).describe(), "must be < 1");
  EXPECT_EQ(error_of([&] { material.get_real("nu", Range::open(-1, 1)); }), "");
  // require()/fail() for checks of several values.
  EXPECT_EQ(
      error_of([&] { material.require(false, "nu", "must be smaller than 0.5 for this model"); }),
      "x.yaml: key 'material.nu' = 0.7: must be smaller than 0.5 for this model");
  EXPECT_EQ(error_of([&] { material.fail("G", "needed when E is absent"); }),
            "x.yaml: key 'material.G': needed when E is absent");
}

TEST_F(CaseFileTest, Units) {
  const CaseFile cf = parse(R"(
E: 210 GPa
h: 4 um
h_micro: "4 µm"
h_mu: "4 μm"
h_nospace: 4um
t: 1e-5 s
rho: 7854 kg/m^3
rho2: 2.33 g/cm^3
rho3: 2330 kg/m3
k: -100 N/m
p: 1000 Pa
p_atm: 1 atm
p_torr: 760 torr
V: 177 V
f: 8.15 Hz
f2: 2 GHz
F: 3 uN
m: 2 mg
T: 300 K
mu: 18.5 uPa s
plain: 2.5e11
us: 5 µs
)");
  const CaseNode r = cf.root();
  using D = Dimension;
  EXPECT_DOUBLE_EQ(r.get_quantity("E", D::Pressure), 2.1e11);
  EXPECT_DOUBLE_EQ(r.get_quantity("h", D::Length), 4e-6);
  EXPECT_DOUBLE_EQ(r.get_quantity("h_micro", D::Length), 4e-6);
  EXPECT_DOUBLE_EQ(r.get_quantity("h_mu", D::Length), 4e-6);
  EXPECT_DOUBLE_EQ(r.get_quantity("h_nospace", D::Length), 4e-6);
  EXPECT_DOUBLE_EQ(r.get_quantity("t", D::Time), 1e-5);
  EXPECT_DOUBLE_EQ(r.get_quantity("rho", D::Density), 7854);
  EXPECT_DOUBLE_EQ(r.get_quantity("rho2", D::Density), 2330);
  EXPECT_DOUBLE_EQ(r.get_quantity("rho3", D::Density), 2330);
  EXPECT_DOUBLE_EQ(r.get_quantity("k", D::ForcePerLength), -100);
  EXPECT_DOUBLE_EQ(r.get_quantity("p", D::Pressure), 1000);
  EXPECT_DOUBLE_EQ(r.get_quantity("p_atm", D::Pressure), 101325);
  EXPECT_DOUBLE_EQ(r.get_quantity("p_torr", D::Pressure), 101325);
  EXPECT_DOUBLE_EQ(r.get_quantity("V", D::Voltage), 177);
  EXPECT_DOUBLE_EQ(r.get_quantity("f", D::Frequency), 8.15);
  EXPECT_DOUBLE_EQ(r.get_quantity("f2", D::Frequency), 2e9);
  EXPECT_DOUBLE_EQ(r.get_quantity("F", D::Force), 3e-6);
  EXPECT_DOUBLE_EQ(r.get_quantity("m", D::Mass), 2e-6);
  EXPECT_DOUBLE_EQ(r.get_quantity("T", D::Temperature), 300);
  EXPECT_DOUBLE_EQ(r.get_quantity("mu", D::Viscosity), 18.5e-6);
  EXPECT_DOUBLE_EQ(r.get_quantity("plain", D::Pressure), 2.5e11);  // a bare number is SI
  EXPECT_DOUBLE_EQ(r.get_quantity("us", D::Time), 5e-6);
  EXPECT_DOUBLE_EQ(r.get_quantity("absent", D::Time, 2e-3), 2e-3);

  EXPECT_EQ(error_of([&] { r.get_quantity("h", D::Pressure); }),
            "x.yaml: key 'h' = '4 um': unit 'um' is a length, expected a pressure (Pa, kPa, MPa, "
            "GPa, atm, bar, "
            "mbar, torr, Torr)");
  EXPECT_EQ(error_of([&] { r.get_quantity("E", D::Dimensionless); }),
            "x.yaml: key 'E' = '210 GPa': unit 'GPa' is a pressure, expected a plain number");
  EXPECT_EQ(error_of([&] { parse("E: 210 GPaa").root().get_quantity("E", D::Pressure); }),
            "x.yaml: key 'E' = '210 GPaa': unknown unit 'GPaa' (expected a pressure: Pa, kPa, MPa, "
            "GPa, atm, bar, "
            "mbar, torr, Torr)");
  EXPECT_EQ(error_of([&] { parse("L: long").root().get_quantity("L", D::Length); }),
            "x.yaml: key 'L' = 'long': expected a length, a number with an optional unit (m, cm, "
            "mm, um, nm)");
}

// Long times (a creep run's hours and days) are time units like any other, so the message
// for an unknown one lists them.
TEST_F(CaseFileTest, TimeUnitsIncludeMinutesHoursAndDays) {
  const CaseNode r = parse("a: 2 min\nb: 500 h\nc: 3 d\nd: 5 years\n").root();
  EXPECT_DOUBLE_EQ(r.get_quantity("a", Dimension::Time), 120);
  EXPECT_DOUBLE_EQ(r.get_quantity("b", Dimension::Time), 500 * 3600.0);
  EXPECT_DOUBLE_EQ(r.get_quantity("c", Dimension::Time), 3 * 86400.0);
  EXPECT_EQ(error_of([&] { r.get_quantity("d", Dimension::Time); }),
            "x.yaml: key 'd' = '5 years': unknown unit 'years' (expected a time: s, ms, us, ns, "
            "min, h, d)");
}

TEST_F(CaseFileTest, QuantitySequences) {
  const CaseFile cf = parse("at: [1 um, 2 um]\nxs: [1 mm, 2, 3 cm]\nbad: [1 um, 2 GPa]\n");
  const CaseNode r = cf.root();
  EXPECT_EQ(r.get_vec3_quantity("at", Dimension::Length), Vec3(1e-6, 2e-6, 0));
  const auto xs = r.get_quantities("xs", Dimension::Length);
  ASSERT_EQ(xs.size(), 3u);
  EXPECT_DOUBLE_EQ(xs[0], 1e-3);
  EXPECT_DOUBLE_EQ(xs[1], 2);
  EXPECT_DOUBLE_EQ(xs[2], 3e-2);
  EXPECT_EQ(error_of([&] { r.get_vec3_quantity("bad", Dimension::Length); }),
            "x.yaml: key 'bad' = [1 um, 2 GPa]: item 1: unit 'GPa' is a pressure, expected a "
            "length (m, cm, mm, "
            "um, nm)");
}

TEST_F(CaseFileTest, NullValueTakesDefault) {
  const CaseFile cf = parse("solver:\n  rtol:\n  atol: ~\nboundary:\n");
  const CaseNode solver = cf.root().child("solver");
  EXPECT_DOUBLE_EQ(solver.get_real("rtol", 1e-6), 1e-6);
  EXPECT_DOUBLE_EQ(solver.get_real("atol", 1e-9), 1e-9);
  EXPECT_EQ(error_of([&] { solver.get_real("rtol"); }),
            "x.yaml: key 'solver.rtol' = null: expected a number");
  // An empty map (key with no value) is a map with no keys.
  const CaseNode boundary = cf.root().child("boundary");
  EXPECT_FALSE(boundary.has("left"));
  EXPECT_TRUE(boundary.keys().empty());
  EXPECT_EQ(boundary.size(), 0u);
  EXPECT_NO_THROW(cf.check_all_used());
}

TEST_F(CaseFileTest, ChildOrEmptyUsesDefaults) {
  const CaseFile cf = parse("a: 1\n");
  const CaseNode damping = cf.root().child_or_empty("damping");
  EXPECT_EQ(damping.path(), "damping");
  EXPECT_FALSE(damping.has("alpha"));
  EXPECT_DOUBLE_EQ(damping.get_real("alpha", 0.5), 0.5);
  EXPECT_EQ(error_of([&] { damping.get_real("alpha"); }), "x.yaml: missing key 'damping.alpha'");
  EXPECT_TRUE(cf.root().has("a"));
  EXPECT_NO_THROW(cf.check_all_used());
}

TEST_F(CaseFileTest, UnknownKeys) {
  {
    const CaseFile cf = parse("solver:\n  rtol: 1e-6\n  rtoll: 1e-7\n");
    cf.root().child("solver").get_real("rtol");
    EXPECT_EQ(error_of([&] { cf.check_all_used(); }), "x.yaml: unknown key 'solver.rtoll'");
  }
  {
    // A whole unread section is reported by its own key.
    const CaseFile cf = parse("mesh: {nx: 2}\noutput: {every: 3}\n");
    cf.root().child("mesh").get_int("nx");
    EXPECT_EQ(error_of([&] { cf.check_all_used(); }), "x.yaml: unknown key 'output'");
  }
  {
    // Sequences of maps: every item's keys count.
    const CaseFile cf =
        parse("probes:\n  - {name: tip, at: [1, 0.5]}\n  - {name: mid, att: [0.5, 0.5]}\n");
    const CaseNode probes = cf.root().child("probes");
    for (std::size_t i = 0; i < probes.size(); ++i) {
      probes.item(i).get_string("name");
      probes.item(i).get_vec3("at", Vec3::Zero());
    }
    EXPECT_EQ(error_of([&] { cf.check_all_used(); }), "x.yaml: unknown key 'probes[1].att'");
  }
  {
    // The first unread key in file order, at any depth.
    const CaseFile cf = parse("a: {b: {c: 1, d: 2}}\ne: 3\n");
    cf.root().child("a").child("b").get_int("c");
    EXPECT_EQ(error_of([&] { cf.check_all_used(); }), "x.yaml: unknown key 'a.b.d'");
  }
  {
    // has() and keys read with a default count as read; absent ones are no concern.
    const CaseFile cf = parse("a: 1\nb: 2\n");
    EXPECT_TRUE(cf.root().has("a"));
    EXPECT_EQ(cf.root().get_int("b", 0), 2);
    EXPECT_EQ(cf.root().get_int("c", 0), 0);
    EXPECT_NO_THROW(cf.check_all_used());
  }
}

TEST_F(CaseFileTest, Overrides) {
  const std::string path = write("case.yaml", kCase);
  const CaseFile cf =
      CaseFile::load(path, {"mesh.nx=320", "material.E=210 GPa", "probes[0].at=[2, 1]",
                            "probes.1.name=center", "solver.method=newmark"});
  const CaseNode root = cf.root();
  EXPECT_EQ(root.child("mesh").get_int("nx"), 320);
  EXPECT_DOUBLE_EQ(root.child("material").get_quantity("E", Dimension::Pressure), 2.1e11);
  EXPECT_EQ(root.child("probes").item(0).get_vec3("at"), Vec3(2, 1, 0));
  EXPECT_EQ(root.child("probes").item(1).get_string("name"), "center");
  EXPECT_EQ(root.child("solver").get_string("method"), "newmark");  // added: parent map exists
  EXPECT_EQ(cf.path(), path);
  EXPECT_EQ(cf.overrides().size(), 5u);
  EXPECT_NE(cf.text().find("nx: 40"), std::string::npos);             // the file as read
  EXPECT_NE(cf.effective_text().find("nx: 320"), std::string::npos);  // after overrides
}

TEST_F(CaseFileTest, OverrideErrors) {
  EXPECT_EQ(error_of([&] { parse(kCase, {"mesh.nx"}); }),
            "x.yaml: malformed override 'mesh.nx' (expected dotted.key=value)");
  EXPECT_EQ(error_of([&] { parse(kCase, {"=3"}); }),
            "x.yaml: malformed override '=3' (expected dotted.key=value)");
  EXPECT_EQ(error_of([&] { parse(kCase, {"mesh..nx=3"}); }),
            "x.yaml: malformed override 'mesh..nx=3' (expected dotted.key=value)");
  EXPECT_EQ(error_of([&] { parse(kCase, {"solver.newton.maxit=3"}); }),
            "x.yaml: key 'solver.newton.maxit' in override 'solver.newton.maxit=3': "
            "'solver.newton' does not exist");
  EXPECT_EQ(error_of([&] { parse(kCase, {"mesh.nx.a=3"}); }),
            "x.yaml: key 'mesh.nx.a' in override 'mesh.nx.a=3': 'mesh.nx' is not a map");
  EXPECT_EQ(error_of([&] { parse(kCase, {"probes[5].name=x"}); }),
            "x.yaml: key 'probes[5].name' in override 'probes[5].name=x': 'probes' has no item 5 "
            "(it has 2)");
  const std::string bad_yaml = error_of([&] { parse(kCase, {"mesh.nx=[1, 2"}); });
  EXPECT_EQ(bad_yaml.rfind("x.yaml: key 'mesh.nx' in override 'mesh.nx=[1, 2': ", 0), 0u)
      << bad_yaml;
}

TEST_F(CaseFileTest, OverrideOfUnknownKeyIsFlaggedLater) {
  const CaseFile cf = parse("solver:\n  rtol: 1e-6\n", {"solver.rtoll=1e-8"});
  EXPECT_DOUBLE_EQ(cf.root().child("solver").get_real("rtol"), 1e-6);
  EXPECT_EQ(error_of([&] { cf.check_all_used(); }), "x.yaml: unknown key 'solver.rtoll'");
  // An override into an empty section adds the key there.
  const CaseFile cf2 = parse("solver:\n", {"solver.rtol=1e-8"});
  EXPECT_DOUBLE_EQ(cf2.root().child("solver").get_real("rtol"), 1e-8);
  EXPECT_NO_THROW(cf2.check_all_used());
}

TEST_F(CaseFileTest, FileErrors) {
  const std::string missing = (dir_ / "nope.yaml").string();
  EXPECT_EQ(error_of([&] { CaseFile::load(missing); }), missing + ": cannot open the case file");

  const std::string bad = write("bad.yaml", "mesh:\n  nx: [1, 2\n  ny: 3\n");
  const std::string msg = error_of([&] { CaseFile::load(bad); });
  EXPECT_EQ(msg.rfind(bad + ": line ", 0), 0u) << msg;
  EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;

  EXPECT_EQ(error_of([&] { parse("- a\n- b\n"); }),
            "x.yaml: expected a map of keys at the top level");
  EXPECT_EQ(error_of([&] { parse("a: 1\nb: {c: 1, c: 2}\n"); }), "x.yaml: key 'b.c' appears twice");
  EXPECT_NO_THROW(parse(""));  // an empty case is an empty map
}

TEST_F(CaseFileTest, MessagesAreOneLine) {
  const CaseFile cf = parse("text: |\n  line one\n  line two\n");
  const std::string msg = error_of([&] { cf.root().get_real("text"); });
  EXPECT_EQ(msg, "x.yaml: key 'text' = 'line one line two ': expected a number");
}

}  // namespace
}  // namespace rfmems
