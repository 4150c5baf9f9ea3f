// Sweeps in the result database: the sweeps table's rows (each with the manifest --resume
// restarts it from) and which jobs of a sweep have a completed run. docs/sweeps.md.
#pragma once

#include <optional>
#include <set>
#include <string>

#include "store/result_store.hpp"

namespace corrmp {

struct SweepRecord {
  std::string id, name;
  std::string created_at;  // set by insert_sweep_record
  int jobs = 0;
  std::string manifest;  // YAML, every job
};

// Inserts the sweep's row, created now, unless the database holds one with its id already.
void insert_sweep_record(ResultStore& store, const SweepRecord& sweep);

// The sweeps table's row of `id`, or nothing.
std::optional<SweepRecord> find_sweep_record(ResultStore& store, const std::string& id);

// Whether some run names the sweep `id`.
bool sweep_has_runs(ResultStore& store, const std::string& id);

// The indices of the sweep's jobs that have a completed run.
std::set<int> completed_sweep_jobs(ResultStore& store, const std::string& sweep_id);

}  // namespace corrmp
