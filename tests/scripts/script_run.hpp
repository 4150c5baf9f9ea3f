// Runs one of the project's scripts/ with bash and captures its exit code and output.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace corrmp::testing {

struct ScriptResult {
  int exit_code = -1;
  std::string out, err;
};

inline std::string read_whole_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Runs scripts/<script> with `arguments` (already shell-quoted); -1 for a signal.
inline ScriptResult run_script(const std::string& script, const std::string& arguments) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / (script + "_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string command = std::string("bash ") + PROJECT_DIR + "/scripts/" + script + " " +
                              arguments + " >" + (dir / "out").string() + " 2>" +
                              (dir / "err").string();
  const int status = std::system(command.c_str());
  ScriptResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = read_whole_file(dir / "out");
  result.err = read_whole_file(dir / "err");
  fs::remove_all(dir);
  return result;
}

}  // namespace corrmp::testing
