// What run_experiment does for a multirun: check every job's config before
// anything is written, then run the jobs here (-j N), submit them to Slurm or
// only write the Slurm files; and, inside each job's process, run that job.
// docs/sweeps.md.
#pragma once

#include <string>
#include <vector>

#include "experiment/pipeline.hpp"
#include "experiment/registries.hpp"
#include "sweep/sweep.hpp"

namespace corrmp {

struct SweepDriverOptions {
  RunOptions run;                  // database, output root, cache use
  std::string executable;          // this run_experiment binary
  int parallel_jobs = 1;           // -j
  int threads = 1;                 // the cores this machine gives the sweep
  std::string launcher = "local";  // local or slurm
  std::string emit_dir;            // --emit slurm DIR: write the files only
  bool wait = false;               // slurm: wait for the array, then merge its shards
};

// Merges the shard databases into `db_path` (store/store_merge.hpp): every shard checked
// before anything is merged, all of them in one transaction, none of them changed; then
// prints one line per shard. Throws StoreError naming the shard that cannot be merged.
void merge_shards(const std::vector<std::string>& shards, const std::string& db_path);

// Loads every job's experiment (throws ConfigError naming the job and its
// axis values for the first that does not load).
void check_sweep_jobs(const Sweep& sweep, const Registries& registries);

// Runs, submits or emits the sweep; returns the process exit code (0 all jobs
// completed or submitted, 1 a job failed, 130 interrupted).
int drive_sweep(const Sweep& sweep, const SweepDriverOptions& options);

// Inside a job's process: runs job `index` of the manifest, recording the
// sweep and the job's axes with the run; a job that already has a completed
// run in the database is not run again. Returns the exit code.
int run_sweep_job(const std::string& manifest, int index, const RunOptions& options,
                  const Registries& registries);

}  // namespace corrmp
