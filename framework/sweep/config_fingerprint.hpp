// The base configs a sweep started with: the hash of each one's values goes into the manifest,
// and a job started later (--resume, a Slurm task submitted again) refuses a base config whose
// values have changed since, which would run the sweep's jobs with different configs.
// docs/sweeps.md, "Resuming".
#pragma once

#include <string>

#include "sweep/sweep.hpp"

namespace corrmp {

// The hash of the values of the config at `path`, its includes merged: comments and layout do
// not count. Throws ConfigError when it does not load.
std::string config_values_hash(const std::string& path);

// Records the hash of each of the sweep's base configs in it.
void fingerprint_base_configs(Sweep& sweep);

// Throws ConfigError naming `config_path` when the sweep recorded a hash for it that its values
// no longer have. A sweep recorded without hashes is not checked.
void check_base_config_unchanged(const Sweep& sweep, const std::string& config_path);

// The same for every base config of the sweep.
void check_base_configs_unchanged(const Sweep& sweep);

}  // namespace corrmp
