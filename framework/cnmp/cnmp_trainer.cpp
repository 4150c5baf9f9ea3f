// CNMP training loop: sampler, Adam updates, validation and best checkpoint.
#include "cnmp/cnmp_trainer.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <numeric>
#include <stdexcept>

#include "cnmp/parallel_cnmp_step.hpp"
#include "core/interrupt.hpp"
#include "core/progress.hpp"
#include "core/thread_budget.hpp"
#include "nn/gemm.hpp"

namespace corrmp {

namespace {

// The Euclidean distance between the rows of a prediction and its trajectory, averaged over time.
double mean_row_distance(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).rowwise().norm().mean();
}

// The mean and max of the trajectories' errors, summed in trajectory order.
PredictionError summarise(const std::vector<double>& errors) {
  double sum = 0.0, max = 0.0;
  for (double error : errors) {
    sum += error;
    max = std::max(max, error);
  }
  return {errors.empty() ? 0.0 : sum / static_cast<double>(errors.size()), max};
}

std::vector<NormalisedTrajectory> normalise(const CnmpModel& model,
                                            const std::vector<CnmpTrajectory>& data) {
  std::vector<NormalisedTrajectory> out;
  for (const auto& t : data) {
    Eigen::MatrixXd xy(t.x.rows(), t.x.cols() + t.y.cols());
    xy << t.x, model.y_normaliser.apply(t.y);
    out.push_back(
        {xy.cast<float>(), model.context_normaliser.apply(t.context.transpose()).cast<float>()});
  }
  return out;
}

void check_shapes(const CnmpArchitecture& a, const std::vector<CnmpTrajectory>& data,
                  const char* which) {
  for (size_t i = 0; i < data.size(); ++i) {
    const auto& t = data[i];
    if (t.x.cols() != a.d_x || t.y.cols() != a.d_y || t.context.size() != a.d_context ||
        t.x.rows() != t.y.rows() || t.x.rows() < 2) {
      throw std::invalid_argument(fmt::format(
          "{} trajectory {}: expected x with {} columns, y with {}, context of {} and at least 2 "
          "time steps; got x {}x{}, y {}x{}, context {}",
          which, i, a.d_x, a.d_y, a.d_context, t.x.rows(), t.x.cols(), t.y.rows(), t.y.cols(),
          t.context.size()));
    }
  }
}

std::vector<Eigen::VectorXf> snapshot(const std::vector<nn::Parameter<float>>& params) {
  std::vector<Eigen::VectorXf> values;
  for (const auto& p : params) values.push_back(p.values());
  return values;
}

void restore(const std::vector<nn::Parameter<float>>& params,
             const std::vector<Eigen::VectorXf>& values) {
  for (size_t i = 0; i < params.size(); ++i) params[i].values() = values[i];
}

Eigen::MatrixXd stack_rows(const std::vector<CnmpTrajectory>& data, bool context) {
  Eigen::Index rows = 0;
  for (const auto& t : data) rows += context ? 1 : t.y.rows();
  const Eigen::Index cols = context ? data.front().context.size() : data.front().y.cols();
  Eigen::MatrixXd out(rows, cols);
  Eigen::Index row = 0;
  for (const auto& t : data) {
    if (context) {
      out.row(row++) = t.context.transpose();
    } else {
      out.middleRows(row, t.y.rows()) = t.y;
      row += t.y.rows();
    }
  }
  return out;
}

// prediction_error on the threads the training's updates use: the trajectories are shared among
// two workers, the second predicting with `copy` (made on first use, then given the model's
// current weights). Each error is computed from the same weights by the same code whichever
// worker has it, and they are added up in trajectory order, so the result is prediction_error's.
PredictionError validation_error(CnmpModel& model, std::unique_ptr<CnmpModel>& copy,
                                 const std::vector<CnmpTrajectory>& data, int workers) {
  if (workers < 2) return prediction_error(model, data);
  if (!copy) copy = std::make_unique<CnmpModel>(model);
  const auto source = model.network().parameters(), target = copy->network().parameters();
  for (size_t k = 0; k < source.size(); ++k) target[k].values() = source[k].values();
  std::vector<double> errors(data.size());
  parallel_for_with_workers(static_cast<int>(data.size()), 2, [&](int index, int worker) {
    CnmpModel& predictor = worker == 0 ? model : *copy;
    const CnmpTrajectory& t = data[static_cast<size_t>(index)];
    const CnmpPrediction prediction =
        predictor.predict(first_observation(t.x, t.y), t.context, t.x);
    errors[static_cast<size_t>(index)] = mean_row_distance(prediction.mean, t.y);
  });
  return summarise(errors);
}

// The size from which a network's updates run on two workers (see train_cnmp).
constexpr int64_t kTeamParameters = 150000;

}  // namespace

double scheduled_learning_rate(const CnmpTrainingParams& params, int64_t update) {
  if (params.final_learning_rate <= 0.0) return params.learning_rate;
  const double progress = static_cast<double>(update - 1) / params.updates;
  return params.final_learning_rate + (params.learning_rate - params.final_learning_rate) *
                                          (1.0 + std::cos(M_PI * progress)) / 2.0;
}

Eigen::MatrixXd first_observation(const Eigen::MatrixXd& x, const Eigen::MatrixXd& y) {
  Eigen::MatrixXd first(1, x.cols() + y.cols());
  first << x.row(0), y.row(0);
  return first;
}

PredictionError prediction_error(CnmpModel& model, const std::vector<CnmpTrajectory>& data) {
  std::vector<double> errors;
  for (const auto& t : data) {
    const CnmpPrediction prediction = model.predict(first_observation(t.x, t.y), t.context, t.x);
    errors.push_back(mean_row_distance(prediction.mean, t.y));
  }
  return summarise(errors);
}

TrainingReport train_cnmp(CnmpModel& model, const std::vector<CnmpTrajectory>& train,
                          const std::vector<CnmpTrajectory>& validation,
                          const CnmpTrainingParams& params, Rng& rng, const std::string& label) {
  if (train.empty()) throw std::invalid_argument(label + ": no training trajectories");
  const CnmpArchitecture& a = model.architecture();
  check_shapes(a, train, "training");
  check_shapes(a, validation, "validation");
  model.y_normaliser = Normaliser::fit(stack_rows(train, false));
  model.context_normaliser =
      a.d_context > 0 ? Normaliser::fit(stack_rows(train, true)) : Normaliser::identity(0);
  const auto data = normalise(model, train);
  BatchSampler sampler(data, a, params);
  const auto parameters = model.network().parameters();
  // Two workers at most. A wide network such as the monolithic baselines' has its own second
  // core when the budget gives one: the layers are shared column by column with a barrier after
  // each, which gains most on wide layers (docs/performance.md, "Measurements behind the code").
  // Any other network borrows the core of a thread that waits for others' work (the last segment
  // network of a loop, or the one trained beside the context extractor); the team then runs where
  // it is the faster.
  const bool splittable = nn::gemm_float_split_exact() && thread_budget() >= 2;
  const bool own = model.network().parameter_count() >= kTeamParameters && parallel_workers(2) == 2;
  ParallelCnmpStep updater(model.network(), params.learning_rate, splittable ? 2 : 1,
                           own ? TeamCores::own : TeamCores::borrowed);
  std::unique_ptr<CnmpModel> validator;  // predicts beside the model when there are two workers

  TrainingReport report;
  std::vector<Eigen::VectorXf> best;
  double best_error = std::numeric_limits<double>::infinity();
  double loss_sum = 0.0;
  int64_t loss_count = 0;
  const auto start = std::chrono::steady_clock::now();
  Progress progress(label, params.updates);
  std::string status;
  for (int64_t update = 1; update <= params.updates; ++update) {
    if ((update - 1) % 100 == 0) {
      updater.set_learning_rate(scheduled_learning_rate(params, update));
    }
    if (update % 1000 == 0) check_interrupt();  // validations may be far apart
    sampler.draw(rng);
    const float loss = updater.step(sampler);
    if (!std::isfinite(loss)) {
      throw std::runtime_error(
          fmt::format("{}: the training loss became {} at update {}", label, loss, update));
    }
    loss_sum += loss;
    ++loss_count;
    if (update % params.validate_every == 0 || update == params.updates) {
      check_interrupt();
      report.final_loss = loss_sum / loss_count;
      loss_sum = 0.0;
      loss_count = 0;
      status = fmt::format("loss {:.3f}", report.final_loss);
      TrainingCurvePoint point{update, report.final_loss, std::nan(""), std::nan("")};
      if (!validation.empty()) {
        const PredictionError error =
            validation_error(model, validator, validation, own ? updater.workers() : 1);
        point.validation_mean = error.mean;
        point.validation_max = error.max;
        status += fmt::format(", validation error {:.4g} (max {:.4g})", error.mean, error.max);
        if (error.mean < best_error) {
          best_error = error.mean;
          best = snapshot(parameters);
          report.best_validation = error;
          report.best_update = update;
        }
      }
      report.curve.push_back(point);
    }
    progress.advance(1, status);
  }
  if (!best.empty()) restore(parameters, best);
  report.updates = params.updates;
  report.team_updates = updater.team_updates();
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress.finish(status);
  return report;
}

}  // namespace corrmp
