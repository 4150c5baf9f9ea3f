// run_experiment CONFIG [key.path=value ...] [options]: loads and validates an
// experiment config, then runs the pipeline and records it in the result store.
// Exit codes: 0 success; 2 usage or config error (nothing written to the
// database); 1 runtime failure (the run is marked failed with its reason);
// 130 interrupted. docs/architecture.md, "Command line".
#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include <iostream>

#include "command_line.hpp"

#include "core/config/config_error.hpp"
#include "core/interrupt.hpp"
#include "core/logging.hpp"
#include "experiment/experiment.hpp"
#include "experiment/pipeline.hpp"
#include "experiment/registries.hpp"
#include "store/result_store.hpp"

namespace {

constexpr const char* kExamples = R"(
Examples:
  run_experiment configs/curves_demo.yaml
  run_experiment configs/curves_demo.yaml seed=7 demonstrations.train=50
  run_experiment configs/curves_demo.yaml --print-config
  run_experiment --list
  run_experiment configs/curves_demo.yaml --db /tmp/sweep.sqlite --out /tmp/runs --quiet
)";

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
  app.footer(kExamples);
  if (const auto exit_code = corrmp::parse_command_line(app, argc, argv)) return *exit_code;

  corrmp::setup_logging(quiet);
  options.use_cache = !no_cache;
  try {
    const corrmp::Registries registries = corrmp::builtin_registries();
    if (list) {
      std::cout << corrmp::describe_registries(registries);
      return 0;
    }
    if (config_path.empty()) {
      std::cerr << "run_experiment: a CONFIG file is required (see --help)\n";
      return 2;
    }
    corrmp::Experiment experiment = corrmp::load_experiment(config_path, overrides, registries);
    if (print_config) {
      std::cout << experiment.resolved_yaml;
      return 0;
    }
    corrmp::install_interrupt_handlers();
    const corrmp::RunResult result = corrmp::run_pipeline(experiment, options);
    if (result.status == "completed") {
      spdlog::info("run {} completed: {}", result.run_id, result.run_dir);
      return 0;
    }
    return result.status == "interrupted" ? 130 : 1;
  } catch (const corrmp::ConfigError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  } catch (const corrmp::StoreError& e) {
    std::cerr << "run_experiment: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "run_experiment: " << e.what() << "\n";
    return 1;
  }
}
