// A shard the merge's checks accept but whose run the target's schema refuses: its runs table
// lacks the status constraint and holds a run whose status is none the target allows.
#pragma once

#include <string>

#include "store/result_store.hpp"
#include "support/store_sql.hpp"

namespace corrmp::testing {

inline void write_shard_the_target_refuses(const std::string& path) {
  ResultStore store(path);
  testing::execute_sql(
      store,
      "DROP TABLE trials; DROP TABLE metrics; DROP TABLE runs; "
      "CREATE TABLE runs (id INTEGER PRIMARY KEY, experiment, config, config_hash, seed, "
      "status, started_at, finished_at, git_commit, git_dirty, out_dir, host, pid, failure, "
      "uid, sweep_id, job_index, axes); "
      "CREATE TABLE trials (run_id, trial, scenario, expected_action, chosen_action, success, "
      "failure, details); CREATE TABLE metrics (run_id, name, value); "
      "INSERT INTO runs (experiment, config, config_hash, seed, status, started_at, uid) "
      "VALUES ('b', 'c', 'h', 1, 'finished somehow', 't', 'u-1')");
}

}  // namespace corrmp::testing
