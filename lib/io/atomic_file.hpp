// Writing output files atomically: write "<path>.tmp.<pid>", then rename() it over <path>,
// so a reader (or a crashed run) never sees a half-written file.
#pragma once
#include <string>
#include <string_view>

namespace rfmems {

// "<path>.tmp.<pid>": the temporary name used while <path> is being written.
std::string temp_path_for(const std::string& path);

// Creates the parent directory of path if it is missing.
void create_parent_directory(const std::string& path);

// Renames from → to (same directory, so atomic); throws std::runtime_error naming both.
void rename_file(const std::string& from, const std::string& to);

// Writes content to a temporary file and renames it to path. Throws std::runtime_error
// naming the file on failure, leaving neither path nor the temporary behind.
void write_file_atomic(const std::string& path, std::string_view content);

}  // namespace rfmems
