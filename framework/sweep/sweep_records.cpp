// A sweep in the result database (sweep_records.hpp).
#include "sweep/sweep_records.hpp"

#include "core/config/config_error.hpp"
#include "store/statement.hpp"
#include "sweep/sweep_manifest.hpp"

namespace corrmp {

void record_sweep(ResultStore& store, const Sweep& sweep) {
  store.transaction([&] {
    Statement insert(store.handle(),
                     "INSERT OR IGNORE INTO sweeps (id, name, created_at, jobs, manifest) VALUES "
                     "(?, ?, ?, ?, ?)");
    insert.bind(1, sweep.id)
        .bind(2, sweep.name)
        .bind(3, utc_timestamp())
        .bind(4, static_cast<int64_t>(sweep.jobs.size()))
        .bind(5, manifest_yaml(sweep))
        .run();
  });
}

std::optional<Sweep> stored_sweep(ResultStore& store, const std::string& id) {
  Statement query(store.handle(), "SELECT manifest FROM sweeps WHERE id = ?");
  query.bind(1, id);
  if (!query.step()) return std::nullopt;
  const std::string origin = store.path() + ": sweep " + id;
  Sweep sweep = parse_manifest(query.column_text(0), origin);
  if (sweep.id != id) {
    throw ConfigError(origin + ": its manifest is of another sweep, '" + sweep.id + "'");
  }
  return sweep;
}

std::set<int> completed_jobs(ResultStore& store, const std::string& sweep_id) {
  Statement query(store.handle(),
                  "SELECT DISTINCT job_index FROM runs WHERE sweep_id = ? AND status = "
                  "'completed'");
  query.bind(1, sweep_id);
  std::set<int> done;
  while (query.step()) done.insert(static_cast<int>(query.column_int(0)));
  return done;
}

}  // namespace corrmp
