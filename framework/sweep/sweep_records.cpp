// A sweep in the result database (sweep_records.hpp).
#include "sweep/sweep_records.hpp"

#include "core/config/config_error.hpp"
#include "store/sweep_queries.hpp"
#include "sweep/sweep_manifest.hpp"

namespace corrmp {

void record_sweep(ResultStore& store, const Sweep& sweep) {
  insert_sweep_record(
      store, {sweep.id, sweep.name, "", static_cast<int>(sweep.jobs.size()), manifest_yaml(sweep)});
}

std::optional<Sweep> stored_sweep(ResultStore& store, const std::string& id) {
  const auto record = find_sweep_record(store, id);
  if (!record) return std::nullopt;
  const std::string origin = store.path() + ": sweep " + id;
  Sweep sweep = parse_manifest(record->manifest, origin);
  if (sweep.id != id) {
    throw ConfigError(origin + ": its manifest is of another sweep, '" + sweep.id + "'");
  }
  return sweep;
}

std::set<int> completed_jobs(ResultStore& store, const std::string& sweep_id) {
  return completed_sweep_jobs(store, sweep_id);
}

}  // namespace corrmp
