// The experiment pipeline and its run bookkeeping.
#include "experiment/pipeline.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>

#include "core/config/config_error.hpp"
#include "core/file_lock.hpp"
#include "core/interrupt.hpp"
#include "core/json_writer.hpp"
#include "core/logging.hpp"
#include "evaluation/environment_evaluation.hpp"
#include "evaluation/offline_evaluation.hpp"
#include "evaluation/trajectory_outputs.hpp"
#include "experiment/demonstration_cache.hpp"
#include "experiment/interrupted_runs.hpp"
#include "experiment/policy_fitting.hpp"
#include "experiment/provenance.hpp"
#include "experiment/training_curves.hpp"
#include "store/result_store.hpp"

namespace corrmp {

namespace fs = std::filesystem;

namespace {

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

void write_run_json(const fs::path& dir, const Experiment& experiment, int64_t run_id,
                    const GitState& git, const std::string& started_at, const RunResult& result,
                    const std::string& finished_at) {
  JsonObject versions;
  for (const auto& [name, version] : library_versions()) versions.add(name, version);
  JsonObject run;
  run.add("run_id", run_id)
      .add("experiment", experiment.config.experiment.name)
      .add("status", to_string(result.status))
      .add("seed", static_cast<int64_t>(experiment.config.seed))
      .add("config", experiment.config_path)
      .add("config_hash", experiment.config_hash)
      .add("git_commit", git.commit)
      .add("git_dirty", git.dirty)
      .add("host", host_name())
      .add("started_at", started_at);
  if (finished_at.empty()) {
    run.add_null("finished_at");
  } else {
    run.add("finished_at", finished_at);
  }
  if (!result.failure.empty()) run.add("failure", result.failure);
  run.add("libraries", versions);
  write_text(dir / "run.json", run.str(2) + "\n");
}

// What determines an environment's demonstrations: the source's type and
// version, the environment and demonstrations sections and the root seed (""
// without an environment: files and synthetic curves are not cached).
std::string demonstrations_key(const Experiment& experiment) {
  const auto& config = experiment.config;
  if (!experiment.environment) return "";
  const std::string text = fmt::format("{} version {} seed {}\n{}{}", config.demonstrations->type,
                                       experiment.demonstrations->version(), config.seed,
                                       config.environment->node->to_yaml_string(),
                                       config.demonstrations->node->to_yaml_string());
  return fmt::format("{:016x}", fnv1a64(text));
}

// Demonstrations from the cache when the same environment, source and seed
// made them before; else collected (and cached when an expert made them). A
// cache file that cannot be read is reported and collected again.
DemonstrationSplit collect_or_reuse(Experiment& experiment, const fs::path& cache_dir,
                                    const std::string& key, bool use_cache, Rng& rng) {
  const fs::path cache = cache_dir / fmt::format("demonstrations-{}.bin", key);
  // Concurrent runs (a sweep's jobs) wanting the same demonstrations: the
  // first collects them, the others wait and reuse them.
  std::optional<FileLock> lock;
  if (!key.empty()) lock.emplace(cache.string() + ".lock");
  if (!key.empty() && use_cache) {
    try {
      if (auto cached = load_demonstrations(cache.string())) {
        spdlog::info("reusing cached demonstrations {}", cache.string());
        return std::move(*cached);
      }
    } catch (const std::exception& e) {
      spdlog::warn("{}; collecting the demonstrations again", e.what());
    }
  }
  DemonstrationSplit demos = experiment.demonstrations->collect(experiment.environment.get(), rng);
  if (!key.empty()) save_demonstrations(cache.string(), demos);
  return demos;
}

// The stages. Each appends what it measured; none invents a number.
void run_stages(Experiment& experiment, const fs::path& dir, const RunOptions& options,
                std::vector<TrialRecord>& trials, std::vector<MetricRecord>& metrics) {
  const fs::path cache_dir = fs::path(options.out_dir) / "cache";
  if (!experiment.demonstrations) {
    spdlog::warn("no demonstrations section: nothing to collect, train or evaluate");
    return;
  }
  Rng collect_rng = experiment.seeds.stream("demonstrations");
  spdlog::info("collecting demonstrations ({})", experiment.config.demonstrations->type);
  const std::string key = demonstrations_key(experiment);
  DemonstrationSplit demos =
      collect_or_reuse(experiment, cache_dir, key, options.use_cache, collect_rng);
  check_interrupt();
  spdlog::info("collected {} training and {} validation demonstrations", demos.train.size(),
               demos.validation.size());
  const MetricDeclaration count = count_metric(Better::neither);
  metrics.push_back({"demonstrations_train", static_cast<double>(demos.train.size()), count});
  metrics.push_back(
      {"demonstrations_validation", static_cast<double>(demos.validation.size()), count});
  if (!experiment.policy) {
    spdlog::warn("no policy section: stopping after collection");
    return;
  }

  const ExtractorCache extractor_cache{key.empty() ? "" : cache_dir.string(), key,
                                       options.use_cache};
  if (experiment.context_extractor) {
    spdlog::info("fitting the context extractor ({})", experiment.config.context->type);
  }
  const auto summaries =
      fit_extractor_and_policy(*experiment.policy, experiment.context_extractor.get(), demos,
                               {experiment.seeds.stream("policy.training"),
                                experiment.seeds.stream("context"), extractor_cache, dir.string()});
  for (const auto& summary : summaries) {
    const std::string team =
        summary.report.team_updates > 0
            ? fmt::format(
                  " ({} of the updates on a team of two threads, the rest on one; the "
                  "same results either way)",
                  summary.report.team_updates)
            : "";
    spdlog::info(
        "'{}': {} parameters, best validation error {:.4g} (max {:.4g}) at update {} "
        "of {}, {:.1f} s{}",
        summary.segment, summary.parameters, summary.report.best_validation.mean,
        summary.report.best_validation.max, summary.report.best_update, summary.report.updates,
        summary.report.seconds, team);
    metrics.push_back(
        {summary.segment + "_parameters", static_cast<double>(summary.parameters), count});
  }
  experiment.policy->save((dir / "models").string());
  write_training_curves(summaries, (dir / "training_curves.csv").string());

  const bool write = experiment.config.output.write_predictions;
  if (experiment.environment) {
    Rng evaluation_rng(mix64(experiment.config.evaluation.seed ^ fnv1a64("evaluation")));
    if (experiment.context_extractor) experiment.context_extractor->start_evaluation();
    EnvironmentEvaluation evaluation = evaluate_in_environment(
        *experiment.environment, *experiment.demonstrations, experiment.context_extractor.get(),
        *experiment.policy, experiment.config.evaluation.trials, evaluation_rng,
        experiment.config.experiment.name);
    trials = std::move(evaluation.trials);
    metrics.insert(metrics.end(), evaluation.metrics.begin(), evaluation.metrics.end());
    std::ofstream(dir / "tables.txt") << evaluation.tables;
    fmt::print("{}", evaluation.tables);
    // The trial files are for plotting: a failure to write them is reported,
    // and the measured trials are still recorded.
    if (write) {
      try {
        write_trajectory_csv(evaluation.evaluated, evaluation.task,
                             (dir / "trajectories.csv").string());
        std::vector<std::string> order;
        for (const auto& s : experiment.environment->segments()) order.push_back(s.name);
        write_trajectory_figure(evaluation.evaluated, evaluation.task, order,
                                (dir / "trajectories.png").string());
        experiment.environment->write_figures(dir.string(), evaluation.evaluated, demos.train);
      } catch (const std::exception& e) {
        spdlog::warn("trajectory files not written: {}", e.what());
      }
    }
    return;
  }
  const std::string csv_dir = write ? (dir / "predictions").string() : "";
  for (const auto& result : evaluate_offline(*experiment.policy, demos.validation, csv_dir)) {
    spdlog::info("'{}' on {} held-out demonstrations: error mean {:.4g}, max {:.4g}",
                 result.segment, demos.validation.size(), result.error.mean, result.error.max);
    // In the demonstrations' own units, which they do not declare.
    const std::string heading = result.segment + " error mean / max (held-out)";
    metrics.push_back(
        {result.segment + "_error_mean", result.error.mean, error_statistic("", heading, "mean")});
    metrics.push_back(
        {result.segment + "_error_max", result.error.max, error_statistic("", heading, "max")});
  }
}

// The folder a run's outputs go in must be a folder this process can write: otherwise the
// run is refused (ConfigError, exit 2) before it is recorded, like a bad config.
void check_output_folder(const fs::path& folder) {
  std::error_code error;
  fs::create_directories(folder, error);
  if (error || !fs::is_directory(folder)) {
    throw ConfigError(fmt::format("--out: cannot make the output folder {}: {}", folder.string(),
                                  error ? error.message() : "a file is in the way"));
  }
  if (::access(folder.c_str(), W_OK | X_OK) != 0) {
    throw ConfigError(fmt::format("--out: cannot write in the output folder {}: {}",
                                  folder.string(), std::strerror(errno)));
  }
}

}  // namespace

RunResult run_pipeline(Experiment& experiment, const RunOptions& options) {
  ResultStore store(options.db_path);
  if (const int stale = mark_interrupted_runs(store); stale > 0) {
    spdlog::warn("{}: marked {} run(s) left 'running' by ended processes as interrupted",
                 options.db_path, stale);
  }
  check_output_folder(fs::path(options.out_dir) / experiment.config.experiment.name);
  const GitState git = build_git_state();
  RunResult result;
  RunRecord record{experiment.config.experiment.name,
                   experiment.resolved_yaml,
                   experiment.config_hash,
                   experiment.config.seed,
                   git.commit,
                   git.dirty,
                   "",
                   options.sweep_id,
                   options.job_index,
                   options.axes_json,
                   {}};
  if (experiment.environment) record.task = experiment.environment->report();
  result.run_id = store.begin_run(record);
  const std::string started_at = utc_timestamp();
  // A sweep's runs get their own folder: the shard databases of a Slurm array
  // all number their runs from 1.
  const fs::path dir = options.sweep_id.empty()
                           ? fs::path(options.out_dir) / experiment.config.experiment.name /
                                 std::to_string(result.run_id)
                           : fs::path(options.out_dir) / experiment.config.experiment.name /
                                 options.sweep_id /
                                 fmt::format("job-{}-run-{}", options.job_index, result.run_id);
  result.run_dir = dir.string();

  std::vector<TrialRecord> trials;
  std::vector<MetricRecord> metrics;
  try {
    fs::create_directories(dir);
    store.set_out_dir(result.run_id, dir.string());
    add_log_file((dir / "log.txt").string());
    if (const std::string changed = source_change_warning(git, source_git_state());
        !changed.empty())
      spdlog::warn("{}", changed);
    write_text(dir / "config.resolved.yaml", experiment.resolved_yaml);
    write_run_json(dir, experiment, result.run_id, git, started_at, result, "");
    spdlog::info("run {} of '{}' in {}", result.run_id, experiment.config.experiment.name,
                 dir.string());
    run_stages(experiment, dir, options, trials, metrics);
    // Read last: an extractor may measure itself on every context it gave.
    if (experiment.context_extractor) {
      for (auto& metric : experiment.context_extractor->metrics()) {
        metrics.push_back(std::move(metric));
      }
    }
    store.complete_run(result.run_id, trials, metrics);
    result.status = RunStatus::completed;
  } catch (const Interrupted& e) {
    result.status = RunStatus::interrupted;
    result.failure = e.what();
  } catch (const std::exception& e) {
    result.status = RunStatus::failed;
    result.failure = e.what();
  }
  if (result.status != RunStatus::completed) {
    spdlog::error("run {} {}: {}", result.run_id, to_string(result.status), result.failure);
    store.end_run(result.run_id, result.status, result.failure);
  }
  if (fs::exists(dir)) {
    write_run_json(dir, experiment, result.run_id, git, started_at, result, utc_timestamp());
  }
  return result;
}

}  // namespace corrmp
