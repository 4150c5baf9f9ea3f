// The experiment pipeline: collect -> fit contexts -> train -> evaluate ->
// report, recording the run in the result store and its run directory
// <out>/<experiment>/<run id>/ (config.resolved.yaml, run.json, log.txt).
// Stages run only when their components are configured and exist.
#pragma once

#include <string>

#include "experiment/experiment.hpp"
#include "store/run_status.hpp"

namespace corrmp {

struct RunOptions {
  std::string db_path = "results/results.sqlite";
  std::string out_dir = "results";
  // false: collect demonstrations and fit extractors afresh (the results are
  // still written to the cache for later runs).
  bool use_cache = true;
  // Set when the run is a job of a sweep: recorded with the run.
  std::string sweep_id;
  int job_index = 0;
  std::string axes_json;  // the job's axis values
};

struct RunResult {
  int64_t run_id = 0;
  RunStatus status = RunStatus::running;  // completed, failed or interrupted once it returns
  std::string run_dir;
  std::string failure;
};

// Runs the experiment. Failures inside the run are caught and recorded (status
// 'failed' with the reason); only a store that cannot be opened throws.
RunResult run_pipeline(Experiment& experiment, const RunOptions& options);

}  // namespace corrmp
