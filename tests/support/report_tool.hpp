// Test helpers: run the report tool or run_experiment on a test's database
// (<dir>/r.sqlite, runs under <dir>/runs) and return the exit code, stdout and stderr.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "config/test_files.hpp"

namespace corrmp::testing {

struct ToolOutcome {
  int exit_code = -1;
  std::string out, err;
};

inline std::string read(const std::string& path) {
  std::stringstream text;
  text << std::ifstream(path).rdbuf();
  return text.str();
}

inline ToolOutcome run_tool(const TempDir& dir, const std::string& command_line) {
  const std::string out = dir.file("out.txt"), err = dir.file("err.txt");
  const std::string command = command_line + " >" + out + " 2>" + err;
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read(out), read(err)};
}

inline ToolOutcome report_tool(const TempDir& dir, const std::string& args) {
  return run_tool(dir, std::string(REPORT_BIN) + " --db " + dir.file("r.sqlite") + " " + args);
}

inline ToolOutcome run_experiment_tool(const TempDir& dir, const std::string& args) {
  return run_tool(dir, std::string(RUN_EXPERIMENT_BIN) + " " + args + " --db " +
                           dir.file("r.sqlite") + " --out " + dir.file("runs"));
}

}  // namespace corrmp::testing
