// Running a sweep on this machine: up to N jobs at once, each a separate
// run_experiment process (`--sweep-job MANIFEST INDEX`) sharing the result
// database, with one progress line for the sweep. Jobs that already have a
// completed run are skipped, so a resumed sweep only runs what is missing.
// docs/sweeps.md.
#pragma once

#include <string>

#include "sweep/sweep.hpp"

namespace corrmp {

struct LocalSweepOptions {
  std::string executable;  // run_experiment
  std::string db_path;
  std::string out_dir;
  int parallel_jobs = 1;
  int threads_per_job = 1;
  bool use_cache = true;
};

struct SweepOutcome {
  int skipped = 0;  // completed before this invocation
  int completed = 0;
  int failed = 0;
  int interrupted = 0;
  int not_started = 0;    // pending jobs a Ctrl-C stopped before they started
  std::string directory;  // <out>/sweeps/<id>: manifest, job logs
};

// Runs the sweep's pending jobs. A database that cannot be used is refused
// (StoreError) before anything is written; a second driver of the same sweep
// is refused (a lock file beside the database's real file, whatever path names it, removed
// when the driver ends). Ctrl-C stops the
// running jobs (they mark their runs interrupted); a driver killed outright takes its jobs with it
// (they are killed when their parent dies), and --resume reruns them.
SweepOutcome run_sweep_locally(const Sweep& sweep, const LocalSweepOptions& options);

}  // namespace corrmp
