// Test helper: SQL on a result store's own connection, for the tests that fabricate what the
// typed store functions never write (an older schema, a row its checks refuse) or look at the
// rows a tool wrote. Everything else reads and writes through the store's typed functions.
#pragma once

#include <cstdint>
#include <string>

#include "store/statement.hpp"
#include "store/store_access.hpp"

namespace corrmp::testing {

// Executes SQL without results (inside a transaction of `store` too).
inline void execute_sql(ResultStore& store, const std::string& sql) {
  StoreAccess::execute(store, sql);
}

// The first column of the first row of a query, as text ("" when no row).
inline std::string query_text(ResultStore& store, const std::string& sql) {
  Statement statement(StoreAccess::connection(store), sql);
  return statement.step() ? statement.column_text(0) : std::string();
}

// The first column of the first row of a query, as an integer (0 when no row).
inline int64_t query_int(ResultStore& store, const std::string& sql) {
  Statement statement(StoreAccess::connection(store), sql);
  return statement.step() ? statement.column_int(0) : 0;
}

// Takes `store` back to schema version 3, as builds before metrics and tasks were declared wrote
// it: no declaration columns on the metrics, no run_tasks table.
inline void downgrade_to_version_3(ResultStore& store) {
  execute_sql(store,
              "DROP TABLE run_tasks; ALTER TABLE metrics DROP COLUMN unit; ALTER TABLE metrics "
              "DROP COLUMN range_min; ALTER TABLE metrics DROP COLUMN range_max; ALTER TABLE "
              "metrics DROP COLUMN better; ALTER TABLE metrics DROP COLUMN heading; ALTER TABLE "
              "metrics DROP COLUMN statistic; PRAGMA user_version = 3");
}

}  // namespace corrmp::testing
