// train_cnmp: trains a CNMP on a researcher's own demonstrations (.npy or CSV),
// no simulation involved, and writes a model file for predict_cnmp.
// Paper, Section III-A; the training parameters of Section IV are the defaults.
#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <iostream>

#include "command_line.hpp"

#include "cnmp/cnmp_memory.hpp"
#include "cnmp/cnmp_trainer.hpp"
#include "cnmp/raw_trajectory.hpp"
#include "cnmp/trajectory_dataset.hpp"
#include "core/interrupt.hpp"
#include "core/logging.hpp"
#include "core/path_checks.hpp"

namespace {

constexpr const char* kExamples = R"(
Examples:
  train_cnmp --data demos.npy --y c1,c2,c3 --context c4 --out model.cnmp
  train_cnmp --data recordings/ --time t --y x,y,z --context corridor --updates 200000 \
             --batch 32 --lr 1e-3 --out corridor.cnmp
Columns of .npy files are called c0, c1, ...; CSV files name them in their header row.
Time is normalised to [0, 1] per demonstration (the step index when --time is not given).
)";

// The model must not overwrite a demonstration file (the same file under any spelling or link).
void refuse_an_input_as_output(const std::vector<std::string>& files, const std::string& out) {
  for (const auto& file : files) {
    if (corrmp::same_file(file, out)) {
      throw corrmp::DataError(fmt::format(
          "--out {}: is the demonstration file {} (--data): write the model to another file", out,
          file));
    }
  }
}

// Sizes whose training cannot fit in memory are refused naming the option to change, as
// run_experiment refuses them at load.
void refuse_what_cannot_fit(const corrmp::CnmpArchitecture& architecture,
                            const corrmp::CnmpTrainingParams& training,
                            const std::vector<corrmp::CnmpTrajectory>& trajectories) {
  int64_t longest = 0;
  for (const auto& t : trajectories) longest = std::max<int64_t>(longest, t.x.rows());
  const auto needs = corrmp::cnmp_training_needs(architecture, training, longest);
  const corrmp::MemoryBudget budget = corrmp::usable_memory();
  if (const auto largest = corrmp::largest_need_beyond(needs, budget)) {
    const std::string option =
        needs[*largest].key == std::string(corrmp::kNetworkKey) ? "--width" : "--batch";
    throw corrmp::DataError(option + ": " + corrmp::memory_refusal(needs, *largest, budget));
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Trains a CNMP on demonstration files.", "train_cnmp"};
  std::vector<std::string> data;
  corrmp::TrajectoryColumns columns;
  corrmp::CnmpArchitecture architecture;
  corrmp::CnmpTrainingParams training;
  double validation_fraction = 0.2;
  uint64_t seed = 0;
  std::string out;
  bool quiet = false;
  app.add_option("--data", data, ".npy files, .csv files or directories of them")->required();
  app.add_option("--time", columns.time, "time column (default: the step index)");
  app.add_option("--x", columns.inputs, "task-parameter columns appended to time")->delimiter(',');
  app.add_option("--y", columns.outputs, "output columns")->delimiter(',')->required();
  app.add_option("--context", columns.context, "context columns")->delimiter(',');
  app.add_option("--updates", training.updates, "Adam updates")
      ->capture_default_str()
      ->check(corrmp::positive_number());
  app.add_option("--batch", training.batch_size, "demonstrations per update")
      ->capture_default_str()
      ->check(corrmp::positive_number());
  app.add_option("--max-observations", training.max_observations, "observations per update")
      ->capture_default_str()
      ->check(corrmp::positive_number());
  app.add_option("--max-targets", training.max_targets, "targets per update")
      ->capture_default_str()
      ->check(corrmp::positive_number());
  app.add_option("--lr", training.learning_rate, "Adam learning rate")
      ->capture_default_str()
      ->check(corrmp::positive_number());
  app.add_option("--validate-every", training.validate_every, "updates between validations")
      ->capture_default_str()
      ->check(corrmp::positive_number());
  app.add_option("--width", architecture.width, "hidden width")
      ->capture_default_str()
      ->check(CLI::Range(1, 4096));
  app.add_option("--encoder-layers", architecture.encoder_layers, "encoder layers")
      ->capture_default_str()
      ->check(CLI::Range(1, 16));
  app.add_option("--decoder-layers", architecture.decoder_layers, "decoder layers")
      ->capture_default_str()
      ->check(CLI::Range(1, 16));
  app.add_option("--min-std", architecture.min_std, "std floor (normalised units)")
      ->capture_default_str()
      ->check(corrmp::positive_number());
  app.add_option("--validation-fraction", validation_fraction, "share held out")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 0.9));
  app.add_option("--seed", seed, "seed of initialisation, split and sampling")
      ->capture_default_str();
  app.add_option("--out", out, "model file to write")->required();
  app.add_flag("-q,--quiet", quiet, "only warnings and errors");
  app.footer(kExamples);
  if (const auto exit_code = corrmp::parse_command_line(app, argc, argv)) return *exit_code;
  corrmp::setup_logging(quiet);
  corrmp::install_interrupt_handlers();
  try {
    corrmp::check_column_roles(columns, {"--time", "--x", "--y", "--context"});
    const std::vector<std::string> files = corrmp::list_trajectory_files(data);
    refuse_an_input_as_output(files, out);
    auto trajectories = corrmp::select_columns(corrmp::read_trajectory_files(files), columns);
    corrmp::Rng rng = corrmp::SeedTree(seed).stream("train_cnmp");
    for (size_t i = trajectories.size(); i > 1; --i) {
      std::swap(trajectories[i - 1], trajectories[rng.uniform_int(0, i - 1)]);
    }
    const auto held_out = static_cast<size_t>(validation_fraction * trajectories.size());
    const std::vector<corrmp::CnmpTrajectory> validation(trajectories.begin(),
                                                         trajectories.begin() + held_out);
    const std::vector<corrmp::CnmpTrajectory> train(trajectories.begin() + held_out,
                                                    trajectories.end());
    if (train.empty()) throw std::runtime_error("no demonstrations left for training");
    architecture.d_x = static_cast<int>(train.front().x.cols());
    architecture.d_y = static_cast<int>(train.front().y.cols());
    architecture.d_context = static_cast<int>(train.front().context.size());
    refuse_what_cannot_fit(architecture, training, trajectories);
    corrmp::CnmpModel model(architecture, corrmp::SeedTree(seed).seed_for("init"));
    spdlog::info("{} training and {} validation demonstrations; CNMP with {} parameters",
                 train.size(), validation.size(), model.network().parameter_count());
    const corrmp::TrainingReport report =
        corrmp::train_cnmp(model, train, validation, training, rng, "train_cnmp");
    model.save(out);
    if (validation.empty()) {
      spdlog::info("wrote {} (final loss {:.4g}; no validation data)", out, report.final_loss);
    } else {
      spdlog::info("wrote {}: best validation error {:.4g} (max {:.4g}) at update {}", out,
                   report.best_validation.mean, report.best_validation.max, report.best_update);
    }
    return 0;
  } catch (const corrmp::Interrupted& e) {
    std::cerr << "train_cnmp: " << e.what() << "\n";
    return 130;
  } catch (const corrmp::DataError& e) {  // bad input, like a bad option
    std::cerr << "train_cnmp: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "train_cnmp: " << e.what() << "\n";
    return 1;
  }
}
