// Case files: YAML documents describing one simulation, plus command-line overrides.
//
// Drivers read values through CaseNode getters, which check type, unit and range and throw
// InputError with one line naming the file, the dotted key and the offending value:
//   cases/x.yaml: missing key 'material.E'
//   cases/x.yaml: key 'mesh.nx' = 'abc': expected an integer
//   cases/x.yaml: key 'material.nu' = 0.7: must be in (-1, 0.5)
// Every key a getter, child() or has() touches is recorded; CaseFile::check_all_used() then
// reports the first key nobody read (usually a typo such as 'solver.rtoll').
//
// Sequence items get paths like 'probes[0].name'.
#pragma once
#include <yaml-cpp/yaml.h>

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/types.hpp"
#include "io/case_schema.hpp"
#include "io/units.hpp"

namespace rfmems {

// Allowed interval of a number: min/max with open or closed ends (infinite = unbounded).
struct Range {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;
  bool max_open = false;

  static Range positive() { return {0.0, std::numeric_limits<double>::infinity(), true, false}; }
  static Range non_negative() {
    return {0.0, std::numeric_limits<double>::infinity(), false, false};
  }
  static Range closed(double a, double b) { return {a, b, false, false}; }
  static Range open(double a, double b) { return {a, b, true, true}; }

  bool contains(double x) const;
  // "must be in (-1, 0.5)", "must be > 0", "must be <= 1", ...
  std::string describe() const;
};

namespace detail {
struct CaseState;
}

// A handle to one node of a loaded case (a map, a sequence or null), with its dotted path.
// Cheap to copy; stays valid while any handle or the CaseFile lives.
class CaseNode {
 public:
  // Dotted path of this node ("" for the root, "material", "probes[0]").
  const std::string& path() const { return path_; }
  // Dotted path of a key of this node.
  std::string key_path(const std::string& key) const;
  // Name of the case file, for messages.
  const std::string& file() const;

  // --- maps ---
  // True if the key is present (and not null); marks it as read.
  bool has(const std::string& key) const;
  // The map or sequence under key. Missing → InputError.
  CaseNode child(const std::string& key) const;
  // Like child(), but a missing key gives an empty node whose getters all use their defaults.
  CaseNode child_or_empty(const std::string& key) const;
  // Keys of this map in file order (does not mark them as read).
  std::vector<std::string> keys() const;

  // --- sequences ---
  // Number of items; 0 for an empty node. InputError if this node is a map.
  std::size_t size() const;
  // Item i (a map, a sequence or null); scalar items are read with get_reals/get_strings.
  CaseNode item(std::size_t i) const;

  // --- typed values. Forms: (key) required, (key, default), and with a Range. A key present
  // with a null value ("key:" or "key: ~") takes the default. ---
  Real get_real(const std::string& key) const;
  Real get_real(const std::string& key, Real default_value) const;
  Real get_real(const std::string& key, const Range& range) const;
  Real get_real(const std::string& key, Real default_value, const Range& range) const;

  // Integers; a real with an integral value (1e6) is accepted.
  long get_int(const std::string& key) const;
  long get_int(const std::string& key, long default_value) const;
  long get_int(const std::string& key, const Range& range) const;
  long get_int(const std::string& key, long default_value, const Range& range) const;

  // true/false (also yes/no, on/off, as YAML).
  bool get_bool(const std::string& key) const;
  bool get_bool(const std::string& key, bool default_value) const;

  std::string get_string(const std::string& key) const;
  std::string get_string(const std::string& key, const std::string& default_value) const;

  // One of `allowed` (case-sensitive).
  std::string get_choice(const std::string& key, const std::vector<std::string>& allowed) const;
  std::string get_choice(const std::string& key, const std::vector<std::string>& allowed,
                         const std::string& default_value) const;

  // A number in SI or a string "<number> <unit>" of dimension d ("210 GPa", "4 µm").
  Real get_quantity(const std::string& key, Dimension d) const;
  Real get_quantity(const std::string& key, Dimension d, Real default_value) const;
  Real get_quantity(const std::string& key, Dimension d, const Range& range) const;
  Real get_quantity(const std::string& key, Dimension d, Real default_value,
                    const Range& range) const;

  // A sequence of 2 or 3 numbers; a missing z is 0.
  Vec3 get_vec3(const std::string& key) const;
  Vec3 get_vec3(const std::string& key, const Vec3& default_value) const;
  // The same, each item a number (SI) or a quantity string of dimension d.
  Vec3 get_vec3_quantity(const std::string& key, Dimension d) const;

  // Sequences of numbers, quantities or strings (may be empty).
  std::vector<Real> get_reals(const std::string& key) const;
  std::vector<Real> get_quantities(const std::string& key, Dimension d) const;
  std::vector<std::string> get_strings(const std::string& key) const;
  // One quantity of dimension d, returned as a list of one, or a sequence of them; absent: the
  // default (one value).
  std::vector<Real> get_quantity_or_list(const std::string& key, Dimension d,
                                         Real default_value) const;

  // --- checks the getters cannot express (e.g. "must be less than mesh.lx") ---
  // Throws "<file>: key '<path.key>' = <value>: <what>" (without " = <value>" if absent).
  [[noreturn]] void fail(const std::string& key, const std::string& what) const;
  void require(bool condition, const std::string& key, const std::string& what) const;
  // Throws "<file>: key '<path>' = <value>: <what>" about this node itself.
  [[noreturn]] void fail(const std::string& what) const;

 private:
  friend class CaseFile;
  CaseNode(std::shared_ptr<detail::CaseState> state, YAML::Node node, std::string path);

  // Records a read for the schema check (text forms of io/case_schema.hpp).
  void note(const std::string& key, const std::string& type, const std::string& default_value,
            const std::string& allowed) const;
  // The value under key, marked as read; an undefined node if absent or null.
  YAML::Node lookup(const std::string& key) const;
  YAML::Node require_key(const std::string& key) const;  // missing → InputError
  void require_map() const;
  Real to_real(const std::string& key, const YAML::Node& value) const;
  long to_int(const std::string& key, const YAML::Node& value) const;
  bool to_bool(const std::string& key, const YAML::Node& value) const;
  std::string to_choice(const std::string& key, const YAML::Node& value,
                        const std::vector<std::string>& allowed) const;
  Real to_quantity(const std::string& key, const YAML::Node& value, Dimension d) const;
  void check_range(const std::string& key, Real x, const Range& range) const;
  std::string scalar_text(const std::string& key, const YAML::Node& value,
                          const char* expected) const;
  Vec3 to_vec3(const std::string& key, const YAML::Node& value, const Dimension* d) const;

  std::shared_ptr<detail::CaseState> state_;
  YAML::Node node_;  // map, sequence, or null/undefined for an empty node
  std::string path_;
};

class CaseFile {
 public:
  // Reads and parses the file and applies the overrides in order. Each override is
  // "dotted.key=value" with the value parsed as YAML ("mesh.nx=320", "material.E=210 GPa",
  // "probes[0].at=[1, 0.5]"). An override may add a key whose parent map exists. Unreadable
  // file, YAML syntax error, malformed override → InputError.
  static CaseFile load(const std::string& path, const std::vector<std::string>& overrides = {});
  // The same from text in memory; `name` stands for the file name in messages.
  static CaseFile parse(const std::string& text, const std::string& name,
                        const std::vector<std::string>& overrides = {});

  CaseNode root() const;

  // Throws "<file>: unknown key '<dotted.key>'" for the first key (in file order, override
  // additions last in their map) that no getter, child() or has() read. Then, with a declared
  // schema and RFMEMS_CHECK_CASE_SCHEMA set (not "0"), throws std::logic_error if a read so far
  // differs from the schema (io/case_schema.hpp): a reader and its declaration disagree.
  void check_all_used() const;

  // The keys the driver reading this case accepts, for the check above.
  void declare_schema(const CaseSchema& schema);
  // Every read so far, one per path and form.
  std::vector<CaseKeyRead> reads() const;

  const std::string& path() const;
  // The file as read, before overrides (for result metadata).
  const std::string& text() const;
  const std::vector<std::string>& overrides() const;
  // The case after overrides, as YAML.
  std::string effective_text() const;

 private:
  explicit CaseFile(std::shared_ptr<detail::CaseState> state) : state_(std::move(state)) {}
  std::shared_ptr<detail::CaseState> state_;
};

}  // namespace rfmems
