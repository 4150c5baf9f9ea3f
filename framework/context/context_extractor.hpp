// A context extractor reads a segment's context vector from what the robot
// observes at the segment's start (paper, Section III: perfect state, an
// autoencoder latent of a camera image, or the colour-segmented rope end).
// The CNMP normalises contexts with training statistics (cnmp/normaliser.hpp).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/memory_need.hpp"
#include "core/metric.hpp"
#include "core/seeds.hpp"
#include "data/demonstrations.hpp"
#include "data/observation.hpp"

namespace corrmp {

// Where an extractor may cache what it learns: a directory and a key naming
// the data it learns from (the demonstrations' cache key). Without `reuse`
// (run_experiment --no-cache) it learns afresh whatever the cache holds, and
// what it learns replaces the cached entry.
struct ExtractorCache {
  std::string directory;
  std::string data_key;
  bool reuse = true;
};

class ContextExtractor {
 public:
  virtual ~ContextExtractor() = default;
  // Learns from demonstrations (the autoencoder trains here; it uses only their
  // images, no labels, so the pipeline passes the training and validation
  // demonstrations, never evaluation trials).
  virtual void fit(const std::vector<Demonstration>& demos, const ExtractorCache& cache,
                   Rng& rng) = 0;
  // The context of `segment`; empty for segments that have none (the evaluation asks only for
  // those segments() lists, one call at a time, in trial order:
  // evaluation/environment_evaluation.hpp).
  virtual Eigen::VectorXd extract(const std::string& segment, const Observation& observation) = 0;
  // The segments it gives a context for.
  virtual std::vector<std::string> segments() const = 0;
  // The observation state values it reads (checked at load against what the
  // environment observes).
  virtual std::vector<std::string> state_names() const { return {}; }
  // The memory fitting will take with the declared sizes (checked at load).
  virtual std::vector<MemoryNeed> memory_needs() const { return {}; }
  // Whether observations must include camera images.
  virtual bool needs_images() const = 0;
  // Writes what a researcher looks at (figures, models) into the run directory.
  virtual void write_outputs(const std::string&, const std::vector<Demonstration>&) {}
  // Called once before the evaluation's trials: later extractions are of
  // scenarios never seen in training.
  virtual void start_evaluation() {}
  // Measurements, each declared (core/metric.hpp), recorded as run metrics after the evaluation.
  virtual std::vector<Metric> metrics() const { return {}; }
};

// Sets every segment's context of every demonstration from its start observation.
void assign_contexts(ContextExtractor& extractor, std::vector<Demonstration>& demos);

}  // namespace corrmp
