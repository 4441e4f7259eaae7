// Case key declarations as YAML: a group's fields come through as written, a malformed
// declaration fails naming its file and line, and every embedded file parses.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "io/case_schema_yaml.hpp"

namespace rfmems {
namespace {

// The message of the std::logic_error parsing `text` throws; "" if it parses.
std::string parse_error(const std::string& text) {
  try {
    parse_case_schema(text, "test/bad.keys.yaml");
  } catch (const std::logic_error& e) {
    return e.what();
  }
  return "";
}

TEST(CaseSchemaYaml, AGroupHasTheFieldsAsWritten) {
  const CaseSchema schema = parse_case_schema(R"yaml(
- section: solver
  title: "the solver (defaults: Newton)"
  keys:
    - path: rtol
      type: number
      default: "1e-06"
      allowed: in (0, 1)
      meaning: the relative tolerance
    - path: <patch>.value
      type: vector of length
      default: (required)
      meaning: "the value; a text with \"quotes\""
- section: ""
  title: the top level
  keys:
    - {path: name, type: text, default: "false", allowed: "> 0", meaning: a name}
)yaml",
                                              "test/good.keys.yaml");
  ASSERT_EQ(schema.size(), 2u);
  const CaseKeyGroup& solver = schema[0];
  EXPECT_EQ(solver.section, "solver");
  EXPECT_EQ(solver.title, "the solver (defaults: Newton)");
  ASSERT_EQ(solver.keys.size(), 2u);
  const CaseKey& rtol = solver.keys[0];
  EXPECT_EQ(rtol.path, "rtol");
  EXPECT_EQ(rtol.type, "number");
  EXPECT_EQ(rtol.default_value, "1e-06");
  EXPECT_EQ(rtol.allowed, "in (0, 1)");
  EXPECT_EQ(rtol.meaning, "the relative tolerance");
  const CaseKey& value = solver.keys[1];
  EXPECT_EQ(value.path, "<patch>.value");
  EXPECT_EQ(value.default_value, "(required)");
  EXPECT_EQ(value.allowed, "");  // left out: anything of the type
  EXPECT_EQ(value.meaning, "the value; a text with \"quotes\"");
  EXPECT_EQ(schema[1].section, "");
  EXPECT_EQ(schema[1].keys[0].default_value, "false");
  EXPECT_EQ(schema[1].keys[0].allowed, "> 0");
}

TEST(CaseSchemaYaml, AMalformedDeclarationNamesItsFileAndLine) {
  // A key without a type.
  EXPECT_EQ(parse_error("- section: solver\n"
                        "  title: the solver\n"
                        "  keys:\n"
                        "    - path: rtol\n"
                        "      default: \"1e-06\"\n"
                        "      meaning: the relative tolerance\n"),
            "case keys test/bad.keys.yaml, line 4: a key of group 'solver: the solver': no field "
            "'type'");
  // A misspelt field.
  EXPECT_EQ(parse_error("- section: solver\n"
                        "  title: the solver\n"
                        "  keys:\n"
                        "    - {path: a, type: number, default: \"1\", meaning: m, alowed: x}\n"),
            "case keys test/bad.keys.yaml, line 4: a key of group 'solver: the solver': unknown "
            "field 'alowed'");
  // An empty value, which YAML reads as null, not as "".
  EXPECT_EQ(parse_error("- section:\n  title: t\n  keys: [{path: a, type: b, default: c, "
                        "meaning: d}]\n"),
            "case keys test/bad.keys.yaml, line 1: a group: field 'section' is not a text (an "
            "empty one is written \"\")");
  // Not YAML at all, and YAML that is not a list of groups.
  EXPECT_NE(parse_error("- [unclosed\n").find("case keys test/bad.keys.yaml, line "),
            std::string::npos);
  EXPECT_EQ(parse_error("section: solver\n"),
            "case keys test/bad.keys.yaml, line 1: the file is not a list of groups");
  EXPECT_EQ(parse_error(""), "case keys test/bad.keys.yaml: the file is not a list of groups");
}

TEST(CaseSchemaYaml, EveryEmbeddedFileParses) {
  ASSERT_FALSE(embedded_case_key_files().empty());
  for (const EmbeddedCaseKeys& file : embedded_case_key_files()) {
    SCOPED_TRACE(file.name);
    EXPECT_FALSE(embedded_case_schema(file.name).empty());
  }
  EXPECT_THROW(embedded_case_schema("no/such.keys.yaml"), std::logic_error);
}

}  // namespace
}  // namespace rfmems
