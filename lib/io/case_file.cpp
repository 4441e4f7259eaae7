// Loading case files, applying overrides, the typed getters of CaseNode and the unknown-key
// check. Parsing is yaml-cpp's; this file only walks the tree and words the errors.
#include "io/case_file.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <variant>

namespace rfmems {

namespace detail {
// Shared by the CaseFile and every CaseNode taken from it.
struct CaseState {
  std::string file;
  std::string text;
  std::vector<std::string> overrides;
  YAML::Node root;
  std::set<std::string> used;   // dotted paths of keys read so far
  std::set<CaseKeyRead> reads;  // every read, for the schema check
  std::optional<CaseSchema> schema;
};
}  // namespace detail

namespace {

bool absent(const YAML::Node& n) { return !n || !n.IsDefined() || n.IsNull(); }

std::string join_key(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

std::string join_index(const std::string& path, std::size_t i) {
  return path + "[" + std::to_string(i) + "]";
}

// The value as shown in messages: numbers bare, other scalars quoted, collections in YAML
// flow style; one line, cut if long.
std::string describe(const YAML::Node& n) {
  std::string text;
  if (absent(n)) return "null";
  if (n.IsScalar()) {
    double x = 0.0;
    text = parse_real(n.Scalar(), x) ? n.Scalar() : "'" + n.Scalar() + "'";
  } else {
    YAML::Emitter out;
    out.SetMapFormat(YAML::Flow);
    out.SetSeqFormat(YAML::Flow);
    out << n;
    text = out.c_str();
  }
  std::replace(text.begin(), text.end(), '\n', ' ');
  if (text.size() > 80) text = text.substr(0, 77) + "...";
  return text;
}

// Every map key must be a scalar and appear once; checked at load so lookups can be simple.
void validate_tree(const YAML::Node& node, const std::string& path, const std::string& file) {
  if (node.IsMap()) {
    std::set<std::string> seen;
    for (const auto& kv : node) {
      if (!kv.first.IsScalar())
        throw InputError(fmt::format("{}: key {} in '{}' is not a plain name", file,
                                     describe(kv.first), path.empty() ? "(top level)" : path));
      const std::string key = join_key(path, kv.first.Scalar());
      if (!seen.insert(kv.first.Scalar()).second)
        throw InputError(fmt::format("{}: key '{}' appears twice", file, key));
      validate_tree(kv.second, key, file);
    }
  } else if (node.IsSequence()) {
    for (std::size_t i = 0; i < node.size(); ++i) validate_tree(node[i], join_index(path, i), file);
  }
}

// First unread key under node, in file order; empty if all were read.
std::optional<std::string> first_unused(const YAML::Node& node, const std::string& path,
                                        const std::set<std::string>& used) {
  if (node.IsMap()) {
    for (const auto& kv : node) {
      const std::string key = join_key(path, kv.first.Scalar());
      if (!used.contains(key)) return key;
      if (auto inner = first_unused(kv.second, key, used)) return inner;
    }
  } else if (node.IsSequence()) {
    for (std::size_t i = 0; i < node.size(); ++i)
      if (auto inner = first_unused(node[i], join_index(path, i), used)) return inner;
  }
  return std::nullopt;
}

std::string read_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path + ": is a directory, not a case file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the case file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(path + ": cannot read the case file");
  return text.str();
}

YAML::Node parse_yaml(const std::string& text, const std::string& where) {
  try {
    return YAML::Load(text);
  } catch (const YAML::Exception& e) {
    if (e.mark.is_null()) throw InputError(fmt::format("{}: {}", where, e.msg));
    throw InputError(fmt::format("{}: line {}, column {}: {}", where, e.mark.line + 1,
                                 e.mark.column + 1, e.msg));
  }
}

// One step of an override path: a map key or a sequence index.
using PathToken = std::variant<std::string, std::size_t>;

// "probes[0].at" → probes, 0, at; "probes.0.at" gives a key "0" that is read as an index when
// the node is a sequence. Empty on a malformed path.
std::vector<PathToken> split_override_path(const std::string& path) {
  std::vector<PathToken> tokens;
  std::size_t pos = 0;
  while (pos <= path.size()) {
    const std::size_t end = std::min(path.find('.', pos), path.size());
    std::string segment = path.substr(pos, end - pos);
    const std::size_t bracket = segment.find('[');
    const std::string name = segment.substr(0, bracket);
    if (name.empty() && (bracket != 0 || tokens.empty())) return {};
    if (!name.empty()) tokens.emplace_back(name);
    for (std::size_t b = bracket; b != std::string::npos && b < segment.size();) {
      const std::size_t close = segment.find(']', b);
      if (segment[b] != '[' || close == std::string::npos) return {};
      std::size_t index = 0;
      const auto* first = segment.data() + b + 1;
      const auto* last = segment.data() + close;
      const auto r = std::from_chars(first, last, index);
      if (first == last || r.ptr != last) return {};
      tokens.emplace_back(index);
      b = close + 1;
    }
    pos = end + 1;
  }
  return tokens;
}

std::string path_string(const std::vector<PathToken>& tokens, std::size_t n) {
  std::string s;
  for (std::size_t i = 0; i < n; ++i) {
    if (const auto* key = std::get_if<std::string>(&tokens[i]))
      s = join_key(s, *key);
    else
      s = join_index(s, std::get<std::size_t>(tokens[i]));
  }
  return s;
}

// A numeric map key may index a sequence ("probes.0.at").
std::optional<std::size_t> as_index(const PathToken& token) {
  if (const auto* i = std::get_if<std::size_t>(&token)) return *i;
  const auto& key = std::get<std::string>(token);
  std::size_t index = 0;
  const auto r = std::from_chars(key.data(), key.data() + key.size(), index);
  if (r.ec == std::errc() && r.ptr == key.data() + key.size()) return index;
  return std::nullopt;
}

void apply_override(detail::CaseState& state, const std::string& override_text) {
  const std::size_t eq = override_text.find('=');
  const std::string key_text = eq == std::string::npos ? "" : override_text.substr(0, eq);
  const std::vector<PathToken> tokens = split_override_path(key_text);
  if (eq == std::string::npos || tokens.empty())
    throw InputError(fmt::format("{}: malformed override '{}' (expected dotted.key=value)",
                                 state.file, override_text));
  const std::string full = path_string(tokens, tokens.size());
  const std::string where =
      fmt::format("{}: key '{}' in override '{}'", state.file, full, override_text);
  const YAML::Node value = parse_yaml(override_text.substr(eq + 1), where);

  YAML::Node node = state.root;  // handles share the tree: assignments below edit it
  for (std::size_t t = 0; t < tokens.size(); ++t) {
    const bool last = t + 1 == tokens.size();
    const std::string parent = t == 0 ? std::string("(top level)") : path_string(tokens, t);
    YAML::Node next;
    bool found = false;
    if (node.IsSequence()) {
      const auto index = as_index(tokens[t]);
      if (!index) throw InputError(fmt::format("{}: '{}' is a sequence, not a map", where, parent));
      if (*index >= node.size())
        throw InputError(
            fmt::format("{}: '{}' has no item {} (it has {})", where, parent, *index, node.size()));
      if (last) {
        node[*index] = value;
        return;
      }
      next.reset(node[*index]);
      found = true;
    } else if (node.IsMap() || (node.IsNull() && t > 0)) {
      const auto* key = std::get_if<std::string>(&tokens[t]);
      if (key == nullptr)
        throw InputError(fmt::format("{}: '{}' is a map, not a sequence", where, parent));
      if (last) {
        node[*key] = value;  // replaces, or adds at the end of the map
        return;
      }
      for (auto kv : node) {
        if (kv.first.Scalar() == *key) {
          next.reset(kv.second);
          found = true;
          break;
        }
      }
    } else {
      throw InputError(fmt::format("{}: '{}' is not a map", where, parent));
    }
    if (!found)
      throw InputError(fmt::format("{}: '{}' does not exist", where, path_string(tokens, t + 1)));
    node.reset(next);
  }
}

}  // namespace

// ---- Range -----------------------------------------------------------------------------

bool Range::contains(double x) const {
  const bool above = min_open ? x > min : x >= min;
  const bool below = max_open ? x < max : x <= max;
  return above && below;
}

std::string Range::describe() const {
  const bool has_min = std::isfinite(min), has_max = std::isfinite(max);
  if (has_min && has_max)
    return fmt::format("must be in {}{}, {}{}", min_open ? "(" : "[", min, max,
                       max_open ? ")" : "]");
  if (has_min) return fmt::format("must be {} {}", min_open ? ">" : ">=", min);
  if (has_max) return fmt::format("must be {} {}", max_open ? "<" : "<=", max);
  return "must be a number";
}

// ---- CaseNode: structure ------------------------------------------------------------------

CaseNode::CaseNode(std::shared_ptr<detail::CaseState> state, YAML::Node node, std::string path)
    : state_(std::move(state)), node_(std::move(node)), path_(std::move(path)) {}

std::string CaseNode::key_path(const std::string& key) const { return join_key(path_, key); }

const std::string& CaseNode::file() const { return state_->file; }

void CaseNode::require_map() const {
  if (!absent(node_) && !node_.IsMap()) fail("expected a map");
}

YAML::Node CaseNode::lookup(const std::string& key) const {
  require_map();
  if (absent(node_)) return YAML::Node();
  for (const auto& kv : node_) {
    if (kv.first.Scalar() == key) {
      state_->used.insert(key_path(key));
      return kv.second;
    }
  }
  return YAML::Node();
}

YAML::Node CaseNode::require_key(const std::string& key) const {
  require_map();
  if (!absent(node_)) {
    for (const auto& kv : node_) {
      if (kv.first.Scalar() == key) {
        state_->used.insert(key_path(key));
        return kv.second;
      }
    }
  }
  throw InputError(fmt::format("{}: missing key '{}'", file(), key_path(key)));
}

// A presence test is not a read of the schema: a reader also asks for keys it refuses.
bool CaseNode::has(const std::string& key) const { return !absent(lookup(key)); }

CaseNode CaseNode::child(const std::string& key) const {
  note(key, "section", kRequiredKey, "");
  const YAML::Node value = require_key(key);
  if (value.IsScalar()) fail(key, "expected a map or a sequence");
  return CaseNode(state_, value, key_path(key));
}

CaseNode CaseNode::child_or_empty(const std::string& key) const {
  note(key, "section", "(empty)", "");
  const YAML::Node value = lookup(key);
  if (!absent(value) && value.IsScalar()) fail(key, "expected a map or a sequence");
  return CaseNode(state_, absent(value) ? YAML::Node() : value, key_path(key));
}

std::vector<std::string> CaseNode::keys() const {
  require_map();
  std::vector<std::string> out;
  if (absent(node_)) return out;
  for (const auto& kv : node_) out.push_back(kv.first.Scalar());
  return out;
}

std::size_t CaseNode::size() const {
  if (absent(node_)) return 0;
  if (!node_.IsSequence()) fail("expected a sequence");
  return node_.size();
}

CaseNode CaseNode::item(std::size_t i) const {
  const std::size_t n = size();
  if (i >= n) fail(fmt::format("has no item {} (it has {})", i, n));
  return CaseNode(state_, node_[i], join_index(path_, i));
}

// ---- CaseNode: errors ---------------------------------------------------------------------

void CaseNode::fail(const std::string& key, const std::string& what) const {
  std::optional<YAML::Node> value;
  if (!absent(node_) && node_.IsMap())
    for (const auto& kv : node_)
      if (kv.first.Scalar() == key) value.emplace(kv.second);
  if (!value) throw InputError(fmt::format("{}: key '{}': {}", file(), key_path(key), what));
  throw InputError(
      fmt::format("{}: key '{}' = {}: {}", file(), key_path(key), describe(*value), what));
}

void CaseNode::require(bool condition, const std::string& key, const std::string& what) const {
  if (!condition) fail(key, what);
}

void CaseNode::fail(const std::string& what) const {
  const std::string name = path_.empty() ? std::string("(top level)") : path_;
  throw InputError(fmt::format("{}: key '{}' = {}: {}", file(), name, describe(node_), what));
}

// ---- CaseNode: conversions ----------------------------------------------------------------

std::string CaseNode::scalar_text(const std::string& key, const YAML::Node& value,
                                  const char* expected) const {
  if (!value.IsScalar()) fail(key, expected);
  return value.Scalar();
}

Real CaseNode::to_real(const std::string& key, const YAML::Node& value) const {
  double x = 0.0;
  if (!parse_real(scalar_text(key, value, "expected a number"), x)) fail(key, "expected a number");
  return x;
}

long CaseNode::to_int(const std::string& key, const YAML::Node& value) const {
  const std::string text = scalar_text(key, value, "expected an integer");
  std::string_view digits = text;
  if (digits.starts_with('+')) digits.remove_prefix(1);
  long n = 0;
  const auto r = std::from_chars(digits.data(), digits.data() + digits.size(), n);
  if (r.ec == std::errc() && r.ptr == digits.data() + digits.size() && !digits.empty()) return n;
  // Also accept reals with an integral value, e.g. "1e6".
  double x = 0.0;
  if (parse_real(text, x) && x == std::floor(x) && std::abs(x) < 9.0e15)
    return static_cast<long>(x);
  fail(key, "expected an integer");
}

Real CaseNode::to_quantity(const std::string& key, const YAML::Node& value, Dimension d) const {
  const std::string text = scalar_text(key, value, "expected a number with an optional unit");
  try {
    return parse_quantity(text, d);
  } catch (const std::invalid_argument& e) {
    fail(key, e.what());
  }
}

void CaseNode::check_range(const std::string& key, Real x, const Range& range) const {
  if (!range.contains(x)) fail(key, range.describe());
}

Vec3 CaseNode::to_vec3(const std::string& key, const YAML::Node& value, const Dimension* d) const {
  const std::string expected = d ? "expected a sequence of 2 or 3 " + dimension_name(*d) + "s"
                                 : "expected a sequence of 2 or 3 numbers";
  if (!value.IsSequence() || value.size() < 2 || value.size() > 3) fail(key, expected);
  Vec3 v = Vec3::Zero();
  for (std::size_t i = 0; i < value.size(); ++i) {
    const YAML::Node item = value[i];
    if (!item.IsScalar()) fail(key, expected);
    if (d == nullptr) {
      if (!parse_real(item.Scalar(), v[static_cast<Eigen::Index>(i)])) fail(key, expected);
    } else {
      try {
        v[static_cast<Eigen::Index>(i)] = parse_quantity(item.Scalar(), *d);
      } catch (const std::invalid_argument& e) {
        fail(key, fmt::format("item {}: {}", i, e.what()));
      }
    }
  }
  return v;
}

// ---- CaseNode: getters ----------------------------------------------------------------------
// Each getter first records the read (type, default and allowed values in the text forms of
// io/case_schema.hpp) for the schema check, then reads.

namespace {

std::string real_text(double x) { return fmt::format("{}", x); }

std::string range_text(const Range& range) {
  const std::string text = range.describe();
  constexpr std::string_view must = "must be ";
  return text.starts_with(must) ? text.substr(must.size()) : text;
}

std::string quantity_text(double x, Dimension d) {
  const std::string unit = si_unit(d);
  return unit.empty() ? real_text(x) : fmt::format("{} {}", x, unit);
}

std::string string_text(const std::string& s) { return s.empty() ? "\"\"" : s; }

}  // namespace

void CaseNode::note(const std::string& key, const std::string& type,
                    const std::string& default_value, const std::string& allowed) const {
  // Sequence items share one declaration: probes[0].at and probes[1].at are probes[].at.
  std::string path;
  const std::string full = key_path(key);
  for (std::size_t i = 0; i < full.size(); ++i) {
    path += full[i];
    if (full[i] == '[') {
      while (i + 1 < full.size() && full[i + 1] != ']') ++i;
    }
  }
  state_->reads.insert({path, type, default_value, allowed});
}

Real CaseNode::get_real(const std::string& key) const {
  note(key, "number", kRequiredKey, "");
  return to_real(key, require_key(key));
}

Real CaseNode::get_real(const std::string& key, Real default_value) const {
  note(key, "number", real_text(default_value), "");
  const YAML::Node v = lookup(key);
  return absent(v) ? default_value : to_real(key, v);
}

Real CaseNode::get_real(const std::string& key, const Range& range) const {
  note(key, "number", kRequiredKey, range_text(range));
  const Real x = to_real(key, require_key(key));
  check_range(key, x, range);
  return x;
}

Real CaseNode::get_real(const std::string& key, Real default_value, const Range& range) const {
  note(key, "number", real_text(default_value), range_text(range));
  const YAML::Node v = lookup(key);
  if (absent(v)) return default_value;
  const Real x = to_real(key, v);
  check_range(key, x, range);
  return x;
}

long CaseNode::get_int(const std::string& key) const {
  note(key, "integer", kRequiredKey, "");
  return to_int(key, require_key(key));
}

long CaseNode::get_int(const std::string& key, long default_value) const {
  note(key, "integer", std::to_string(default_value), "");
  const YAML::Node v = lookup(key);
  return absent(v) ? default_value : to_int(key, v);
}

long CaseNode::get_int(const std::string& key, const Range& range) const {
  note(key, "integer", kRequiredKey, range_text(range));
  const long n = to_int(key, require_key(key));
  check_range(key, static_cast<double>(n), range);
  return n;
}

long CaseNode::get_int(const std::string& key, long default_value, const Range& range) const {
  note(key, "integer", std::to_string(default_value), range_text(range));
  const YAML::Node v = lookup(key);
  if (absent(v)) return default_value;
  const long n = to_int(key, v);
  check_range(key, static_cast<double>(n), range);
  return n;
}

bool CaseNode::to_bool(const std::string& key, const YAML::Node& value) const {
  bool b = false;
  if (!value.IsScalar() || !YAML::convert<bool>::decode(value, b))
    fail(key, "expected true or false");
  return b;
}

bool CaseNode::get_bool(const std::string& key) const {
  note(key, "bool", kRequiredKey, "");
  return to_bool(key, require_key(key));
}

bool CaseNode::get_bool(const std::string& key, bool default_value) const {
  note(key, "bool", default_value ? "true" : "false", "");
  const YAML::Node v = lookup(key);
  return absent(v) ? default_value : to_bool(key, v);
}

std::string CaseNode::get_string(const std::string& key) const {
  note(key, "text", kRequiredKey, "");
  return scalar_text(key, require_key(key), "expected a string");
}

std::string CaseNode::get_string(const std::string& key, const std::string& default_value) const {
  note(key, "text", string_text(default_value), "");
  const YAML::Node v = lookup(key);
  return absent(v) ? default_value : scalar_text(key, v, "expected a string");
}

std::string CaseNode::to_choice(const std::string& key, const YAML::Node& value,
                                const std::vector<std::string>& allowed) const {
  const std::string s = scalar_text(key, value, "expected a string");
  if (std::find(allowed.begin(), allowed.end(), s) == allowed.end())
    fail(key, fmt::format("expected one of: {}", fmt::join(allowed, ", ")));
  return s;
}

std::string CaseNode::get_choice(const std::string& key,
                                 const std::vector<std::string>& allowed) const {
  note(key, "choice", kRequiredKey, fmt::format("{}", fmt::join(allowed, ", ")));
  return to_choice(key, require_key(key), allowed);
}

std::string CaseNode::get_choice(const std::string& key, const std::vector<std::string>& allowed,
                                 const std::string& default_value) const {
  note(key, "choice", string_text(default_value), fmt::format("{}", fmt::join(allowed, ", ")));
  const YAML::Node v = lookup(key);
  return absent(v) ? default_value : to_choice(key, v, allowed);
}

Real CaseNode::get_quantity(const std::string& key, Dimension d) const {
  note(key, quantity_type(d), kRequiredKey, "");
  return to_quantity(key, require_key(key), d);
}

Real CaseNode::get_quantity(const std::string& key, Dimension d, Real default_value) const {
  note(key, quantity_type(d), quantity_text(default_value, d), "");
  const YAML::Node v = lookup(key);
  return absent(v) ? default_value : to_quantity(key, v, d);
}

Real CaseNode::get_quantity(const std::string& key, Dimension d, const Range& range) const {
  note(key, quantity_type(d), kRequiredKey, range_text(range));
  const Real x = to_quantity(key, require_key(key), d);
  check_range(key, x, range);
  return x;
}

Real CaseNode::get_quantity(const std::string& key, Dimension d, Real default_value,
                            const Range& range) const {
  note(key, quantity_type(d), quantity_text(default_value, d), range_text(range));
  const YAML::Node v = lookup(key);
  if (absent(v)) return default_value;
  const Real x = to_quantity(key, v, d);
  check_range(key, x, range);
  return x;
}

Vec3 CaseNode::get_vec3(const std::string& key) const {
  note(key, "vector", kRequiredKey, "");
  return to_vec3(key, require_key(key), nullptr);
}

Vec3 CaseNode::get_vec3(const std::string& key, const Vec3& default_value) const {
  note(key, "vector",
       fmt::format("[{}, {}, {}]", default_value.x(), default_value.y(), default_value.z()), "");
  const YAML::Node v = lookup(key);
  return absent(v) ? default_value : to_vec3(key, v, nullptr);
}

Vec3 CaseNode::get_vec3_quantity(const std::string& key, Dimension d) const {
  note(key, "vector of " + quantity_type(d), kRequiredKey, "");
  return to_vec3(key, require_key(key), &d);
}

std::vector<Real> CaseNode::get_reals(const std::string& key) const {
  note(key, "list of numbers", kRequiredKey, "");
  const YAML::Node v = require_key(key);
  if (!v.IsSequence()) fail(key, "expected a sequence of numbers");
  std::vector<Real> out(v.size());
  for (std::size_t i = 0; i < v.size(); ++i)
    if (!v[i].IsScalar() || !parse_real(v[i].Scalar(), out[i]))
      fail(key, "expected a sequence of numbers");
  return out;
}

std::vector<Real> CaseNode::get_quantities(const std::string& key, Dimension d) const {
  note(key, "list of " + quantity_type(d), kRequiredKey, "");
  const YAML::Node v = require_key(key);
  const std::string expected = "expected a sequence of " + dimension_name(d) + "s";
  if (!v.IsSequence()) fail(key, expected);
  std::vector<Real> out(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!v[i].IsScalar()) fail(key, expected);
    try {
      out[i] = parse_quantity(v[i].Scalar(), d);
    } catch (const std::invalid_argument& e) {
      fail(key, fmt::format("item {}: {}", i, e.what()));
    }
  }
  return out;
}

std::vector<Real> CaseNode::get_quantity_or_list(const std::string& key, Dimension d,
                                                 Real default_value) const {
  note(key, quantity_type(d) + " or list of " + quantity_type(d), quantity_text(default_value, d),
       "");
  const YAML::Node v = lookup(key);
  if (absent(v)) return {default_value};
  if (!v.IsSequence()) return {to_quantity(key, v, d)};
  std::vector<Real> out;
  for (std::size_t i = 0; i < v.size(); ++i) out.push_back(to_quantity(key, v[i], d));
  return out;
}

std::vector<std::string> CaseNode::get_strings(const std::string& key) const {
  note(key, "list of texts", kRequiredKey, "");
  const YAML::Node v = require_key(key);
  if (!v.IsSequence()) fail(key, "expected a sequence of strings");
  std::vector<std::string> out;
  for (const auto& item : v) {
    if (!item.IsScalar()) fail(key, "expected a sequence of strings");
    out.push_back(item.Scalar());
  }
  return out;
}

// ---- CaseFile -----------------------------------------------------------------------------

CaseFile CaseFile::load(const std::string& path, const std::vector<std::string>& overrides) {
  return parse(read_file(path), path, overrides);
}

CaseFile CaseFile::parse(const std::string& text, const std::string& name,
                         const std::vector<std::string>& overrides) {
  auto state = std::make_shared<detail::CaseState>();
  state->file = name;
  state->text = text;
  state->overrides = overrides;
  state->root.reset(parse_yaml(text, name));
  if (absent(state->root)) state->root.reset(YAML::Node(YAML::NodeType::Map));  // empty file
  if (!state->root.IsMap()) throw InputError(name + ": expected a map of keys at the top level");
  validate_tree(state->root, "", name);
  for (const auto& o : overrides) apply_override(*state, o);
  validate_tree(state->root, "", name);
  return CaseFile(std::move(state));
}

CaseNode CaseFile::root() const { return CaseNode(state_, state_->root, ""); }

void CaseFile::check_all_used() const {
  if (auto key = first_unused(state_->root, "", state_->used))
    throw InputError(fmt::format("{}: unknown key '{}'", state_->file, *key));
  const char* check = std::getenv("RFMEMS_CHECK_CASE_SCHEMA");
  if (state_->schema && check != nullptr && *check != '\0' && std::string(check) != "0") {
    const std::vector<std::string> wrong = case_schema_mismatches(*state_->schema, reads());
    if (!wrong.empty())
      throw std::logic_error(
          fmt::format("the case schema differs from the readers ({} reads of "
                      "{}): {}",
                      wrong.size(), state_->file, fmt::join(wrong, "; ")));
  }
}

void CaseFile::declare_schema(const CaseSchema& schema) { state_->schema = schema; }

std::vector<CaseKeyRead> CaseFile::reads() const {
  return {state_->reads.begin(), state_->reads.end()};
}

const std::string& CaseFile::path() const { return state_->file; }
const std::string& CaseFile::text() const { return state_->text; }
const std::vector<std::string>& CaseFile::overrides() const { return state_->overrides; }
std::string CaseFile::effective_text() const { return YAML::Dump(state_->root); }

}  // namespace rfmems
