// Checks on paths before they are written (path_checks.hpp).
#include "core/path_checks.hpp"

#include <filesystem>

namespace corrmp {

namespace fs = std::filesystem;

bool same_file(const std::string& a, const std::string& b) {
  std::error_code error;
  const bool same = fs::equivalent(a, b, error);
  return same && !error;
}

std::string file_in_the_way(const std::string& folder) {
  for (fs::path p = fs::path(folder); !p.empty(); p = p.parent_path()) {
    std::error_code error;
    const fs::file_status status = fs::status(p, error);
    if (fs::exists(status)) {
      return fs::is_directory(status) ? "" : "'" + p.string() + "' is a file, not a folder";
    }
    if (p == p.parent_path()) break;
  }
  return "";
}

}  // namespace corrmp
