// Running run_experiment from the sweep tests: a small, quick config, a command's exit code
// and output, and files a run left behind.
#pragma once

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "config/test_files.hpp"

namespace corrmp::testing {

// A config that trains for a fraction of a second.
inline const std::string kTiny =
    "experiment: {name: tiny}\nseed: 3\ndemonstrations: {type: curve_family, train: 4, "
    "validation: 2, time_steps: 10}\npolicy:\n  type: segmented_cnmp\n  network: {width: 8}\n"
    "  training: {updates: 200, validate_every: 50}\n";

// kTiny training for minutes: a test stops it first.
inline std::string slow_tiny() {
  std::string slow = kTiny;
  slow.replace(slow.find("updates: 200"), 12, "updates: 10000000");
  return slow;
}

struct Outcome {
  int exit_code;
  std::string out;
};

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

inline long line_count(const std::string& text) {
  return static_cast<long>(std::count(text.begin(), text.end(), '\n'));
}

// Runs run_experiment with `args` (a bash command line's words) and the database and output
// folder in `dir` unless `db` names another database; stdout and stderr together. With
// `timeout_seconds`, a run still going then gets a Ctrl-C (SIGINT).
inline Outcome run(const TempDir& dir, const std::string& args, const std::string& db = "",
                   int timeout_seconds = 0) {
  const std::string log = dir.file("output.txt");
  const std::string command =
      (timeout_seconds > 0 ? "timeout -s INT " + std::to_string(timeout_seconds) + " "
                           : std::string()) +
      std::string(RUN_EXPERIMENT_BIN) + " " + args + " --db " +
      (db.empty() ? dir.file("r.sqlite") : db) + " --out " + dir.file("runs") + " >" + log +
      " 2>&1";
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_text(log)};
}

// The files under `folder` whose names contain `part`.
inline int files_named(const std::filesystem::path& folder, const std::string& part) {
  int count = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
    if (entry.path().filename().string().find(part) != std::string::npos) ++count;
  }
  return count;
}

}  // namespace corrmp::testing
