// Running a sweep on a Slurm cluster: one job array whose task i runs job i of the
// sweep's manifest, each writing its own shard database. docs/slurm.md.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sweep/sweep.hpp"

namespace corrmp {

// Where the array's tasks find their program and inputs and put their outputs, all on
// a filesystem every node shares. The script holds them as absolute paths (relative
// ones are taken from the current directory), since the tasks run in sbatch's working
// directory on other machines.
struct SlurmPaths {
  std::string run_experiment;  // the run_experiment binary
  std::string manifest;        // the sweep's manifest (its jobs), read by --sweep-job
  std::string shard_dir;       // task i writes <shard_dir>/job-<i>.sqlite
  std::string out_dir;         // the run directories (run_experiment --out)
  std::string log_dir;         // task i's stdout and stderr: <log_dir>/job-<i>.out, .err
};

// Which of the sweep's jobs the array runs, and how many at once.
struct SlurmArraySelection {
  std::vector<int> indices;  // job indices to run (to resume a sweep); empty: all
  int max_concurrent = 0;    // Slurm's "%" limit on running tasks; 0: no limit
};

// The bash job-array script for `sweep`: #SBATCH lines for the name, the array, the
// sweep's `slurm:` resources (--partition only when set) and the log files, then one
// line running `run_experiment --sweep-job MANIFEST $SLURM_ARRAY_TASK_ID` with the
// task's shard database. Throws std::invalid_argument for an empty sweep, an index
// outside it, or a resource or log directory an #SBATCH line cannot hold.
std::string slurm_array_script(const Sweep& sweep, const SlurmPaths& paths,
                               const SlurmArraySelection& selection = {});

// Why a resource value (time, memory, partition) cannot go on an #SBATCH line as is ("'1 hour'
// is not a Slurm value (...)"): only letters, digits and :-_.,+ may, which Slurm's syntax for
// them needs. Empty when it can.
std::string slurm_value_problem(const std::string& value);

// The array specification: sorted indices, consecutive runs as ranges ("0-3",
// "1,3-4"), then "%<max_concurrent>" when limited.
std::string slurm_array_spec(std::vector<int> indices, int max_concurrent = 0);

struct SlurmSubmission {
  std::string job_id;  // the array's job id, as sbatch --parsable prints it
  // With wait: sbatch's exit status, the highest of the array's tasks (1 for a task
  // killed by a signal); 0 when all succeeded.
  std::optional<int> exit_code;
};

// Submits the script with `sbatch --parsable [--wait] SCRIPT` (no shell). Throws
// std::runtime_error when sbatch is not installed or cannot submit (with its stderr).
SlurmSubmission submit_slurm(const std::string& script_path, bool wait);

}  // namespace corrmp
