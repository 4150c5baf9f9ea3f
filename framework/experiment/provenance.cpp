// Provenance of runs: git state and library versions.
#include "experiment/provenance.hpp"

#include <fmt/format.h>
#include <spdlog/version.h>

#include <LinearMath/btScalar.h>
#include <Eigen/Core>
#include <opencv2/core/version.hpp>

#include <array>
#include <cstdio>
#include <memory>

#include "store/result_store.hpp"

namespace corrmp {

namespace {

// Runs a shell command; returns its standard output, or nullopt-like "" with ok=false.
bool capture(const std::string& command, std::string& output) {
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  if (!pipe) return false;
  std::array<char, 256> buffer{};
  output.clear();
  while (fgets(buffer.data(), buffer.size(), pipe.get()) != nullptr) output += buffer.data();
  return pclose(pipe.release()) == 0;
}

}  // namespace

GitState source_git_state() {
  GitState state;
  const std::string git = fmt::format("git -C '{}' ", CORRMP_SOURCE_DIR);
  std::string output;
  // The tree's own repository only (as cmake/build_info.cmake): inside another work tree, the
  // prefix printed after the commit is not empty.
  if (capture(git + "rev-parse HEAD --show-prefix 2>/dev/null", output) && !output.empty() &&
      output.find_first_not_of("\r\n", output.find_first_of("\r\n")) == std::string::npos) {
    state.commit = output.substr(0, output.find_first_of("\r\n"));
    // --no-optional-locks: a commit made meanwhile must not find the index locked.
    if (capture(git + "--no-optional-locks status --porcelain --untracked-files=no 2>/dev/null",
                output)) {
      state.dirty = !output.empty();
    }
  }
  return state;
}

std::string source_change_warning(const GitState& built, const GitState& now) {
  if (built.commit == "unknown" || now.commit == "unknown") return "";
  if (built.commit == now.commit && built.dirty == now.dirty) return "";
  const auto describe = [](const GitState& state) {
    return fmt::format("{}{}", state.commit.substr(0, 12),
                       state.dirty ? " with uncommitted changes" : "");
  };
  return fmt::format(
      "this binary was built from {}, but the source tree is now at {}; the run records the "
      "binary's state (rebuild before the next run or sweep to run the code as it is now)",
      describe(built), describe(now));
}

std::vector<std::pair<std::string, std::string>> library_versions() {
  return {
      {"eigen",
       fmt::format("{}.{}.{}", EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION)},
      {"sqlite", sqlite_library_version()},
      {"bullet", fmt::format("{}", btGetVersion())},
      {"opencv", CV_VERSION},
      {"spdlog", fmt::format("{}.{}.{}", SPDLOG_VER_MAJOR, SPDLOG_VER_MINOR, SPDLOG_VER_PATCH)},
      {"fmt", fmt::format("{}", FMT_VERSION)},
      {"compiler", __VERSION__},
  };
}

}  // namespace corrmp
