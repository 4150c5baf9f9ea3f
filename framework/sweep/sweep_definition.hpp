// What a multirun asks for, from the command line or a sweep file under
// configs/sweeps/, turned into a Sweep (its jobs, its Slurm resources and a
// fresh id). docs/sweeps.md.
#pragma once

#include <string>
#include <vector>

#include "sweep/sweep.hpp"

namespace corrmp {

// Whether `path` is a sweep file: a YAML map whose only top-level key is `sweep`.
bool is_sweep_file(const std::string& path);

// The sweep of `config_path` (an experiment config or a sweep file) with the
// command line's assignments: sweeping ones (a,b / range() / choice()) become
// axes after the file's, the others fixed overrides after the file's. Throws
// ConfigError for a malformed sweep file or axis.
Sweep define_sweep(const std::string& config_path, const std::vector<std::string>& assignments);

// <name>-<UTC yyyymmddThhmmss>-<4 random hex digits>.
std::string new_sweep_id(const std::string& name);

}  // namespace corrmp
