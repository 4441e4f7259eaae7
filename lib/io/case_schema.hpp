// The case keys a reader accepts, declared beside the reader that reads them.
//
// Each reader declares its keys as data, in a YAML file beside its source:
// lib/<dir>/<reader>.keys.yaml for lib/<dir>/<reader>.cpp (the format and how the files are
// compiled into the library: io/case_schema_yaml.hpp). The file holds the reader's groups
// (CaseKeyGroup): the section the keys sit under and, for each key, its type, default, allowed
// values and one line of meaning. The reader's *_case_keys() returns them, joined with the
// groups of the readers it calls. A driver's schema is the list of groups its readers use;
// `<driver> --help-case` prints it (format_case_schema) and docs/case-reference.md is generated
// from those prints.
//
// The declarations cannot drift from the readers unnoticed: CaseNode records every read a
// reader makes (the type, default and range it passes to the getter), and with the environment
// variable RFMEMS_CHECK_CASE_SCHEMA set (the tests set it), CaseFile::check_all_used() compares
// them with the driver's schema and fails on a read that is undeclared or declared otherwise.
//
// A key's path is relative to its group's section, dotted: "rtol", "law.A". A segment "<name>"
// stands for any one key (a boundary named by the mesh), and "[]" for any item of a sequence
// ("probes[].at"). The text forms, which a read must reproduce exactly:
//   type     number | integer | bool | text | choice | <dimension> (a quantity: length, time,
//            voltage, ...) | vector | vector of <dimension> | list of numbers |
//            list of <dimension> | list of texts | section (a map or a sequence)
//   default  "(required)" for a required key; the value as the reader formats it ("0.001",
//            "1e-06 s", "scalar"); any other text in parentheses is a default computed from
//            other keys ("(end_time / 500)") and is shown but not compared
//   allowed  "> 0", "in (0, 1)", "a, b, c" (a choice: a read may allow fewer), or "" for
//            anything of the type; text in parentheses is a bound computed from other keys
//            and is not compared
#pragma once
#include <string>
#include <vector>

#include "io/units.hpp"

namespace rfmems {

struct CaseKey {
  std::string path;
  std::string type;
  std::string default_value;
  std::string allowed;
  std::string meaning;
};

struct CaseKeyGroup {
  std::string section;  // dotted path the keys sit under; "" for the top level
  std::string title;    // one line: what the keys describe
  std::vector<CaseKey> keys;
};

// A driver's schema: the groups of the readers it runs, in the order its help lists them.
using CaseSchema = std::vector<CaseKeyGroup>;

// The groups of several readers in order, each group once (a reader called by two others).
CaseSchema join_schemas(const std::vector<CaseSchema>& parts);

// The default text of a required key.
inline const std::string kRequiredKey = "(required)";

// One read a reader made, in the text forms above, at its path with sequence indices as "[]".
struct CaseKeyRead {
  std::string path;
  std::string type;
  std::string default_value;
  std::string allowed;
  auto operator<=>(const CaseKeyRead&) const = default;
};

// The type text of a quantity of dimension d: "length", "pressure", ...
std::string quantity_type(Dimension d);

// The schema as Markdown: a heading per group, then a table key | type | unit | default |
// allowed | meaning (the key as its full dotted path).
std::string format_case_schema(const std::string& program, const CaseSchema& schema);

// One line per read that no key of the schema declares, or that a key declares with another
// type, default or allowed values; empty if every read agrees with its declaration.
std::vector<std::string> case_schema_mismatches(const CaseSchema& schema,
                                                const std::vector<CaseKeyRead>& reads);

}  // namespace rfmems
