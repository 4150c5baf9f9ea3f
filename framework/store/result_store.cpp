// The SQLite result store. docs/architecture.md, "Database".
#include "store/result_store.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <signal.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <cerrno>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "core/path_checks.hpp"
#include "store/legacy_metrics.hpp"
#include "store/metric_rows.hpp"
#include "store/run_uid.hpp"
#include "store/statement.hpp"
#include "store/task_rows.hpp"

namespace corrmp {

namespace {

constexpr const char* kSchema = R"sql(
CREATE TABLE IF NOT EXISTS runs (
  id INTEGER PRIMARY KEY,
  experiment TEXT NOT NULL,
  config TEXT NOT NULL,
  config_hash TEXT NOT NULL,
  seed INTEGER NOT NULL,
  status TEXT NOT NULL CHECK (status IN ('running', 'completed', 'failed', 'interrupted')),
  started_at TEXT NOT NULL,
  finished_at TEXT,
  git_commit TEXT,
  git_dirty INTEGER,
  out_dir TEXT,
  host TEXT,
  pid INTEGER,
  failure TEXT,
  uid TEXT,
  sweep_id TEXT,
  job_index INTEGER,
  axes TEXT
);
CREATE TABLE IF NOT EXISTS sweeps (
  id TEXT PRIMARY KEY,
  name TEXT NOT NULL,
  created_at TEXT NOT NULL,
  jobs INTEGER NOT NULL,
  manifest TEXT NOT NULL
);
CREATE TABLE IF NOT EXISTS trials (
  run_id INTEGER NOT NULL REFERENCES runs(id),
  trial INTEGER NOT NULL,
  scenario TEXT NOT NULL,
  expected_action TEXT,
  chosen_action TEXT,
  success INTEGER NOT NULL,
  failure TEXT,
  details TEXT
);
CREATE TABLE IF NOT EXISTS metrics (
  run_id INTEGER NOT NULL REFERENCES runs(id),
  name TEXT NOT NULL,
  value REAL,
  unit TEXT,
  range_min REAL,
  range_max REAL,
  better TEXT CHECK (better IN ('higher', 'lower', 'neither')),
  heading TEXT,
  statistic TEXT
);
CREATE TABLE IF NOT EXISTS run_tasks (
  run_id INTEGER PRIMARY KEY REFERENCES runs(id),
  trajectory_columns TEXT NOT NULL,
  error_unit TEXT NOT NULL,
  error_scale REAL NOT NULL,
  error_segments TEXT NOT NULL,
  error_columns TEXT NOT NULL,
  decision_segment TEXT NOT NULL,
  decision_labels TEXT NOT NULL,
  relative_columns TEXT NOT NULL,
  plot_horizontal INTEGER NOT NULL,
  plot_vertical INTEGER NOT NULL,
  outcome_metrics TEXT NOT NULL,
  failure_categories TEXT NOT NULL
);
CREATE INDEX IF NOT EXISTS trials_run ON trials(run_id);
CREATE INDEX IF NOT EXISTS metrics_run ON metrics(run_id);
CREATE UNIQUE INDEX IF NOT EXISTS runs_uid ON runs(uid);
CREATE INDEX IF NOT EXISTS runs_sweep ON runs(sweep_id, job_index);
)sql";

// Version 3: a run's unique id (for merging databases) and its sweep. The runs recorded before
// get the uid a merge of this database gives them (give_runs_derived_uids).
constexpr const char* kMigrateToV3 = R"sql(
ALTER TABLE runs ADD COLUMN uid TEXT;
ALTER TABLE runs ADD COLUMN sweep_id TEXT;
ALTER TABLE runs ADD COLUMN job_index INTEGER;
ALTER TABLE runs ADD COLUMN axes TEXT;
)sql";

void give_runs_derived_uids(sqlite3* db) {
  std::vector<std::pair<int64_t, std::string>> uids;  // run id -> uid
  Statement runs(db, fmt::format("SELECT {} FROM runs WHERE uid IS NULL",
                                 fmt::join(kRunIdentityColumns, ", ")));
  while (runs.step()) {
    std::vector<std::string> identity;
    for (size_t i = 0; i < kRunIdentityColumns.size(); ++i) {
      identity.push_back(runs.column_text(static_cast<int>(i)));
    }
    uids.emplace_back(runs.column_int(0), derived_run_uid(identity));  // column 0 is the id
  }
  Statement set_uid(db, "UPDATE runs SET uid = ? WHERE id = ?");
  for (const auto& [id, uid] : uids) set_uid.bind(1, uid).bind(2, id).run();
}

// Version 4: each metric's declaration (its unit, range, direction and report column) and each
// run's task declaration (the run_tasks table, made by kSchema). The metrics recorded before get
// the declaration their names imply (declare_legacy_metrics); their runs have no task declaration.
constexpr const char* kMigrateToV4 = R"sql(
ALTER TABLE metrics ADD COLUMN unit TEXT;
ALTER TABLE metrics ADD COLUMN range_min REAL;
ALTER TABLE metrics ADD COLUMN range_max REAL;
ALTER TABLE metrics ADD COLUMN better TEXT CHECK (better IN ('higher', 'lower', 'neither'));
ALTER TABLE metrics ADD COLUMN heading TEXT;
ALTER TABLE metrics ADD COLUMN statistic TEXT;
)sql";

void declare_legacy_metrics(sqlite3* db) {
  std::vector<std::string> names;
  Statement distinct(db, "SELECT DISTINCT name FROM metrics");
  while (distinct.step()) names.push_back(distinct.column_text(0));
  Statement declare(db, fmt::format("UPDATE metrics SET ({}) = (?, ?, ?, ?, ?, ?) WHERE name = ?",
                                    kDeclarationColumns));
  for (const auto& name : names) {
    bind_declaration(declare, 1, inferred_declaration(name));
    declare.bind(kDeclarationColumnCount + 1, name).run();
  }
}

// Whether process `pid` of this host exists and has not ended. One that ended but that its parent
// has not reaped yet (a zombie: a job killed with its driver, for a moment) has ended.
bool process_alive(int64_t pid) {
  if (pid <= 0) return false;
  if (kill(static_cast<pid_t>(pid), 0) != 0 && errno != EPERM) return false;
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  const std::string text{std::istreambuf_iterator<char>(stat), std::istreambuf_iterator<char>()};
  const auto name_end = text.rfind(')');  // "pid (name) state ..."; the name may hold ')'
  return name_end == std::string::npos || name_end + 2 >= text.size() || text[name_end + 2] != 'Z';
}

}  // namespace

std::string utc_timestamp() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return buffer;
}

std::string sqlite_library_version() { return sqlite3_libversion(); }

std::string host_name() {
  char buffer[256] = {};
  if (gethostname(buffer, sizeof buffer - 1) != 0) return "unknown";
  return buffer;
}

ResultStore::ResultStore(const std::string& path, int busy_timeout_ms) : path_(path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (fs::is_directory(status))
    throw StoreError(fmt::format("{}: is a directory, not a database", path));
  if (fs::exists(status) && !fs::is_regular_file(status)) {
    throw StoreError(fmt::format("{}: is not a regular file, not a database", path));
  }
  const bool existed_empty = fs::is_regular_file(status) && fs::file_size(path, ec) == 0 && !ec;
  const auto parent = fs::path(path).parent_path();
  if (!parent.empty()) {
    std::error_code made;
    fs::create_directories(parent, made);
    if (made) {
      const std::string in_the_way = file_in_the_way(parent.string());
      throw StoreError(fmt::format("{}: cannot make its folder: {}", path,
                                   in_the_way.empty() ? made.message() : in_the_way));
    }
  }
  if (sqlite3_open_v2(path.c_str(), &db_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr) !=
      SQLITE_OK) {
    const std::string message = db_ ? sqlite3_errmsg(db_) : "out of memory";
    sqlite3_close(db_);
    db_ = nullptr;
    throw StoreError(fmt::format("{}: cannot open database: {}", path, message));
  }
  sqlite3_busy_timeout(db_, busy_timeout_ms);
  try {
    execute("PRAGMA journal_mode=WAL");
    execute("PRAGMA foreign_keys=ON");
    migrate(existed_empty);
  } catch (const StoreError&) {
    const int code = sqlite3_errcode(db_);
    sqlite3_close(db_);
    db_ = nullptr;
    // Garbage bytes or a truncated database: say so, with what to do.
    if (code == SQLITE_NOTADB || code == SQLITE_CORRUPT) {
      throw StoreError(fmt::format(
          "{}: not a usable result database ({}); move it aside or choose another database file",
          path,
          code == SQLITE_NOTADB ? "not an SQLite database" : "the file is damaged or truncated"));
    }
    throw;
  } catch (...) {
    sqlite3_close(db_);
    db_ = nullptr;
    throw;
  }
}

ResultStore::~ResultStore() { sqlite3_close(db_); }

void ResultStore::execute(const std::string& sql) {
  char* error = nullptr;
  if (sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &error) != SQLITE_OK) {
    const std::string message = error ? error : sqlite3_errmsg(db_);
    sqlite3_free(error);
    throw StoreError(fmt::format("{}: {}", path_, message));
  }
}

int64_t ResultStore::query_int(const std::string& sql) {
  Statement statement(db_, sql);
  return statement.step() ? statement.column_int(0) : 0;
}

void ResultStore::transaction(const std::function<void()>& body) {
  execute("BEGIN IMMEDIATE");
  try {
    body();
    execute("COMMIT");
  } catch (...) {
    sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
    throw;
  }
}

void ResultStore::migrate(bool existed_empty) {
  transaction([&] {
    const int64_t version = query_int("PRAGMA user_version");
    // A 0-byte file is what `touch` or a creator killed before its first
    // commit leaves: SQLite takes it for a new database, and so do we, aloud.
    // (A WAL database whose schema is not yet checkpointed also has a 0-byte
    // main file; it has tables, and no notice.)
    if (existed_empty && version == 0 && query_int("SELECT count(*) FROM sqlite_master") == 0) {
      spdlog::warn("{}: empty file (0 bytes); using it as a new result database", path_);
    }
    if (version > kSchemaVersion) {
      throw StoreError(fmt::format(
          "{}: database schema version {} is newer than this build's {}; use a newer build or "
          "another --db",
          path_, version, kSchemaVersion));
    }
    if (version >= 1 && version < 2) execute("ALTER TABLE trials ADD COLUMN details TEXT");
    if (version >= 1 && version < 3) {
      execute(kMigrateToV3);
      give_runs_derived_uids(db_);
    }
    if (version >= 1 && version < 4) {
      execute(kMigrateToV4);
      declare_legacy_metrics(db_);
    }
    if (version < kSchemaVersion) {
      execute(kSchema);
      execute(fmt::format("PRAGMA user_version = {}", kSchemaVersion));
    }
  });
}

void ResultStore::set_interrupted(const std::vector<InterruptedRun>& runs) {
  Statement mark(db_,
                 "UPDATE runs SET status = 'interrupted', finished_at = ?, failure = ? "
                 "WHERE id = ?");
  for (const InterruptedRun& run : runs) {
    mark.bind(1, run.finished_at).bind(2, run.failure).bind(3, run.id).run();
  }
}

std::vector<ResultStore::InterruptedRun> ResultStore::mark_interrupted_runs() {
  std::vector<InterruptedRun> marked;
  transaction([&] {
    marked.clear();  // a retried transaction starts again
    Statement running(
        db_,
        "SELECT id, pid, coalesce(out_dir, '') FROM runs WHERE status = 'running' AND host = ?");
    running.bind(1, host_name());
    while (running.step()) {
      if (!process_alive(running.column_int(1)))
        marked.push_back({running.column_int(0), running.column_text(2), utc_timestamp(),
                          "the process running it ended without finishing"});
    }
    set_interrupted(marked);
  });
  return marked;
}

std::vector<ResultStore::InterruptedRun> ResultStore::mark_job_runs_interrupted(
    const std::string& sweep_id, int job_index) {
  std::vector<InterruptedRun> marked;
  transaction([&] {
    marked.clear();  // a retried transaction starts again
    Statement running(db_,
                      "SELECT id, coalesce(out_dir, ''), coalesce(host, ''), pid FROM runs "
                      "WHERE sweep_id = ? AND job_index = ? AND status = 'running'");
    running.bind(1, sweep_id).bind(2, int64_t{job_index});
    const std::string this_host = host_name();
    while (running.step()) {
      if (running.column_text(2) == this_host && process_alive(running.column_int(3))) continue;
      marked.push_back({running.column_int(0), running.column_text(1), utc_timestamp(),
                        "an earlier attempt at this sweep job ended without finishing"});
    }
    set_interrupted(marked);
  });
  return marked;
}

int64_t ResultStore::begin_run(const RunRecord& run) {
  int64_t id = 0;
  transaction([&] {
    Statement insert(db_,
                     "INSERT INTO runs (experiment, config, config_hash, seed, status, "
                     "started_at, git_commit, git_dirty, out_dir, host, pid, uid, sweep_id, "
                     "job_index, axes) VALUES "
                     "(?, ?, ?, ?, 'running', ?, ?, ?, ?, ?, ?, lower(hex(randomblob(16))), ?, ?, "
                     "?)");
    insert.bind(1, run.experiment)
        .bind(2, run.config)
        .bind(3, run.config_hash)
        .bind(4, static_cast<int64_t>(run.seed))
        .bind(5, utc_timestamp())
        .bind(6, run.git_commit)
        .bind(7, int64_t{run.git_dirty})
        .bind(8, run.out_dir)
        .bind(9, host_name())
        .bind(10, static_cast<int64_t>(getpid()));
    if (run.sweep_id.empty()) {
      insert.bind_null(11).bind_null(12).bind_null(13);
    } else {
      insert.bind(11, run.sweep_id).bind(12, int64_t{run.job_index}).bind(13, run.axes);
    }
    insert.run();
    id = sqlite3_last_insert_rowid(db_);
    if (run.task) insert_task(db_, id, *run.task);
  });
  return id;
}

void ResultStore::set_out_dir(int64_t run_id, const std::string& out_dir) {
  transaction([&] {
    Statement update(db_, "UPDATE runs SET out_dir = ? WHERE id = ?");
    update.bind(1, out_dir).bind(2, run_id).run();
  });
}

void ResultStore::insert_trials(int64_t run_id, const std::vector<TrialRecord>& trials) {
  Statement insert(db_,
                   "INSERT INTO trials (run_id, trial, scenario, expected_action, chosen_action, "
                   "success, failure, details) VALUES (?, ?, ?, ?, ?, ?, ?, ?)");
  for (const auto& trial : trials) {
    insert.bind(1, run_id)
        .bind(2, int64_t{trial.trial})
        .bind(3, trial.scenario)
        .bind(4, trial.expected_action)
        .bind(5, trial.chosen_action)
        .bind(6, int64_t{trial.success});
    if (trial.failure.empty()) {
      insert.bind_null(7);
    } else {
      insert.bind(7, trial.failure);
    }
    if (trial.details.empty()) {
      insert.bind_null(8);
    } else {
      insert.bind(8, trial.details);
    }
    insert.run();
  }
}

void ResultStore::insert_metrics(int64_t run_id, const std::vector<MetricRecord>& metrics) {
  Statement insert(db_, fmt::format("INSERT INTO metrics (run_id, name, value, {}) VALUES "
                                    "(?, ?, ?, ?, ?, ?, ?, ?, ?)",
                                    kDeclarationColumns));
  for (const auto& metric : metrics) {
    insert.bind(1, run_id).bind(2, metric.name).bind(3, metric.value);
    bind_declaration(insert, 4, metric.declaration);
    insert.run();
  }
}

void ResultStore::add_trials(int64_t run_id, const std::vector<TrialRecord>& trials) {
  transaction([&] { insert_trials(run_id, trials); });
}

void ResultStore::add_metrics(int64_t run_id, const std::vector<MetricRecord>& metrics) {
  transaction([&] { insert_metrics(run_id, metrics); });
}

void ResultStore::complete_run(int64_t run_id, const std::vector<TrialRecord>& trials,
                               const std::vector<MetricRecord>& metrics) {
  transaction([&] {
    insert_trials(run_id, trials);
    insert_metrics(run_id, metrics);
    Statement update(db_, "UPDATE runs SET status = 'completed', finished_at = ? WHERE id = ?");
    update.bind(1, utc_timestamp()).bind(2, run_id).run();
  });
}

void ResultStore::end_run(int64_t run_id, RunStatus status, const std::string& reason) {
  if (status != RunStatus::failed && status != RunStatus::interrupted) {
    throw std::invalid_argument("a run ends failed or interrupted, not " + to_string(status));
  }
  transaction([&] {
    Statement update(db_, "UPDATE runs SET status = ?, finished_at = ?, failure = ? WHERE id = ?");
    update.bind(1, to_string(status))
        .bind(2, utc_timestamp())
        .bind(3, reason)
        .bind(4, run_id)
        .run();
  });
}

}  // namespace corrmp
