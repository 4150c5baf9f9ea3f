// A single-node Slurm for one test: tests/support/local_slurm.sh started in a
// directory, stopped at destruction (also when the test fails). docs/slurm.md,
// "Testing against a local Slurm".
#pragma once

#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "sweep/run_command.hpp"

extern char** environ;

namespace corrmp::testing {

class LocalSlurm {
 public:
  // Starts Slurm with all its files in `dir`; running() tells whether it did,
  // unavailable() whether the harness found Slurm cannot run here (exit 77: skip the
  // test), and reason() why not (the harness's one line). Points this process's Slurm
  // commands at it (SLURM_CONF) and clears inherited SLURM_* and SBATCH_* variables,
  // which would otherwise change what sbatch asks for.
  explicit LocalSlurm(const std::string& dir) : dir_(dir) {
    clear_slurm_environment();
    const CommandResult started = run_command({"bash", script(), "start", dir_});
    if (started.exit_code == 0) {
      running_ = true;
      ::setenv("SLURM_CONF", (dir_ + "/slurm.conf").c_str(), 1);
    } else {
      unavailable_ = started.exit_code == 77;
      reason_ = started.out.empty() ? started.err : started.out;
      while (!reason_.empty() && reason_.back() == '\n') reason_.pop_back();
      if (!unavailable_) {
        reason_ = "local_slurm.sh start failed with exit " + std::to_string(started.exit_code) +
                  ": " + reason_;
      }
    }
  }
  ~LocalSlurm() {
    try {
      run_command({"bash", script(), "stop", dir_});
    } catch (const std::exception&) {
      // Nothing more to stop with: the daemons' pids are in dir/pids.
    }
    ::unsetenv("SLURM_CONF");
  }
  LocalSlurm(const LocalSlurm&) = delete;
  LocalSlurm& operator=(const LocalSlurm&) = delete;

  bool running() const { return running_; }
  bool unavailable() const { return unavailable_; }
  const std::string& reason() const { return reason_; }
  const std::string& dir() const { return dir_; }

 private:
  static std::string script() { return std::string(PROJECT_DIR) + "/tests/support/local_slurm.sh"; }

  static void clear_slurm_environment() {
    std::vector<std::string> names;
    for (char** entry = environ; *entry != nullptr; ++entry) {
      const std::string variable = *entry;
      const std::string name = variable.substr(0, variable.find('='));
      if (name.rfind("SLURM_", 0) == 0 || name.rfind("SBATCH_", 0) == 0) names.push_back(name);
    }
    for (const std::string& name : names) ::unsetenv(name.c_str());
  }

  std::string dir_;
  bool running_ = false;
  bool unavailable_ = false;
  std::string reason_;
};

}  // namespace corrmp::testing
