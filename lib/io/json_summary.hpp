// The one-object JSON summary each driver prints with --json (and may save to a file).
// The type is nlohmann::json; this file adds only output helpers.
#pragma once
#include <nlohmann/json.hpp>
#include <string>

namespace rfmems {

using Json = nlohmann::json;

// Indented text with a final newline. Invalid UTF-8 in strings is replaced, not thrown on;
// NaN and infinities become null (JSON has no such numbers).
std::string json_text(const nlohmann::json& j);

// Writes json_text(j) to path atomically (temporary file + rename).
void write_json_atomic(const std::string& path, const nlohmann::json& j);

}  // namespace rfmems
