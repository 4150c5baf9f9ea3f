// The paper's method (Section III): one CNMP per segment of the skill, each
// conditioned on the segment's start point and, where the config says so, on
// the segment's context vector. The segments are data: a config lists them.
// The segment networks are independent and train concurrently, each on its own
// random stream, so the trained networks do not depend on the thread budget.
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "cnmp/cnmp_architecture.hpp"
#include "cnmp/cnmp_trainer.hpp"
#include "policies/policy.hpp"

namespace corrmp {

struct SegmentSpec {
  std::string name;
  bool use_context = true;

  template <class Fields>
  void describe(Fields& f) {
    f("name", name, "segment name as the demonstrations call it (pre, cor, post, full, ...)",
      required());
    f("use_context", use_context, "condition this segment's CNMP on the segment's context");
  }
};

struct SegmentedCnmpParams {
  std::vector<SegmentSpec> segments{SegmentSpec{"full", true}};
  CnmpArchitecture network;
  CnmpTrainingParams training;

  template <class Fields>
  void describe(Fields& f) {
    f("segments", segments, "the segments, in execution order, each with its own CNMP");
    f("network", network, "CNMP sizes (the paper: encoder 3, decoder 4 layers of width 128)");
    f("training", training, "CNMP training");
  }
};

class SegmentedCnmp : public Policy {
 public:
  SegmentedCnmp(const SegmentedCnmpParams& params, uint64_t seed);

  std::vector<PolicyTrainingSummary> fit(const std::vector<Demonstration>& train,
                                         const std::vector<Demonstration>& validation, Rng rng,
                                         Networks which = Networks::all) override;
  std::vector<std::string> segments() const override;
  std::vector<std::string> context_segments() const override;
  CnmpPrediction generate(const std::string& segment, const Eigen::MatrixXd& observations,
                          const Eigen::VectorXd& context, const Eigen::MatrixXd& query_x) override;
  std::vector<MemoryNeed> memory_needs(int64_t longest) const override;
  void save(const std::string& directory) override;

 private:
  SegmentedCnmpParams params_;
  uint64_t seed_;
  std::mutex models_mutex_;  // two fits of disjoint networks may finish at the same time
  std::map<std::string, std::unique_ptr<CnmpModel>> models_;
};

// The trajectories of one segment of every demonstration, in CNMP form;
// without `use_context` the context is left empty. Throws naming the
// demonstration when one lacks the segment.
std::vector<CnmpTrajectory> segment_trajectories(const std::vector<Demonstration>& demos,
                                                 const std::string& segment, bool use_context);

}  // namespace corrmp
