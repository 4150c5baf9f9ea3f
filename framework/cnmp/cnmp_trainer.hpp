// CNMP training as in the public CNMP code (Seker et al., RSS 2019) and the
// paper's Section IV training parameters: per update, a batch of B
// demonstrations; n observations uniform in 1..max_observations and m targets
// uniform in 1..max_targets, drawn disjoint from one random permutation of the
// time steps; Adam on the Gaussian negative log-likelihood. Every
// validate_every updates the held-out demonstrations are predicted from their
// first point and context, and the best weights (lowest mean error) are kept.
// With final_learning_rate > 0 the learning rate follows a cosine schedule
//   lr(u) = lr_end + (lr_start - lr_end) (1 + cos(pi u / U)) / 2,
// which the scaled-down default protocol uses to converge in fewer updates.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <string>
#include <vector>

#include "cnmp/cnmp_model.hpp"
#include "core/config/field_rule.hpp"
#include "core/seeds.hpp"

namespace corrmp {

struct CnmpTrainingParams {
  int64_t updates = 20000;
  int batch_size = 1;
  int max_observations = 5;
  int max_targets = 1;
  double learning_rate = 1e-4;
  double final_learning_rate = 0.0;  // 0: constant learning rate (the paper)
  int validate_every = 1000;

  template <class Fields>
  void describe(Fields& f) {
    f("updates", updates, "Adam updates (the paper: 10M per model)", at_least(1));
    f("batch_size", batch_size, "demonstrations per update (1 is the original CNMP)",
      in_range(1, 1 << 20));
    f("max_observations", max_observations, "observations per update: uniform in 1..this",
      at_least(1));
    f("max_targets", max_targets, "targets per update: uniform in 1..this", at_least(1));
    f("learning_rate", learning_rate, "Adam learning rate (the paper: 1e-4)", positive());
    f("final_learning_rate", final_learning_rate,
      "when > 0, the learning rate follows a cosine from learning_rate down to this",
      at_least(0.0));
    f("validate_every", validate_every, "updates between validations", at_least(1));
  }
};

// One trajectory for training, in data units: x (T x d_x, column 0 time in
// [0, 1]), y (T x d_y), context (d_context values).
struct CnmpTrajectory {
  Eigen::MatrixXd x;
  Eigen::MatrixXd y;
  Eigen::VectorXd context;
};

// The error of a CNMP's predictions on trajectories: the Euclidean distance
// between predicted and true rows averaged over time, then its mean and max
// over the trajectories (data units).
struct PredictionError {
  double mean = 0.0;
  double max = 0.0;
};

// The observation a prediction is conditioned on: the trajectory's first point
// as one row (x then y).
Eigen::MatrixXd first_observation(const Eigen::MatrixXd& x, const Eigen::MatrixXd& y);

// One point of the training curve, at each validation: the mean loss (the
// Gaussian negative log-likelihood) over the updates since the previous point
// and the validation error then (NaN without validation data).
struct TrainingCurvePoint {
  int64_t update = 0;
  double loss = 0.0;
  double validation_mean = 0.0;
  double validation_max = 0.0;
};

struct TrainingReport {
  int64_t updates = 0;
  int64_t best_update = 0;
  double final_loss = 0.0;  // mean loss over the last validation interval
  PredictionError best_validation;
  double seconds = 0.0;
  int64_t team_updates = 0;  // updates run on two threads (cnmp/parallel_cnmp_step.hpp)
  std::vector<TrainingCurvePoint> curve;
};

// Error of predictions conditioned on each trajectory's first point and context,
// queried at all its time steps, against the trajectory (data units).
PredictionError prediction_error(CnmpModel& model, const std::vector<CnmpTrajectory>& data);

// The learning rate of update `update` (1-based): constant, or the cosine
// schedule when final_learning_rate > 0.
double scheduled_learning_rate(const CnmpTrainingParams& params, int64_t update);

// Fits the normalisers to `train` and trains the model. Without validation
// data the final weights are kept. `label` names the progress bar.
TrainingReport train_cnmp(CnmpModel& model, const std::vector<CnmpTrajectory>& train,
                          const std::vector<CnmpTrajectory>& validation,
                          const CnmpTrainingParams& params, Rng& rng, const std::string& label);

}  // namespace corrmp
