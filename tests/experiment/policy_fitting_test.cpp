// Tests of the training stage: the networks without context train beside the extractor, give
// the models of one fit of all, are reported in the policy's order, and are abandoned when the
// extractor fails.
#include "experiment/policy_fitting.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "core/thread_budget.hpp"
#include "policies/segmented_cnmp.hpp"

namespace corrmp {
namespace {

using ::testing::StrEq;
using ::testing::ThrowsMessage;

// Segments a and b; b's context is its phase, which only the extractor sets.
DemonstrationSplit demonstrations() {
  Rng rng(3);
  DemonstrationSplit split;
  for (int d = 0; d < 10; ++d) {
    Demonstration demo;
    for (const char* name : {"a", "b"}) {
      SegmentTrajectory s;
      s.segment = name;
      s.x = Eigen::VectorXd::LinSpaced(10, 0.0, 1.0);
      s.y = (2.0 * s.x.array() + rng.uniform(-1.0, 1.0)).sin().matrix();
      s.start.state["phase"] = rng.uniform(-1.0, 1.0);
      demo.segments.push_back(s);
    }
    (d < 8 ? split.train : split.validation).push_back(demo);
  }
  return split;
}

// Reads the phase for b; `fail` makes its fit throw.
class PhaseExtractor : public ContextExtractor {
 public:
  explicit PhaseExtractor(bool fail) : fail_(fail) {}
  void fit(const std::vector<Demonstration>&, const ExtractorCache&, Rng&) override {
    if (fail_) throw std::runtime_error("no rope end in image 3");
  }
  Eigen::VectorXd extract(const std::string& segment, const Observation& observation) override {
    if (segment != "b") return {};
    return Eigen::VectorXd::Constant(1, observation.value("phase"));
  }
  std::vector<std::string> segments() const override { return {"b"}; }
  bool needs_images() const override { return false; }

 private:
  bool fail_;
};

SegmentedCnmpParams params(int64_t updates) {
  SegmentedCnmpParams p;
  p.segments = {{"b", true}, {"a", false}};  // a context network listed first
  p.network.encoder_layers = 2;
  p.network.decoder_layers = 2;
  p.network.width = 8;
  p.training.updates = updates;
  p.training.validate_every = updates;
  return p;
}

PolicyFitting fitting() { return {Rng(5), Rng(6), {}, ""}; }

Eigen::MatrixXd mean_of(SegmentedCnmp& policy, const std::string& segment) {
  Eigen::MatrixXd observation(1, 2);
  observation << 0.0, 0.3;
  return policy
      .generate(segment, observation, Eigen::VectorXd::Constant(1, 0.2),
                Eigen::VectorXd::LinSpaced(5, 0.0, 1.0))
      .mean;
}

TEST(PolicyFitting, BesideTheExtractorTheModelsAreThoseOfOneThread) {
  const int saved = thread_budget();
  std::vector<Eigen::MatrixXd> means;
  for (int budget : {1, 2}) {
    set_thread_budget(budget);
    SegmentedCnmp policy(params(600), 7);
    PhaseExtractor extractor(false);
    DemonstrationSplit demos = demonstrations();
    const auto summaries = fit_extractor_and_policy(policy, &extractor, demos, fitting());
    ASSERT_EQ(summaries.size(), 2u);
    EXPECT_EQ(summaries[0].segment, "b");  // the policy's order
    EXPECT_EQ(summaries[1].segment, "a");
    EXPECT_EQ(demos.train[0].find("b")->context.size(), 1);
    means.push_back(mean_of(policy, "a"));
    means.push_back(mean_of(policy, "b"));
  }
  set_thread_budget(saved);
  EXPECT_EQ(means[0], means[2]);
  EXPECT_EQ(means[1], means[3]);
}

TEST(PolicyFitting, AFailingExtractorStopsTheNetworksTrainingBesideIt) {
  const int saved = thread_budget();
  set_thread_budget(2);
  // Minutes of training unless the failure stops it at its next check.
  SegmentedCnmp policy(params(50'000'000), 7);
  PhaseExtractor extractor(true);
  DemonstrationSplit demos = demonstrations();
  EXPECT_THAT([&] { fit_extractor_and_policy(policy, &extractor, demos, fitting()); },
              ThrowsMessage<std::runtime_error>(StrEq("no rope end in image 3")));
  set_thread_budget(saved);
  // Abandoned, not finished: no model for a.
  EXPECT_THROW(mean_of(policy, "a"), std::runtime_error);
}

}  // namespace
}  // namespace corrmp
