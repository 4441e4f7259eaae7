// Reading case key declarations from their YAML text.
#include "io/case_schema_yaml.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <initializer_list>
#include <stdexcept>
#include <vector>

namespace rfmems {

namespace {

class DeclarationReader {
 public:
  explicit DeclarationReader(const std::string& name) : name_(name) {}

  [[noreturn]] void fail(const YAML::Mark& at, const std::string& what) const {
    if (at.is_null()) throw std::logic_error(fmt::format("case keys {}: {}", name_, what));
    throw std::logic_error(fmt::format("case keys {}, line {}: {}", name_, at.line + 1, what));
  }

  // A map with the fields `required` and, of `optional`, those it gives; nothing else.
  void expect_fields(const YAML::Node& node, const std::string& what,
                     std::initializer_list<const char*> required,
                     std::initializer_list<const char*> optional = {}) const {
    if (!node.IsMap()) fail(node.Mark(), fmt::format("{} is not a map", what));
    std::vector<std::string> seen;
    for (const auto& field : node) {
      const std::string key = field.first.Scalar();
      auto is = [&](const char* f) { return key == f; };
      if (std::none_of(required.begin(), required.end(), is) &&
          std::none_of(optional.begin(), optional.end(), is))
        fail(field.first.Mark(), fmt::format("{}: unknown field '{}'", what, key));
      if (std::find(seen.begin(), seen.end(), key) != seen.end())
        fail(field.first.Mark(), fmt::format("{}: field '{}' given twice", what, key));
      seen.push_back(key);
    }
    for (const char* f : required)
      if (std::find(seen.begin(), seen.end(), f) == seen.end())
        fail(node.Mark(), fmt::format("{}: no field '{}'", what, f));
  }

  // The text of a field; absent (for an optional field), "".
  std::string text(const YAML::Node& node, const char* field, const std::string& what) const {
    for (const auto& f : node) {
      if (f.first.Scalar() != field) continue;
      if (!f.second.IsScalar())
        fail(f.first.Mark(),
             fmt::format("{}: field '{}' is not a text (an empty one is written \"\")", what,
                         field));
      return f.second.Scalar();
    }
    return "";
  }

  CaseKey key(const YAML::Node& node, const std::string& group) const {
    const std::string what = fmt::format("a key of group '{}'", group);
    expect_fields(node, what, {"path", "type", "default", "meaning"}, {"allowed"});
    const std::string path = text(node, "path", what);
    const std::string of_key = fmt::format("key '{}'", path);
    return {path, text(node, "type", of_key), text(node, "default", of_key),
            text(node, "allowed", of_key), text(node, "meaning", of_key)};
  }

  CaseKeyGroup group(const YAML::Node& node) const {
    expect_fields(node, "a group", {"section", "title", "keys"});
    CaseKeyGroup g{text(node, "section", "a group"), text(node, "title", "a group"), {}};
    // Named as --help-case heads it.
    const std::string label =
        fmt::format("{}: {}", g.section.empty() ? "(top level)" : g.section, g.title);
    const YAML::Node keys = node["keys"];
    if (!keys.IsSequence() || keys.size() == 0)
      fail(keys.Mark().is_null() ? node.Mark() : keys.Mark(),
           fmt::format("group '{}': keys is not a list of keys", label));
    for (const YAML::Node& k : keys) g.keys.push_back(key(k, label));
    return g;
  }

  CaseSchema schema(const std::string& text) const {
    YAML::Node root;
    try {
      root = YAML::Load(text);
    } catch (const YAML::Exception& e) {
      fail(e.mark, e.msg);
    }
    if (!root.IsSequence() || root.size() == 0)
      fail(root.Mark(), "the file is not a list of groups");
    CaseSchema out;
    for (const YAML::Node& g : root) out.push_back(group(g));
    return out;
  }

 private:
  std::string name_;
};

}  // namespace

CaseSchema parse_case_schema(const std::string& text, const std::string& name) {
  return DeclarationReader(name).schema(text);
}

CaseSchema embedded_case_schema(std::string_view name) {
  const std::span<const EmbeddedCaseKeys> files = embedded_case_key_files();
  const auto file = std::find_if(files.begin(), files.end(),
                                 [&](const EmbeddedCaseKeys& f) { return name == f.name; });
  if (file == files.end())
    throw std::logic_error(fmt::format(
        "case keys {}: no embedded file of that name (lib/**/*.keys.yaml, by the path below lib/)",
        name));
  return parse_case_schema(file->text, file->name);
}

}  // namespace rfmems
