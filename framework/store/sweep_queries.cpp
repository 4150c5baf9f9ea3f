// Sweeps in the result database (sweep_queries.hpp).
#include "store/sweep_queries.hpp"

#include "store/run_queries.hpp"
#include "store/statement.hpp"
#include "store/store_access.hpp"

namespace corrmp {

namespace {

bool table_exists(sqlite3* db, const std::string& table) {
  Statement exists(db, "SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = ?");
  exists.bind(1, table);
  return exists.step();
}

}  // namespace

void insert_sweep_record(ResultStore& store, const SweepRecord& sweep) {
  store.transaction([&] {
    Statement insert(StoreAccess::connection(store),
                     "INSERT OR IGNORE INTO sweeps (id, name, created_at, jobs, manifest) VALUES "
                     "(?, ?, ?, ?, ?)");
    insert.bind(1, sweep.id)
        .bind(2, sweep.name)
        .bind(3, utc_timestamp())
        .bind(4, static_cast<int64_t>(sweep.jobs))
        .bind(5, sweep.manifest)
        .run();
  });
}

std::optional<SweepRecord> find_sweep_record(ResultStore& store, const std::string& id) {
  sqlite3* db = StoreAccess::connection(store);
  if (!table_exists(db, "sweeps")) return std::nullopt;
  Statement select(db, "SELECT name, created_at, jobs, manifest FROM sweeps WHERE id = ?");
  select.bind(1, id);
  if (!select.step()) return std::nullopt;
  return SweepRecord{id, select.column_text(0), select.column_text(1),
                     static_cast<int>(select.column_int(2)), select.column_text(3)};
}

bool sweep_has_runs(ResultStore& store, const std::string& id) {
  if (!records_sweeps(store)) return false;
  Statement runs(StoreAccess::connection(store), "SELECT 1 FROM runs WHERE sweep_id = ? LIMIT 1");
  runs.bind(1, id);
  return runs.step();
}

std::set<int> completed_sweep_jobs(ResultStore& store, const std::string& sweep_id) {
  Statement select(StoreAccess::connection(store),
                   "SELECT DISTINCT job_index FROM runs WHERE sweep_id = ? AND status = "
                   "'completed'");
  select.bind(1, sweep_id);
  std::set<int> done;
  while (select.step()) done.insert(static_cast<int>(select.column_int(0)));
  return done;
}

}  // namespace corrmp
