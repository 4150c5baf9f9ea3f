// A sweep: the jobs of a multirun (the cross product of its axes over one or
// more base configs), each one run of run_experiment with its own overrides.
// docs/sweeps.md.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/config/config_error.hpp"

namespace corrmp {

// What each job asks of a cluster scheduler (Slurm): from the sweep file's
// `slurm:` section, or the defaults.
struct SlurmResources {
  int cpus_per_task = 2;
  std::string time = "01:00:00";  // Slurm's --time
  std::string memory = "4G";      // Slurm's --mem
  std::string partition;          // empty: the cluster's default
};

struct SweepJob {
  int index = 0;
  std::string config_path;  // the base config this job runs
  // Every override in force for this job, in order: the sweep's fixed ones,
  // then one per axis.
  std::vector<std::string> overrides;
  // The axis values that make this job (key, value as written), for the
  // database and the reports.
  std::vector<std::pair<std::string, std::string>> axes;
};

// Where a sweep file set a config key, so that an error in its value names that place rather
// than the command line.
struct SweepKeyOrigin {
  std::string key;       // the config key path it sets, e.g. policy.training.updates
  SourceLocation where;  // its place in the sweep file
  std::string
      path;  // the file's own path to it: sweep.axes.<key>, sweep.zip.<key>, sweep.overrides
};

// The places of a sweep file's settings; not kept in the manifest.
struct SweepFilePlaces {
  std::vector<SweepKeyOrigin> overrides;  // its `overrides`, in order: the first of every job's
  std::vector<SweepKeyOrigin> axes;       // its `axes` and `zip` axes (keys swept once each)
};

struct Sweep {
  std::string id;    // unique: <name>-<UTC time>-<random hex>
  std::string name;  // the sweep file's name, or the base config's experiment
  std::vector<SweepJob> jobs;
  SlurmResources slurm;
  SweepFilePlaces file_places;
  // Each base config (as the jobs name it) with the hash of its values when the sweep started
  // (config_fingerprint.hpp); empty for a sweep recorded before hashes were kept.
  std::vector<std::pair<std::string, std::string>> config_hashes;
};

}  // namespace corrmp
