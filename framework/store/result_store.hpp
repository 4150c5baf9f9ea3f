// The SQLite result store: runs, trials and metrics. WAL mode; every write in a
// BEGIN IMMEDIATE transaction with a busy timeout, so several processes can share
// one file; schema version in PRAGMA user_version (a newer one is refused).
// docs/architecture.md, "Database".
#pragma once

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "store/records.hpp"
#include "store/run_status.hpp"

struct sqlite3;  // the connection, opaque outside the store (store_access.hpp)

namespace corrmp {

// Every StoreError's message starts with the database file's path.
class StoreError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class ResultStore {
 public:
  // 2: trials.details; 3: runs' uid and sweep; 4: metric declarations and run_tasks
  static constexpr int kSchemaVersion = 4;

  // Opens (creating the file and its folder if needed) and migrates the schema.
  // An existing 0-byte file becomes a new database with a one-line warning.
  // Throws StoreError naming the path for a directory, garbage bytes or a
  // damaged or truncated database ("not a usable result database"), or a
  // folder that cannot be made (a file in the way), before anything is written.
  explicit ResultStore(const std::string& path, int busy_timeout_ms = 60000);
  ~ResultStore();
  ResultStore(const ResultStore&) = delete;
  ResultStore& operator=(const ResultStore&) = delete;

  // A run marked interrupted by mark_interrupted_runs.
  struct InterruptedRun {
    int64_t id = 0;
    std::string out_dir;  // its run folder ("" if it had none yet)
    std::string finished_at, failure;
  };
  // Marks runs left 'running' by processes of this host that no longer exist as
  // 'interrupted'; returns them.
  std::vector<InterruptedRun> mark_interrupted_runs();
  // Marks the runs of a sweep's job still 'running' as interrupted: earlier attempts that ended
  // or are ending (a driver killed, a Slurm time limit, a lost node), on any host, but for one
  // whose process is alive on this host (the job started twice at once); returns them.
  std::vector<InterruptedRun> mark_job_runs_interrupted(const std::string& sweep_id, int job_index);

  // Inserts a run with status 'running' (and its task declaration, if any) and returns its id.
  int64_t begin_run(const RunRecord& run);
  void set_out_dir(int64_t run_id, const std::string& out_dir);
  // Writes the run's trials and metrics and marks it completed, in one transaction.
  void complete_run(int64_t run_id, const std::vector<TrialRecord>& trials,
                    const std::vector<MetricRecord>& metrics);
  // Marks the run failed or interrupted with a reason; throws std::invalid_argument for another
  // status.
  void end_run(int64_t run_id, RunStatus status, const std::string& reason);

  void add_trials(int64_t run_id, const std::vector<TrialRecord>& trials);
  void add_metrics(int64_t run_id, const std::vector<MetricRecord>& metrics);

  // Runs `body` inside BEGIN IMMEDIATE ... COMMIT; rolls back if it throws.
  void transaction(const std::function<void()>& body);

  const std::string& path() const { return path_; }

 private:
  friend class StoreAccess;  // the store's own query files
  // Executes SQL without results (outside or inside a transaction).
  void execute(const std::string& sql);
  int64_t query_int(const std::string& sql);
  void migrate(bool existed_empty);
  void insert_trials(int64_t run_id, const std::vector<TrialRecord>& trials);
  void insert_metrics(int64_t run_id, const std::vector<MetricRecord>& metrics);
  void set_interrupted(const std::vector<InterruptedRun>& runs);  // inside a transaction

  std::string path_;
  sqlite3* db_ = nullptr;
};

std::string utc_timestamp();  // ISO 8601, e.g. 2026-11-22T02:24:37Z
std::string host_name();
std::string sqlite_library_version();  // of the SQLite the store runs on, e.g. "3.40.1"

}  // namespace corrmp
