// Making and cleaning up a sweep's folders (sweep_folders.hpp).
#include "sweep/sweep_folders.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/config/config_error.hpp"

namespace corrmp {

namespace fs = std::filesystem;

void make_sweep_folder(const fs::path& folder, const std::string& option) {
  std::error_code error;
  fs::create_directories(folder, error);
  if (error || !fs::is_directory(folder, error)) {
    throw ConfigError(fmt::format("{}: cannot make the folder {}: {}", option, folder.string(),
                                  error ? error.message() : "a file is in the way"));
  }
  if (::access(folder.c_str(), W_OK | X_OK) != 0) {
    throw ConfigError(fmt::format("{}: cannot write in the folder {}: {}", option, folder.string(),
                                  std::strerror(errno)));
  }
}

NewFolderCleanup::NewFolderCleanup(const fs::path& folder) {
  std::error_code error;
  fs::path start = fs::absolute(folder, error).lexically_normal();
  if (start.filename().empty()) start = start.parent_path();  // a trailing '/'
  for (fs::path at = start; !at.empty() && !fs::exists(fs::symlink_status(at, error));
       at = at.parent_path()) {
    topmost_new_ = at;
    if (at == at.parent_path()) break;
  }
}

NewFolderCleanup::~NewFolderCleanup() {
  if (topmost_new_.empty()) return;
  std::error_code ignored;  // a folder that cannot be removed stays: nothing more to do here
  fs::remove_all(topmost_new_, ignored);
}

}  // namespace corrmp
