// What a run records about where it came from: git commit and dirty flag of the
// source tree, host, and library versions (run.json).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace corrmp {

struct GitState {
  std::string commit = "unknown";
  bool dirty = false;
};

// The state of the source tree this binary was built from (CORRMP_SOURCE_DIR).
GitState source_git_state();

// Name and version of each library linked into the framework.
std::vector<std::pair<std::string, std::string>> library_versions();

}  // namespace corrmp
