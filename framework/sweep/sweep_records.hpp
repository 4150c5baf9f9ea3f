// A sweep in the result database: the `sweeps` row (with the manifest, from
// which --resume restarts it) and which of its jobs have a completed run.
// docs/sweeps.md.
#pragma once

#include <optional>
#include <set>
#include <string>

#include "store/result_store.hpp"
#include "sweep/sweep.hpp"

namespace corrmp {

// Inserts the sweep's row unless it is there already.
void record_sweep(ResultStore& store, const Sweep& sweep);

// The sweep recorded under `id`, or nothing. Throws ConfigError when its manifest names
// another sweep or an unsafe id.
std::optional<Sweep> stored_sweep(ResultStore& store, const std::string& id);

// The indices of the jobs that have a completed run.
std::set<int> completed_jobs(ResultStore& store, const std::string& sweep_id);

}  // namespace corrmp
