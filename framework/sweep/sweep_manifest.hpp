// A sweep's manifest: its id, name, Slurm resources and every job (config,
// overrides, axis values) as YAML. The sweep's driver writes it; each job's
// process (`run_experiment --sweep-job MANIFEST INDEX`, locally or as a Slurm
// array task) reads its own job from it; the database keeps a copy, from which
// `--resume` restarts the sweep. docs/sweeps.md.
#pragma once

#include <string>

#include "sweep/sweep.hpp"

namespace corrmp {

std::string manifest_yaml(const Sweep& sweep);

// Throws std::runtime_error naming `origin` when the text is not a manifest, and
// ConfigError when its id is not a safe name (sweep_names.hpp).
Sweep parse_manifest(const std::string& text, const std::string& origin);

// Written to a temporary name, then renamed into place.
void write_manifest(const std::string& path, const Sweep& sweep);
Sweep read_manifest(const std::string& path);

// The job's axis values as a JSON object, for the database.
std::string axes_json(const SweepJob& job);

}  // namespace corrmp
