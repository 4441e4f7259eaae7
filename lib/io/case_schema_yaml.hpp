// Case key declarations as data: the YAML files the readers' groups are written in
// (io/case_schema.hpp), compiled into the library.
//
// A declaration file is a list of groups, each a map
//   section: the dotted section the keys sit under ("" for the top level)
//   title:   one line: what the keys describe
//   keys:    a list of maps path, type, default, allowed, meaning (allowed may be left out
//            for anything of the type)
// every value a text exactly as case_schema.hpp describes it; a value YAML would read as
// something else (a number, true, a text starting with '>' or '[') is quoted.
//
// Each reader's file sits beside its source: lib/<dir>/<reader>.keys.yaml for
// lib/<dir>/<reader>.cpp. At build time cmake/embed_case_keys.cmake writes every such file into
// a generated source as a raw string literal, named by its path below lib/.
#pragma once
#include <span>
#include <string>
#include <string_view>

#include "io/case_schema.hpp"

namespace rfmems {

// One embedded declaration file: its path below lib/ and its text.
struct EmbeddedCaseKeys {
  const char* name;
  const char* text;
};

// Every embedded declaration file (defined in the generated source).
std::span<const EmbeddedCaseKeys> embedded_case_key_files();

// The groups a declaration file's text holds, in order. `name` names the file in the errors: a
// malformed text throws std::logic_error "case keys <name>, line <n>: <what is wrong>".
CaseSchema parse_case_schema(const std::string& text, const std::string& name);

// The groups of the embedded file `name` ("coupling/pull_in_study.keys.yaml"); throws
// std::logic_error if no file has that name or its text is malformed.
CaseSchema embedded_case_schema(std::string_view name);

}  // namespace rfmems
