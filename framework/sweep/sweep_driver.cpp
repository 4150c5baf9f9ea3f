// Driving a multirun (sweep_driver.hpp).
#include "sweep/sweep_driver.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>

#include "core/config/config_error.hpp"
#include "core/config/config_loader.hpp"
#include "experiment/experiment.hpp"
#include "experiment/interrupted_runs.hpp"
#include "store/store_merge.hpp"
#include "sweep/config_fingerprint.hpp"
#include "sweep/local_sweep.hpp"
#include "sweep/shell_words.hpp"
#include "sweep/slurm_launcher.hpp"
#include "sweep/sweep_folders.hpp"
#include "sweep/sweep_manifest.hpp"
#include "sweep/sweep_records.hpp"

namespace corrmp {

namespace fs = std::filesystem;

namespace {

std::string describe_axes(const SweepJob& job) {
  std::string text;
  for (const auto& [key, value] : job.axes) text += (text.empty() ? "" : " ") + key + "=" + value;
  return text.empty() ? job.config_path : text;
}

// An error about one of `job`'s overrides that a sweep file set, placed in that file: the
// override is found by the place the config loader gave its values (its file part, whatever
// the line of a value nested in it), then by its position (the file's fixed overrides come
// first in every job, the axes last). Null for other errors.
std::optional<ConfigError> in_sweep_file(const Sweep& sweep, const SweepJob& job,
                                         const ConfigError& error, const std::string& context) {
  const auto& overrides = job.overrides;
  std::size_t i = 0;
  while (i < overrides.size() && override_location(overrides[i]).file != error.where().file) ++i;
  if (i == overrides.size()) return std::nullopt;
  const SweepKeyOrigin* origin = nullptr;
  if (i + job.axes.size() >= overrides.size()) {
    const std::string key = overrides[i].substr(0, overrides[i].find('='));
    for (const SweepKeyOrigin& axis : sweep.file_places.axes) {
      if (axis.key == key) origin = &axis;
    }
  } else if (i < sweep.file_places.overrides.size()) {
    origin = &sweep.file_places.overrides[i];
  }
  if (origin == nullptr) return std::nullopt;  // the command line's
  // The key the error names when it is not the override's own (one nested in its value, or
  // a misspelt part of its path).
  std::string path = origin->path;
  const std::string& key = error.key_path().empty() ? origin->key : error.key_path();
  if (path == "sweep.overrides" || key != origin->key) path += ": " + key;
  return ConfigError(origin->where, path, error.reason() + context);
}

// Writes the manifest, the array script and the folders its tasks write to; `option` is the
// command-line option that gave `dir`, for an error about it.
std::string write_slurm_files(const Sweep& sweep, const SweepDriverOptions& options,
                              const fs::path& dir, const std::string& option) {
  SlurmPaths paths;
  paths.run_experiment = options.executable;
  paths.manifest = (dir / "manifest.yaml").string();
  paths.shard_dir = (dir / "shards").string();
  paths.out_dir = options.run.out_dir;
  paths.log_dir = (dir / "logs").string();
  // Rendered first: resources an #SBATCH line cannot hold are refused before
  // anything is written.
  std::string text;
  try {
    text = slurm_array_script(sweep, paths);
  } catch (const std::invalid_argument& e) {
    throw ConfigError(e.what());
  }
  make_sweep_folder(dir, option);
  make_sweep_folder(dir / "shards", option);
  make_sweep_folder(dir / "logs", option);
  write_manifest(paths.manifest, sweep);
  const fs::path script = dir / "sweep.sbatch";
  std::ofstream(script) << text;
  if (!fs::exists(script)) throw std::runtime_error("cannot write " + script.string());
  return script.string();
}

int run_on_slurm(const Sweep& sweep, const SweepDriverOptions& options) {
  const bool emit_only = !options.emit_dir.empty();
  const fs::path dir =
      emit_only ? fs::path(options.emit_dir) : fs::path(options.run.out_dir) / "sweeps" / sweep.id;
  // What this invocation makes goes again if the array is not submitted.
  NewFolderCleanup cleanup(dir);
  const std::string script =
      write_slurm_files(sweep, options, dir, emit_only ? "--emit slurm" : "--out");
  // Printed commands are quoted for bash; the shards' pattern is left for it to expand.
  const std::string merge_command =
      fmt::format("run_experiment merge {}/*.sqlite --db {}", shell_word((dir / "shards").string()),
                  shell_word(options.run.db_path));
  if (emit_only) {
    cleanup.keep();
    fmt::print("wrote {} ({} array tasks); submit with: sbatch {}\nthen merge: {}\n", script,
               sweep.jobs.size(), shell_word(script), merge_command);
    return 0;
  }
  const SlurmSubmission submission = submit_slurm(script, options.wait);
  cleanup.keep();
  fmt::print("sweep {}: submitted Slurm job array {} ({} tasks)\n", sweep.id, submission.job_id,
             sweep.jobs.size());
  if (!options.wait) {
    fmt::print("when it has finished: {}\n", merge_command);
    return 0;
  }
  std::vector<std::string> shards;
  for (const auto& entry : fs::directory_iterator(dir / "shards")) {
    if (entry.path().extension() == ".sqlite") shards.push_back(entry.path().string());
  }
  std::sort(shards.begin(), shards.end());
  merge_shards(shards, options.run.db_path);
  return submission.exit_code.value_or(1) == 0 ? 0 : 1;
}

}  // namespace

void merge_shards(const std::vector<std::string>& shards, const std::string& db_path) {
  check_shards(shards, db_path);  // before the target is opened or made
  // A failed merge leaves no target it made: the file with its -wal and -shm, or the topmost
  // folder made for it, goes again (NewFolderCleanup removes a new file as well as a folder).
  std::error_code error;
  const bool target_is_new = !fs::exists(fs::symlink_status(db_path, error));
  NewFolderCleanup new_target(db_path);
  std::vector<MergeCounts> counts;
  try {
    ResultStore target(db_path);
    counts = merge_shards_into(target, shards);
  } catch (...) {
    if (target_is_new) {
      for (const char* suffix : {"-wal", "-shm"}) fs::remove(db_path + suffix, error);
    }
    throw;
  }
  new_target.keep();
  for (size_t i = 0; i < shards.size(); ++i) {
    fmt::print("{}: {} runs added, {} already in {}{}\n", shards[i], counts[i].added,
               counts[i].present, db_path,
               counts[i].unfinished > 0
                   ? fmt::format(", {} still running (merge again later)", counts[i].unfinished)
                   : "");
  }
}

void check_sweep_jobs(const Sweep& sweep, const Registries& registries) {
  if (sweep.jobs.empty()) throw ConfigError("the sweep has no jobs");
  for (const auto& job : sweep.jobs) {
    try {
      load_experiment(job.config_path, job.overrides, registries);
    } catch (const ConfigError& e) {
      const std::string context = fmt::format(" (sweep job {}: {})", job.index, describe_axes(job));
      if (auto placed = in_sweep_file(sweep, job, e, context)) throw *placed;
      throw ConfigError(e.what() + context);
    }
  }
}

int drive_sweep(const Sweep& sweep, const SweepDriverOptions& options) {
  if (options.launcher == "slurm" || !options.emit_dir.empty()) {
    return run_on_slurm(sweep, options);
  }
  LocalSweepOptions local;
  local.executable = options.executable;
  local.db_path = options.run.db_path;
  local.out_dir = options.run.out_dir;
  local.use_cache = options.run.use_cache;
  local.parallel_jobs = std::max(1, options.parallel_jobs);
  local.threads_per_job = std::max(1, options.threads / local.parallel_jobs);
  const SweepOutcome outcome = run_sweep_locally(sweep, local);
  fmt::print(
      "sweep {}: {} completed, {} failed, {} interrupted{} ({} completed before); "
      "runs in {} (report --sweep {}), logs in {}\n",
      sweep.id, outcome.completed, outcome.failed, outcome.interrupted,
      outcome.not_started > 0 ? fmt::format(", {} not started", outcome.not_started) : "",
      outcome.skipped, options.run.db_path, shell_word(sweep.id), outcome.directory);
  if (outcome.interrupted > 0 || outcome.not_started > 0) {
    fmt::print("resume with: run_experiment --resume {} --db {} --out {}{}{}\n",
               shell_word(sweep.id), shell_word(options.run.db_path),
               shell_word(options.run.out_dir),
               local.parallel_jobs > 1 ? fmt::format(" -j {}", local.parallel_jobs) : "",
               local.use_cache ? "" : " --no-cache");
    return 130;
  }
  return outcome.failed > 0 ? 1 : 0;
}

int run_sweep_job(const std::string& manifest, int index, const RunOptions& options,
                  const Registries& registries) {
  const Sweep sweep = read_manifest(manifest);
  if (index < 0 || index >= static_cast<int>(sweep.jobs.size())) {
    throw ConfigError(
        fmt::format("{}: no job {} (the sweep has {})", manifest, index, sweep.jobs.size()));
  }
  const SweepJob& job = sweep.jobs[static_cast<size_t>(index)];
  check_base_config_unchanged(sweep, job.config_path);
  {
    ResultStore store(options.db_path);
    record_sweep(store, sweep);
    if (completed_jobs(store, sweep.id).count(index) > 0) {
      spdlog::info("sweep {} job {} has a completed run already: nothing to do", sweep.id, index);
      return 0;
    }
    // An earlier attempt still 'running' was killed (a driver killed, a Slurm
    // time limit, a lost node) on whatever host it ran, unless its process is
    // alive on this host: marked so in the database and its run.json.
    mark_job_runs_interrupted(store, sweep.id, index);
  }
  Experiment experiment = load_experiment(job.config_path, job.overrides, registries);
  RunOptions run = options;
  run.sweep_id = sweep.id;
  run.job_index = index;
  run.axes_json = axes_json(job);
  const RunResult result = run_pipeline(experiment, run);
  if (result.status == RunStatus::completed) return 0;
  return result.status == RunStatus::interrupted ? 130 : 1;
}

}  // namespace corrmp
