// A context extractor reads a segment's context vector from what the robot
// observes at the segment's start (paper, Section III: perfect state, an
// autoencoder latent of a camera image, or the colour-segmented rope end).
// The CNMP normalises contexts with training statistics (cnmp/normaliser.hpp).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/seeds.hpp"
#include "envs/demonstrations.hpp"
#include "envs/observation.hpp"

namespace corrmp {

class ContextExtractor {
 public:
  virtual ~ContextExtractor() = default;
  // Learns from the training demonstrations (the autoencoder trains here).
  virtual void fit(const std::vector<Demonstration>& train, Rng& rng) = 0;
  // The context of `segment`; empty for segments that have none.
  virtual Eigen::VectorXd extract(const std::string& segment, const Observation& observation) = 0;
  // Whether observations must include camera images.
  virtual bool needs_images() const = 0;
  // Writes what a researcher looks at (figures, models) into the run directory.
  virtual void write_outputs(const std::string&, const std::vector<Demonstration>&) {}
};

// Sets every segment's context of every demonstration from its start observation.
void assign_contexts(ContextExtractor& extractor, std::vector<Demonstration>& demos);

}  // namespace corrmp
