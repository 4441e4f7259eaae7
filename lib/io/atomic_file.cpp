// Temporary-file-and-rename writing declared in atomic_file.hpp.
#include "io/atomic_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace rfmems {

std::string temp_path_for(const std::string& path) {
  return path + ".tmp." + std::to_string(::getpid());
}

void create_parent_directory(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (parent.empty()) return;
  std::error_code ec;
  std::filesystem::create_directories(parent, ec);
  if (ec)
    throw std::runtime_error(path + ": cannot create directory " + parent.string() + ": " +
                             ec.message());
}

void rename_file(const std::string& from, const std::string& to) {
  if (std::rename(from.c_str(), to.c_str()) != 0)
    throw std::runtime_error(to + ": cannot rename " + from + " to it: " + std::strerror(errno));
}

void write_file_atomic(const std::string& path, std::string_view content) {
  create_parent_directory(path);
  const std::string temp = temp_path_for(path);
  std::FILE* f = std::fopen(temp.c_str(), "wb");
  if (f == nullptr)
    throw std::runtime_error(path + ": cannot create " + temp + ": " + std::strerror(errno));
  const bool written = std::fwrite(content.data(), 1, content.size(), f) == content.size();
  const int saved_errno = errno;
  // fclose flushes; a full disk may only show up here.
  if (std::fclose(f) != 0 || !written) {
    const int e = written ? errno : saved_errno;
    std::remove(temp.c_str());
    throw std::runtime_error(path + ": cannot write " + temp + ": " + std::strerror(e));
  }
  try {
    rename_file(temp, path);
  } catch (...) {
    std::remove(temp.c_str());
    throw;
  }
}

}  // namespace rfmems
