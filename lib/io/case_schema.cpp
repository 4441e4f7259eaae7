// Printing a driver's case schema and comparing a reader's reads with it.
#include "io/case_schema.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <set>
#include <string_view>

namespace rfmems {

namespace {

constexpr std::array kDimensions = {
    Dimension::Dimensionless,  Dimension::Length,    Dimension::Pressure,
    Dimension::Time,           Dimension::Density,   Dimension::Force,
    Dimension::ForcePerLength, Dimension::Moment,    Dimension::Voltage,
    Dimension::Frequency,      Dimension::Mass,      Dimension::Temperature,
    Dimension::Velocity,       Dimension::Viscosity,
};

// The SI unit of a type that names a dimension ("length", "vector of length", "list of
// voltage"); "" for the others.
std::string unit_of_type(std::string_view type) {
  for (const std::string_view prefix : {"vector of ", "list of "})
    if (type.starts_with(prefix)) type.remove_prefix(prefix.size());
  for (const Dimension d : kDimensions)
    if (type == quantity_type(d)) return si_unit(d);
  return "";
}

std::string join_path(const std::string& section, const std::string& key) {
  return section.empty() ? key : section + "." + key;
}

std::vector<std::string_view> split_dots(std::string_view path) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = path.find('.', start);
    out.push_back(path.substr(start, dot == std::string_view::npos ? dot : dot - start));
    if (dot == std::string_view::npos) return out;
    start = dot + 1;
  }
}

// A declared segment "<name>" (possibly "<name>[]") matches any key (with the same suffix).
bool segment_matches(std::string_view declared, std::string_view read) {
  if (!declared.starts_with('<')) return declared == read;
  const std::size_t close = declared.find('>');
  if (close == std::string_view::npos) return false;
  const std::string_view suffix = declared.substr(close + 1);
  return read.size() > suffix.size() && read.ends_with(suffix);
}

// With `prefix`, whether the read is a section holding the declared key.
bool path_matches(const std::string& declared, const std::string& read, bool prefix = false) {
  const auto d = split_dots(declared), r = split_dots(read);
  if (prefix ? d.size() <= r.size() : d.size() != r.size()) return false;
  for (std::size_t i = 0; i < r.size(); ++i)
    if (!segment_matches(d[i], r[i])) return false;
  return true;
}

// Whether some declared key sits under the section `path` (which is then declared with it); a
// list's items count ("probes" holds "probes[].at").
bool holds_declared_keys(const CaseSchema& schema, const std::string& path) {
  auto without_items = [](std::string p) {
    for (std::size_t i; (i = p.find("[]")) != std::string::npos;) p.erase(i, 2);
    return p;
  };
  for (const CaseKeyGroup& group : schema)
    for (const CaseKey& key : group.keys)
      if (path_matches(without_items(join_path(group.section, key.path)), without_items(path),
                       true))
        return true;
  return false;
}

// The declarations of a read: those of its exact path, else those whose "<name>" segments
// match it. A key may be declared more than once when its type depends on another key (a
// boundary's value is a displacement or a traction by the boundary's type).
std::vector<const CaseKey*> find_declarations(const CaseSchema& schema, const std::string& path) {
  std::vector<const CaseKey*> exact, wildcard;
  for (const CaseKeyGroup& group : schema)
    for (const CaseKey& key : group.keys) {
      const std::string full = join_path(group.section, key.path);
      if (full == path)
        exact.push_back(&key);
      else if (path_matches(full, path))
        wildcard.push_back(&key);
    }
  return exact.empty() ? wildcard : exact;
}

// Text in parentheses is computed from other keys and not compared (but "(required)" is).
bool compared(const std::string& text) { return text == kRequiredKey || !text.starts_with('('); }

// A read allows what its declaration allows; a choice may allow fewer (a reader that takes
// only the choices meaningful where it is called).
bool allowed_within(const CaseKeyRead& read, const std::string& declared) {
  if (read.allowed.empty()) return true;  // a second reader that leaves the check to the first
  if (read.type != "choice") return read.allowed == declared;
  auto items = [](const std::string& list) {
    std::set<std::string> out;
    std::size_t start = 0;
    while (start <= list.size()) {
      const std::size_t comma = std::min(list.find(", ", start), list.size());
      out.insert(list.substr(start, comma - start));
      start = comma + 2;
    }
    return out;
  };
  const std::set<std::string> r = items(read.allowed), d = items(declared);
  return std::includes(d.begin(), d.end(), r.begin(), r.end());
}

std::string cell(std::string text) {
  std::string out;
  for (const char c : text) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

}  // namespace

std::string quantity_type(Dimension d) { return dimension_name(d); }

CaseSchema join_schemas(const std::vector<CaseSchema>& parts) {
  CaseSchema out;
  for (const CaseSchema& part : parts)
    for (const CaseKeyGroup& group : part)
      if (std::none_of(out.begin(), out.end(), [&](const CaseKeyGroup& g) {
            return g.section == group.section && g.title == group.title;
          }))
        out.push_back(group);
  return out;
}

std::string format_case_schema(const std::string& program, const CaseSchema& schema) {
  std::string out = fmt::format(
      "# Case keys of {}\n\n"
      "Quantities take a number in SI units or a string with a unit (\"4 um\", \"210 GPa\"). "
      "A default in parentheses depends on other keys.\n",
      program);
  for (const CaseKeyGroup& group : schema) {
    out += fmt::format("\n## {}: {}\n\n", group.section.empty() ? "(top level)" : group.section,
                       group.title);
    out += "| key | type | unit | default | allowed | meaning |\n";
    out += "|---|---|---|---|---|---|\n";
    for (const CaseKey& key : group.keys)
      out += fmt::format("| `{}` | {} | {} | {} | {} | {} |\n", join_path(group.section, key.path),
                         cell(key.type), unit_of_type(key.type), cell(key.default_value),
                         cell(key.allowed), cell(key.meaning));
  }
  return out;
}

std::vector<std::string> case_schema_mismatches(const CaseSchema& schema,
                                                const std::vector<CaseKeyRead>& reads) {
  std::vector<std::string> out;
  auto describe = [](const CaseKeyRead& r) {
    return fmt::format("type '{}', default '{}', allowed '{}'", r.type, r.default_value, r.allowed);
  };
  for (const CaseKeyRead& read : reads) {
    const std::vector<const CaseKey*> keys = find_declarations(schema, read.path);
    if (read.type == "section" && holds_declared_keys(schema, read.path)) continue;
    if (keys.empty()) {
      out.push_back(
          fmt::format("key '{}' is read but not declared: {}", read.path, describe(read)));
      continue;
    }
    auto agrees = [&](const CaseKey* key) {
      // A reader may take any key as a node (to count a list's items) or another type's key
      // as its raw text (a choice, a duration "500 h"); whether a section is required depends
      // on the caller.
      if (read.type == "section" || (read.type == "text" && key->type != "text")) return true;
      return key->type == read.type &&
             (!compared(key->default_value) || key->default_value == read.default_value) &&
             (!compared(key->allowed) || allowed_within(read, key->allowed));
    };
    if (std::none_of(keys.begin(), keys.end(), agrees))
      out.push_back(fmt::format(
          "key '{}' is read with {} but declared with {}", read.path, describe(read),
          describe({read.path, keys[0]->type, keys[0]->default_value, keys[0]->allowed})));
  }
  return out;
}

}  // namespace rfmems
