// Hashes of a sweep's base configs (config_fingerprint.hpp).
#include "sweep/config_fingerprint.hpp"

#include <fmt/format.h>

#include "core/config/config_loader.hpp"
#include "core/seeds.hpp"

namespace corrmp {

std::string config_values_hash(const std::string& path) {
  return fmt::format("{:016x}", fnv1a64(load_config_file(path).to_yaml_string()));
}

void fingerprint_base_configs(Sweep& sweep) {
  sweep.config_hashes.clear();
  for (const auto& job : sweep.jobs) {
    bool known = false;
    for (const auto& [path, hash] : sweep.config_hashes) known = known || path == job.config_path;
    if (!known)
      sweep.config_hashes.emplace_back(job.config_path, config_values_hash(job.config_path));
  }
}

void check_base_config_unchanged(const Sweep& sweep, const std::string& config_path) {
  for (const auto& [path, hash] : sweep.config_hashes) {
    if (path != config_path || config_values_hash(path) == hash) continue;
    throw ConfigError(fmt::format(
        "{}: changed since sweep {} started (its hash differs): its remaining jobs would run "
        "another config than its finished ones; restore the file, or start a new sweep",
        path, sweep.id));
  }
}

void check_base_configs_unchanged(const Sweep& sweep) {
  for (const auto& [path, hash] : sweep.config_hashes) check_base_config_unchanged(sweep, path);
}

}  // namespace corrmp
