// A policy learned from demonstrations: it generates each segment's trajectory
// from the state at the segment's start and the segment's context (paper,
// Section III: pre-MP, cor-MP and post-MP, or one monolithic primitive).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "cnmp/cnmp_model.hpp"
#include "cnmp/cnmp_trainer.hpp"
#include "core/memory_need.hpp"
#include "core/seeds.hpp"
#include "data/demonstrations.hpp"

namespace corrmp {

struct PolicyTrainingSummary {
  std::string segment;
  TrainingReport report;
  int64_t parameters = 0;
};

// Which of a policy's networks a fit() call trains. The pipeline trains the
// networks that read no context while the context extractor fits, then the
// others (docs/architecture.md, "Caches and determinism"); `all` trains every one.
enum class Networks { all, without_context, with_context };

class Policy {
 public:
  virtual ~Policy() = default;

  // Learns the `which` networks from the training demonstrations, choosing
  // checkpoints on the validation demonstrations; networks it does not train
  // stay as they were. Every network's training depends only on `rng`'s state
  // and the data, so fitting the two halves (both from the same `rng`) gives
  // the models one fit of all gives. The two halves may be fitted at the same
  // time on two threads.
  virtual std::vector<PolicyTrainingSummary> fit(const std::vector<Demonstration>& train,
                                                 const std::vector<Demonstration>& validation,
                                                 Rng rng, Networks which = Networks::all) = 0;

  // The segments this policy generates, in execution order.
  virtual std::vector<std::string> segments() const = 0;
  // The demonstrations' segments it learns from (checked at load against what
  // the demonstration source provides).
  virtual std::vector<std::string> data_segments() const { return segments(); }
  // The segments it conditions on a context (each needs one at load).
  virtual std::vector<std::string> context_segments() const = 0;

  // The trajectory of `segment` conditioned on `observations` (rows x then y,
  // typically the segment's start point) and `context`, at query inputs `query_x`.
  virtual CnmpPrediction generate(const std::string& segment, const Eigen::MatrixXd& observations,
                                  const Eigen::VectorXd& context,
                                  const Eigen::MatrixXd& query_x) = 0;

  // The memory training will take with the declared sizes (checked at load);
  // `longest` is the demonstrations' longest trajectory when known, else 0.
  virtual std::vector<MemoryNeed> memory_needs(int64_t longest) const {
    (void)longest;
    return {};
  }

  // Writes the trained networks as model files into `directory`.
  virtual void save(const std::string& directory) = 0;
};

}  // namespace corrmp
