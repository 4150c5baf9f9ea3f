// Runs left 'running' by a process that ended without finishing them (kill -9, a crash, a lost
// node): the next process to open the database marks them 'interrupted' there and in their
// run.json, so that a run's folder says what the database says (docs/usage.md, "When things go
// wrong").
#pragma once

#include <string>

#include "store/result_store.hpp"

namespace corrmp {

/// Marks such runs of this host in `store` and in their folders' run.json; returns how many.
int mark_interrupted_runs(ResultStore& store);

/// Marks the runs of a sweep's job left 'running' by earlier attempts (ResultStore::
/// mark_job_runs_interrupted) in `store` and in their folders' run.json; returns how many.
int mark_job_runs_interrupted(ResultStore& store, const std::string& sweep_id, int job_index);

/// Rewrites the run.json at `path`, as the pipeline wrote it while the run ran ("status":
/// "running", "finished_at": null), with the status 'interrupted', the end and the reason. Returns
/// false, leaving the file as it is, when it is missing or not in that form.
bool mark_run_json_interrupted(const std::string& path, const std::string& finished_at,
                               const std::string& failure);

}  // namespace corrmp
