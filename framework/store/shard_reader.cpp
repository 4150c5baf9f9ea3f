// Reading a merge's input database without changing it (shard_reader.hpp).
#include "store/shard_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <vector>

#include "store/result_store.hpp"
#include "store/statement.hpp"

namespace corrmp {

namespace {

namespace fs = std::filesystem;

// The columns of the first schema, which every version since has; later versions added
// trials.details (2), the runs' uid, sweep_id, job_index and axes (3), and the metrics'
// declarations and the run_tasks table (4).
const std::vector<std::pair<std::string, std::vector<std::string>>> kFirstColumns = {
    {"runs",
     {"id", "experiment", "config", "config_hash", "seed", "status", "started_at", "finished_at",
      "git_commit", "git_dirty", "out_dir", "host", "pid", "failure"}},
    {"trials",
     {"run_id", "trial", "scenario", "expected_action", "chosen_action", "success", "failure"}},
    {"metrics", {"run_id", "name", "value"}},
};
const std::vector<std::string> kSweepColumns = {"id", "name", "created_at", "jobs", "manifest"};

// An SQLite URI naming `path` (absolute), every byte but unreserved ones and '/' percent-encoded.
std::string file_uri(const std::string& path, const char* parameters) {
  std::string uri = "file://";
  for (const unsigned char c : path) {
    if (std::isalnum(c) || c == '/' || c == '-' || c == '.' || c == '_' || c == '~') {
      uri += static_cast<char>(c);
    } else {
      uri += fmt::format("%{:02X}", c);
    }
  }
  return uri + "?" + parameters;
}

// A database with its write-ahead log beside it has committed rows in that log, which only a
// reader that uses the log sees; that log and its index already exist, so reading makes no new
// file (but for an index that is missing: SQLite cannot read the log without one, and makes it).
// Any other is read as immutable: no lock, no log, nothing made beside it. `path` is the real
// file, links followed, as SQLite keeps the log beside that.
const char* read_only_parameters(const std::string& path) {
  std::error_code error;
  const auto log_size = fs::file_size(path + "-wal", error);
  return !error && log_size > 0 ? "mode=ro" : "immutable=1";
}

}  // namespace

ShardReader::ShardReader(const std::string& path) : path_(path) {
  std::error_code error;
  if (!fs::is_regular_file(path, error)) {
    throw ShardError(fmt::format("{}: no such database file", path));
  }
  const std::string real_path = fs::canonical(path, error).string();
  if (error) throw ShardError(fmt::format("{}: cannot open it: {}", path, error.message()));
  const std::string uri = file_uri(real_path, read_only_parameters(real_path));
  try {
    const int code =
        sqlite3_open_v2(uri.c_str(), &db_, SQLITE_OPEN_READONLY | SQLITE_OPEN_URI, nullptr);
    if (code != SQLITE_OK) fail(code, "open");
    read_schema();
  } catch (...) {
    sqlite3_close(db_);
    db_ = nullptr;
    throw;
  }
}

ShardReader::~ShardReader() { sqlite3_close(db_); }

void ShardReader::fail(int code, const std::string& during) const {
  const std::string message = db_ ? sqlite3_errmsg(db_) : sqlite3_errstr(code);
  if (code == SQLITE_NOTADB) {
    throw ShardError(
        fmt::format("{}: not a result database to merge ({})", path_, sqlite3_errstr(code)));
  }
  if (code == SQLITE_CORRUPT) {
    throw ShardError(fmt::format("{}: the database is damaged or truncated ({})", path_, message));
  }
  throw ShardError(fmt::format("{}: cannot {} it: {}", path_, during, message));
}

void ShardReader::read_failed() const { fail(sqlite3_errcode(db_), "read"); }

void ShardReader::read_schema() {
  int64_t version = 0;
  try {
    Statement pragma(db_, "PRAGMA user_version");
    if (pragma.step()) version = pragma.column_int(0);
    Statement columns(db_,
                      "SELECT m.name, p.name FROM sqlite_master m, pragma_table_info(m.name) p "
                      "WHERE m.type = 'table' AND m.name IN ('runs', 'trials', 'metrics', "
                      "'sweeps', 'run_tasks')");
    while (columns.step()) columns_[columns.column_text(0)].insert(columns.column_text(1));
  } catch (const StoreError&) {
    read_failed();
  }
  for (const auto& entry : kFirstColumns) {
    if (!has_table(entry.first)) {
      throw ShardError(fmt::format(
          "{}: not a result database to merge (it lacks the runs, trials or metrics table)",
          path_));
    }
  }
  if (version > ResultStore::kSchemaVersion) {
    throw ShardError(fmt::format(
        "{}: written by a newer version of this program (schema {}, this one reads up to {})",
        path_, version, ResultStore::kSchemaVersion));
  }
  auto check = [&](const std::string& table, const std::vector<std::string>& wanted) {
    for (const auto& column : wanted) {
      if (columns_[table].count(column) == 0) {
        throw ShardError(
            fmt::format("{}: not a result database to merge (its {} table has no column '{}')",
                        path_, table, column));
      }
    }
  };
  for (const auto& [table, wanted] : kFirstColumns) check(table, wanted);
  if (has_table("sweeps")) check("sweeps", kSweepColumns);
}

void ShardReader::check_integrity() {
  std::string verdict;
  try {
    Statement check(db_, "PRAGMA quick_check(1)");
    if (check.step()) verdict = check.column_text(0);
  } catch (const StoreError&) {
    read_failed();
  }
  if (verdict != "ok") {
    std::replace(verdict.begin(), verdict.end(), '\n', ' ');  // the error is one line
    throw ShardError(fmt::format("{}: the database is damaged or truncated ({})", path_, verdict));
  }
}

ShardQuery::ShardQuery(ShardReader& shard, const std::string& sql) : shard_(shard) {
  try {
    rows_ = std::make_unique<Statement>(shard.handle(), sql);
  } catch (const StoreError&) {
    shard_.read_failed();
  }
}

ShardQuery::~ShardQuery() = default;

ShardQuery& ShardQuery::bind(int index, int64_t value) {
  try {
    rows_->bind(index, value);
  } catch (const StoreError&) {
    shard_.read_failed();
  }
  return *this;
}

bool ShardQuery::step() {
  try {
    return rows_->step();
  } catch (const StoreError&) {
    shard_.read_failed();
  }
}

void ShardQuery::reset() { rows_->reset(); }

std::string ShardReader::column_or_null(const std::string& table, const std::string& column) const {
  const auto it = columns_.find(table);
  return it != columns_.end() && it->second.count(column) > 0 ? column : "NULL";
}

}  // namespace corrmp
