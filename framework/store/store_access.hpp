// Store-internal: the SQLite connection behind a ResultStore, for the store's own query files
// (and the tests' SQL helper, tests/support/store_sql.hpp). Code outside framework/store/ reads
// and writes through the typed functions of result_store.hpp, run_queries.hpp and
// sweep_queries.hpp.
#pragma once

#include <sqlite3.h>

#include "store/result_store.hpp"

namespace corrmp {

class StoreAccess {
 public:
  static sqlite3* connection(ResultStore& store) { return store.db_; }
  static void execute(ResultStore& store, const std::string& sql) { store.execute(sql); }
};

}  // namespace corrmp
