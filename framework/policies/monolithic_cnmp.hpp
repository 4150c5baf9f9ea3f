// The baseline of the paper's Section IV-B: one CNMP for the whole trajectory
// (the demonstrations' "full" segment), given the context seen at the start
// (the paper gives it the corridor location) and executed open loop, with a width chosen so that
// its parameter count matches the sum of the segment networks it replaces.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "cnmp/cnmp_architecture.hpp"
#include "cnmp/cnmp_trainer.hpp"
#include "policies/policy.hpp"

namespace corrmp {

struct MonolithicCnmpParams {
  std::string segment = "full";
  std::vector<std::string> matched_segments{"pre", "cor", "post"};
  std::vector<std::string> matched_without_context{"pre"};
  CnmpArchitecture network;
  CnmpTrainingParams training;

  template <class Fields>
  void describe(Fields& f) {
    f("segment", segment, "the demonstrations' whole-trajectory segment");
    f("matched_segments", matched_segments,
      "segment networks whose summed parameter count the width is chosen to match "
      "(empty: keep network.width)");
    f("matched_without_context", matched_without_context,
      "matched segments whose network has no context input");
    f("network", network, "CNMP sizes (the width is replaced by the matched one)");
    f("training", training, "CNMP training");
  }
};

class MonolithicCnmp : public Policy {
 public:
  MonolithicCnmp(const MonolithicCnmpParams& params, uint64_t seed);

  std::vector<PolicyTrainingSummary> fit(const std::vector<Demonstration>& train,
                                         const std::vector<Demonstration>& validation, Rng rng,
                                         Networks which = Networks::all) override;
  std::vector<std::string> segments() const override { return {params_.segment}; }
  std::vector<std::string> data_segments() const override;
  std::vector<std::string> context_segments() const override { return {params_.segment}; }
  CnmpPrediction generate(const std::string& segment, const Eigen::MatrixXd& observations,
                          const Eigen::VectorXd& context, const Eigen::MatrixXd& query_x) override;
  std::vector<MemoryNeed> memory_needs(int64_t longest) const override;
  void save(const std::string& directory) override;

 private:
  MonolithicCnmpParams params_;
  uint64_t seed_;
  std::unique_ptr<CnmpModel> model_;
};

}  // namespace corrmp
