// The plain records a run writes to the result store and reads back: no database in sight, so
// that the code producing them (evaluation, pipeline) needs only this header.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/metric.hpp"
#include "core/task_declaration.hpp"

namespace corrmp {

struct RunRecord {
  std::string experiment;
  std::string config;  // resolved YAML
  std::string config_hash;
  uint64_t seed = 0;
  std::string git_commit;
  bool git_dirty = false;
  std::string out_dir;
  // Set for a run of a sweep: the sweep, the job's index and its axis values
  // (a JSON object, key -> value as written).
  std::string sweep_id;
  int job_index = 0;
  std::string axes;
  // What the run's task declares; none for a run without an environment.
  std::optional<TaskDeclaration> task{};
};

struct TrialRecord {
  int trial = 0;
  std::string scenario;  // JSON
  std::string expected_action;
  std::string chosen_action;
  bool success = false;
  std::string failure;  // empty on success
  std::string details;  // JSON: the trial's contexts and the task's outcome values
};

// A metric with its declaration (core/metric.hpp), as a run records it.
using MetricRecord = Metric;

}  // namespace corrmp
