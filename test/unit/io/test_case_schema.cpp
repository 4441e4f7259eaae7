// The case schema: the reads a reader makes are recorded in the declaration's text forms, and
// a read that is undeclared or declared with another type, default or range is named; the
// check at the end of reading runs only when RFMEMS_CHECK_CASE_SCHEMA is set.
#include <gtest/gtest.h>

#include <cstdlib>
#include <limits>
#include <stdexcept>

#include "io/case_file.hpp"
#include "io/case_schema.hpp"

namespace rfmems {
namespace {

const CaseKeyGroup kSolver{"solver",
                           "a test solver",
                           {
                               {"rtol", "number", "0.001", "in (0, 1)", "relative tolerance"},
                               {"atol", "length", "1e-12 m", "> 0", "absolute tolerance"},
                               {"method", "choice", "newton", "newton, picard", "the iteration"},
                               {"steps", "integer", "(required)", ">= 1", "steps"},
                               {"interval", "time", "(end_time / 500)", "> 0", "computed"},
                               {"label", "text", "left", "", "a text with a default"},
                           }};
const CaseKeyGroup kBoundaries{
    "boundaries",
    "boundary conditions",
    {
        {"<name>", "section", "(required)", "", "one boundary"},
        {"<name>.type", "choice", "(required)", "clamped, free", "its type"},
    }};
const CaseKeyGroup kProbes{
    "", "probes", {{"probes[].at", "vector of length", "(required)", "", "point"}}};
const CaseSchema kSchema{kSolver, kBoundaries, kProbes};

// Reads the case the way a reader would, with one read changed by `variant`.
std::vector<std::string> mismatches_of(const std::string& variant) {
  const CaseFile file = CaseFile::parse(
      "solver: {steps: 3}\nboundaries: {left: {type: clamped}}\nprobes: [{at: [1, 2]}]\n",
      "t.yaml");
  const CaseNode solver = file.root().child_or_empty("solver");
  solver.get_real("rtol", variant == "rtol default" ? 1e-4 : 1e-3, Range::open(0.0, 1.0));
  solver.get_quantity("atol", Dimension::Length, 1e-12, Range::positive());
  solver.get_choice("method", {"newton", "picard"}, "newton");
  solver.get_int("steps", Range{1.0, std::numeric_limits<double>::infinity(), false, false});
  solver.get_quantity("interval", Dimension::Time, variant == "interval" ? 7.0 : 3.0,
                      Range::positive());
  solver.get_string("label", variant == "text default" ? "right" : "left");
  solver.get_string("method", "newton");  // a choice read as its raw text
  if (variant == "undeclared") solver.get_bool("verbose", false);
  if (variant == "type") solver.get_real("method", 0.0);
  const CaseNode left = file.root().child("boundaries").child("left");
  left.get_choice("type", {"clamped", "free"});
  file.root().child("probes").item(0).get_vec3_quantity("at", Dimension::Length);
  return case_schema_mismatches(kSchema, file.reads());
}

TEST(CaseSchema, ReadsThatAgreeWithTheDeclarationsPass) {
  EXPECT_TRUE(mismatches_of("").empty()) << mismatches_of("")[0];
  // A default computed from other keys is shown, not compared.
  EXPECT_TRUE(mismatches_of("interval").empty());
}

TEST(CaseSchema, ADifferentDefaultIsNamed) {
  const auto m = mismatches_of("rtol default");
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0],
            "key 'solver.rtol' is read with type 'number', default '0.0001', allowed 'in (0, 1)' "
            "but declared with type 'number', default '0.001', allowed 'in (0, 1)'");
}

TEST(CaseSchema, AnUndeclaredKeyAndAnotherTypeAreNamed) {
  const auto u = mismatches_of("undeclared");
  ASSERT_EQ(u.size(), 1u);
  EXPECT_EQ(u[0],
            "key 'solver.verbose' is read but not declared: type 'bool', default 'false', "
            "allowed ''");
  const auto t = mismatches_of("type");
  ASSERT_EQ(t.size(), 1u);
  EXPECT_NE(t[0].find("key 'solver.method' is read with type 'number'"), std::string::npos);
  const auto d = mismatches_of("text default");
  ASSERT_EQ(d.size(), 1u);
  EXPECT_NE(d[0].find("key 'solver.label' is read with type 'text', default 'right'"),
            std::string::npos);
}

TEST(CaseSchema, CheckAllUsedComparesOnlyWhenAsked) {
  CaseFile file = CaseFile::parse("solver: {steps: 3}\n", "t.yaml");
  file.declare_schema(kSchema);
  file.root().child("solver").get_int(
      "steps", Range{1.0, std::numeric_limits<double>::infinity(), false, false});
  file.root().child("solver").get_bool("verbose", false);  // undeclared
  ::unsetenv("RFMEMS_CHECK_CASE_SCHEMA");
  EXPECT_NO_THROW(file.check_all_used());
  ::setenv("RFMEMS_CHECK_CASE_SCHEMA", "1", 1);
  EXPECT_THROW(file.check_all_used(), std::logic_error);
  ::unsetenv("RFMEMS_CHECK_CASE_SCHEMA");
}

TEST(CaseSchema, TheHelpListsFullPathsWithSiUnits) {
  const std::string text = format_case_schema("prog", kSchema);
  EXPECT_EQ(text.rfind("# Case keys of prog\n", 0), 0u);
  EXPECT_NE(text.find("\n## solver: a test solver\n"), std::string::npos);
  EXPECT_NE(text.find("| `solver.atol` | length | m | 1e-12 m | > 0 | absolute tolerance |"),
            std::string::npos);
  EXPECT_NE(text.find("| `boundaries.<name>.type` | choice |  | (required) | clamped, free |"),
            std::string::npos);
}

}  // namespace
}  // namespace rfmems
