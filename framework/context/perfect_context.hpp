// Context extractor `perfect` (paper, Section IV-B "perfect context"): named
// state values read straight from the simulator, e.g. in the corridor task
// cor-MP gets the corridor's x position and post-MP the object's x position.
#pragma once

#include <string>
#include <vector>

#include "context/context_extractor.hpp"
#include "core/config/field_rule.hpp"

namespace corrmp {

struct SegmentContextSpec {
  std::string segment;
  std::vector<std::string> state;

  template <class Fields>
  void describe(Fields& f) {
    f("segment", segment, "segment name", required());
    f("state", state, "observation state values forming the context, in order", required());
  }
};

struct PerfectContextParams {
  std::vector<SegmentContextSpec> segments;

  template <class Fields>
  void describe(Fields& f) {
    f("segments", segments,
      "which state values form each segment's context, e.g. [{segment: cor, state: [x]}]",
      required());
  }
};

class PerfectContext : public ContextExtractor {
 public:
  explicit PerfectContext(const PerfectContextParams& params) : params_(params) {}
  void fit(const std::vector<Demonstration>&, const ExtractorCache&, Rng&) override {}
  Eigen::VectorXd extract(const std::string& segment, const Observation& observation) override;
  std::vector<std::string> segments() const override;
  std::vector<std::string> state_names() const override;
  bool needs_images() const override { return false; }

 private:
  PerfectContextParams params_;
};

}  // namespace corrmp
