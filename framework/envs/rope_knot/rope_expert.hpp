// Demonstrator `rope_expert`: emulates the human teleoperating the two
// grippers in the paper's knotting experiment (Section IV-C). Every
// demonstration shows pre-MP (loop the rope over the bar, present the free
// end), the correction at the critical point and post-MP (enclose, pull
// through, tighten, release); the paper's 28 correction demonstrations are
// posterior-to-anterior, anterior-to-posterior, lateral and combinations,
// plus a few without correction (here: a share of unperturbed scenarios). The
// correction moves the left gripper's finger mid-point onto the rope end, as
// the human sees it. Each demonstration also holds the whole skill as one
// recording ("full", absolute rows) for the monolithic baseline. Only
// demonstrations that tie the knot are kept.
#pragma once

#include <string>
#include <vector>

#include "core/config/field_rule.hpp"
#include "envs/demonstration_source.hpp"
#include "envs/expert_memory.hpp"
#include "envs/rope_knot/rope_knot.hpp"

namespace corrmp {

struct RopeExpertParams {
  int train = 28;
  int validation = 6;
  bool images = true;
  double no_correction_share = 0.15;
  int max_attempts_factor = 3;

  template <class Fields>
  void describe(Fields& f) {
    f("train", train, "training demonstrations (the paper: 28 corrections)", in_range(1, 100000));
    f("validation", validation, "validation demonstrations", in_range(0, 100000));
    f("images", images, "capture head-camera RGB-D images at the segment starts");
    f("no_correction_share", no_correction_share,
      "share of demonstrations of the unperturbed scenario (no correction needed)",
      in_range(0.0, 1.0));
    f("max_attempts_factor", max_attempts_factor,
      "scenarios tried per wanted demonstration before giving up (failed ones are dropped)",
      in_range(1, 1000));
  }
};

class RopeExpert : public DemonstrationSource {
 public:
  explicit RopeExpert(const RopeExpertParams& params) : params_(params) {}

  DemonstrationSplit collect(Environment* environment, Rng& rng) override;
  std::vector<std::string> segments() const override { return {"pre", "cor", "post", "full"}; }
  bool needs_environment() const override { return true; }
  std::string environment_type() const override { return "rope_knot"; }
  bool records_images() const override { return params_.images; }
  bool can_demonstrate() const override { return true; }
  std::vector<MemoryNeed> memory_needs(const Environment* environment) const override {
    return expert_memory_needs(environment,
                               {params_.train + params_.validation, params_.images ? 3 : 0});
  }
  int64_t longest_trajectory(const Environment* environment) const override {
    return expert_longest_trajectory(environment);
  }
  Demonstration demonstrate(Environment& environment, const Scenario& scenario,
                            bool with_images) override;
  // 2: every attempt draws from its own stream (parallel collection).
  std::string version() const override { return "2"; }

 private:
  RopeExpertParams params_;
};

}  // namespace corrmp
