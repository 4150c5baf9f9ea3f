// run_experiment CONFIG [key.path=value ...] [options]: loads and validates an
// experiment config, then runs the pipeline and records it in the result store.
// With -m (or a sweep file) it runs a sweep: every combination of the swept
// values, -j N at a time, here or on Slurm (docs/sweeps.md); `merge` merges
// the shard databases of a Slurm sweep.
// Exit codes: 0 success; 2 usage or config error (nothing written to the
// database); 1 runtime failure (the run is marked failed with its reason);
// 130 interrupted. docs/architecture.md, "Command line".
#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <thread>

#include "command_line.hpp"

#include "core/config/config_error.hpp"
#include "core/config/config_loader.hpp"
#include "core/interrupt.hpp"
#include "core/logging.hpp"
#include "core/thread_budget.hpp"
#include "experiment/experiment.hpp"
#include "experiment/pipeline.hpp"
#include "experiment/registries.hpp"
#include "store/result_store.hpp"
#include "sweep/config_fingerprint.hpp"
#include "sweep/sweep_axes.hpp"
#include "sweep/sweep_definition.hpp"
#include "sweep/sweep_driver.hpp"
#include "sweep/sweep_manifest.hpp"
#include "sweep/sweep_names.hpp"
#include "sweep/sweep_records.hpp"

namespace {

constexpr const char* kExamples = R"(
Examples:
  run_experiment configs/curves_demo.yaml
  run_experiment configs/curves_demo.yaml seed=7 demonstrations.train=50
  run_experiment configs/curves_demo.yaml --print-config
  run_experiment --list
  run_experiment configs/curves_demo.yaml --db /tmp/sweep.sqlite --out /tmp/runs --quiet
  run_experiment configs/corridor_pc.yaml -m seed=range(0,5) policy.training.updates=2000,8000 -j 2
  run_experiment configs/sweeps/paper.yaml -j 2
  run_experiment --resume corridor_pc-20261123T110000-ab12
  run_experiment configs/sweeps/paper.yaml --launcher slurm
  run_experiment configs/sweeps/paper.yaml --emit slurm /shared/sweep
  run_experiment merge /shared/sweep/shards/*.sqlite --db results/results.sqlite
)";

int merge_command(const std::vector<std::string>& shards, const std::string& db_path) {
  try {
    corrmp::merge_shards(shards, db_path);
  } catch (const corrmp::StoreError& e) {
    std::cerr << "run_experiment merge: " << e.what() << "\n";
    return 2;
  }
  return 0;
}

// load_experiment for a run without -m: an error about an override that looks like a sweep
// axis (a,b, range(), choice()) says that -m makes it one.
corrmp::Experiment load_single_run(const std::string& config_path,
                                   const std::vector<std::string>& overrides,
                                   const corrmp::Registries& registries) {
  try {
    return corrmp::load_experiment(config_path, overrides, registries);
  } catch (const corrmp::ConfigError& e) {
    for (const auto& assignment : overrides) {
      if (corrmp::is_sweep_assignment(assignment) &&
          e.where().file == corrmp::override_location(assignment).file) {
        throw corrmp::ConfigError(std::string(e.what()) + " (to sweep over '" + assignment +
                                  "', add -m)");
      }
    }
    throw;
  }
}

std::string this_executable() {
  std::error_code error;
  const auto path = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error) throw std::runtime_error("cannot locate this executable: " + error.message());
  return path.string();
}

int parse_index(const std::string& text) {
  try {
    size_t used = 0;
    const int index = std::stoi(text, &used);
    if (used == text.size() && index >= 0) return index;
  } catch (const std::exception&) {
  }
  throw corrmp::ConfigError("--sweep-job: '" + text + "' is not a job index");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Runs an experiment of the correction-primitive framework.", "run_experiment"};
  std::string config_path;
  std::vector<std::string> overrides;
  corrmp::RunOptions options;
  bool print_config = false, list = false, quiet = false;
  app.add_option("config", config_path, "experiment config (YAML)");
  app.add_option("overrides", overrides, "key.path=value overrides, applied in order");
  app.add_flag("--print-config", print_config, "print the resolved config and exit");
  app.add_flag("--list", list, "list every registered component and its parameters");
  app.add_option("--db", options.db_path, "result database")->capture_default_str();
  app.add_option("--out", options.out_dir, "directory for run outputs")->capture_default_str();
  bool no_cache = false;
  app.add_flag("--no-cache", no_cache,
               "collect demonstrations and fit context extractors afresh instead of reusing "
               "<out>/cache (the fresh results still replace the cached ones)");
  app.add_flag("-q,--quiet", quiet, "only warnings and errors on stderr");

  bool multirun = false;
  corrmp::SweepDriverOptions sweep_options;
  std::string resume;
  std::vector<std::string> sweep_job;
  std::vector<std::string> emit;
  int threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  app.add_flag("-m,--multirun", multirun,
               "sweep: overrides with a,b,c, range(start,stop[,step]) or choice(a,b) values "
               "are axes; every combination runs");
  app.add_option("-j,--jobs", sweep_options.parallel_jobs, "sweep jobs to run at once")
      ->check(CLI::Range(1, 256))
      ->capture_default_str();
  app.add_option("--threads", threads,
                 "threads of this run (of all jobs, for a sweep); default: all cores")
      ->check(CLI::Range(1, 1024))
      ->capture_default_str();
  app.add_option("--resume", resume, "run a sweep's jobs that have no completed run yet");
  app.add_option("--launcher", sweep_options.launcher, "where a sweep's jobs run")
      ->check(CLI::IsMember({"local", "slurm"}))
      ->capture_default_str();
  app.add_option("--emit", emit, "only write the sweep's Slurm files: --emit slurm DIR")
      ->expected(2);
  app.add_flag("--wait", sweep_options.wait,
               "slurm: wait for the job array, then merge its shards into --db");
  app.add_option("--sweep-job", sweep_job, "run job INDEX of a sweep manifest (used by sweeps)")
      ->expected(2)
      ->group("");
  std::vector<std::string> shards;
  std::string merge_db = "results/results.sqlite";
  CLI::App* merge = app.add_subcommand("merge", "merge shard databases of a Slurm sweep");
  merge->add_option("shards", shards, "shard databases")->required();
  merge->add_option("--db", merge_db, "the database to merge into")->capture_default_str();
  app.footer(kExamples);
  if (const auto exit_code = corrmp::parse_command_line(app, argc, argv)) return *exit_code;

  corrmp::setup_logging(quiet);
  options.use_cache = !no_cache;
  corrmp::set_thread_budget(threads);
  // Mesa's llvmpipe rasteriser (the head camera) starts one thread per core
  // unless told otherwise: keep it within this run's share of the cores,
  // unless the user set LP_NUM_THREADS (a sweep's driver renders nothing and
  // sets nothing; its jobs get their own --threads).
  const auto limit_renderer_threads = [threads] {
    ::setenv("LP_NUM_THREADS", std::to_string(threads).c_str(), 0);
  };
  try {
    if (merge->parsed()) return merge_command(shards, merge_db);
    const corrmp::Registries registries = corrmp::builtin_registries();
    if (list) {
      std::cout << corrmp::describe_registries(registries);
      return 0;
    }
    if (!sweep_job.empty()) {
      corrmp::install_interrupt_handlers();
      limit_renderer_threads();
      return corrmp::run_sweep_job(sweep_job[0], parse_index(sweep_job[1]), options, registries);
    }
    sweep_options.run = options;
    sweep_options.threads = threads;
    if (!emit.empty()) {
      if (emit[0] != "slurm") {
        std::cerr << "run_experiment: --emit takes 'slurm DIR'\n";
        return 2;
      }
      if (emit[1].empty()) {
        std::cerr << "run_experiment: --emit slurm: the folder is empty\n";
        return 2;
      }
      sweep_options.emit_dir = emit[1];
    }
    if (!resume.empty()) {
      if (!config_path.empty() || multirun || print_config) {
        std::cerr << "run_experiment: --resume takes no config, overrides, -m or --print-config: "
                     "the sweep's jobs are in the database\n";
        return 2;
      }
      if (const std::string problem = corrmp::sweep_id_problem(resume); !problem.empty()) {
        std::cerr << "run_experiment: --resume: " << problem << "\n";
        return 2;
      }
      if (!std::filesystem::is_regular_file(options.db_path)) {
        std::cerr << "run_experiment: no database at '" << options.db_path
                  << "' to resume from (see --db)\n";
        return 2;
      }
      corrmp::ResultStore store(options.db_path);
      const auto sweep = corrmp::stored_sweep(store, resume);
      if (!sweep) {
        std::cerr << "run_experiment: no sweep '" << resume << "' in " << options.db_path << "\n";
        return 2;
      }
      corrmp::install_interrupt_handlers();
      sweep_options.executable = this_executable();
      corrmp::check_base_configs_unchanged(*sweep);
      corrmp::check_sweep_jobs(*sweep, registries);
      return corrmp::drive_sweep(*sweep, sweep_options);
    }
    if (config_path.empty()) {
      std::cerr << "run_experiment: a CONFIG file is required (see --help)\n";
      return 2;
    }
    if (multirun || corrmp::is_sweep_file(config_path) || !emit.empty() ||
        sweep_options.launcher != "local") {
      corrmp::Sweep sweep = corrmp::define_sweep(config_path, overrides);
      corrmp::check_sweep_jobs(sweep, registries);
      corrmp::fingerprint_base_configs(sweep);
      if (print_config) {
        std::cout << corrmp::manifest_yaml(sweep);
        return 0;
      }
      corrmp::install_interrupt_handlers();
      sweep_options.executable = this_executable();
      return corrmp::drive_sweep(sweep, sweep_options);
    }
    corrmp::Experiment experiment = load_single_run(config_path, overrides, registries);
    if (print_config) {
      std::cout << experiment.resolved_yaml;
      return 0;
    }
    corrmp::install_interrupt_handlers();
    limit_renderer_threads();
    const corrmp::RunResult result = corrmp::run_pipeline(experiment, options);
    if (result.status == corrmp::RunStatus::completed) {
      spdlog::info("run {} completed: {}", result.run_id, result.run_dir);
      return 0;
    }
    return result.status == corrmp::RunStatus::interrupted ? 130 : 1;
  } catch (const corrmp::ConfigError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  } catch (const corrmp::StoreError& e) {
    // A database that cannot be used (damaged, a directory, not SQLite) is bad input: it is
    // refused before a run is recorded, like a bad config.
    std::cerr << "run_experiment: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "run_experiment: " << e.what() << "\n";
    return 1;
  }
}
