// A result database read as the input of a merge (store_merge.hpp). It is opened read-only and
// never changed: no schema upgrade, no journal-mode change, and no -wal or -shm file made beside
// it (a database whose write-ahead log is beside it, one a task may still be writing, is read
// through that log; if the log's -shm index is missing, SQLite makes it, as it cannot read the
// log without one). docs/slurm.md, "Merging the shards".
#pragma once

#include <sqlite3.h>

#include <map>
#include <memory>
#include <set>
#include <string>

#include "store/result_store.hpp"
#include "store/statement.hpp"

namespace corrmp {

// A failure reading a shard (not writing the database it is merged into); the message starts
// with the shard's path.
class ShardError : public StoreError {
 public:
  using StoreError::StoreError;
};

class ShardReader {
 public:
  // Opens `path` and checks that it is a result database a merge can read: the runs, trials and
  // metrics tables (and sweeps, when present) with the columns the first schema had, a schema
  // version no newer than this build's. Throws ShardError naming `path` otherwise.
  explicit ShardReader(const std::string& path);
  ~ShardReader();
  ShardReader(const ShardReader&) = delete;
  ShardReader& operator=(const ShardReader&) = delete;

  // Reads every page of the database; throws ShardError naming the path when one is damaged.
  void check_integrity();

  bool has_table(const std::string& table) const { return columns_.count(table) > 0; }
  // `column` of `table` for a SELECT list, or NULL when an older schema lacks it.
  std::string column_or_null(const std::string& table, const std::string& column) const;

  const std::string& path() const { return path_; }
  sqlite3* handle() { return db_; }

  // Throws ShardError naming the path for the last error of this connection.
  [[noreturn]] void read_failed() const;

 private:
  void read_schema();
  // Throws ShardError naming the path for the error `code` of this connection.
  [[noreturn]] void fail(int code, const std::string& during) const;

  std::string path_;
  sqlite3* db_ = nullptr;
  std::map<std::string, std::set<std::string>> columns_;  // table -> its columns
};

// A query on a shard whose failures are ShardErrors naming the shard.
class ShardQuery {
 public:
  ShardQuery(ShardReader& shard, const std::string& sql);
  ~ShardQuery();
  ShardQuery(const ShardQuery&) = delete;
  ShardQuery& operator=(const ShardQuery&) = delete;

  ShardQuery& bind(int index, int64_t value);
  bool step();  // true when a row is available
  void reset();
  const Statement& row() const { return *rows_; }  // the current row

 private:
  ShardReader& shard_;
  std::unique_ptr<Statement> rows_;
};

}  // namespace corrmp
