// Demonstrator `via_point_expert`: the teacher of the via-point reach. pre-MP
// goes straight along the x axis to the critical point; there the expert sees
// the via point and bends through it (cor-MP: above, straight or below, as
// ViaPoint::decision_of names the bend); post-MP goes straight on to the goal.
// Each demonstration records every segment's x, y and the observation at its
// start, the decision, and the whole skill as one recording at constant speed
// (the monolithic baseline's data), in which the critical points fall where
// the path's length puts them.
#pragma once

#include <string>
#include <vector>

#include "core/config/field_rule.hpp"
#include "envs/demonstration_source.hpp"
#include "envs/expert_memory.hpp"
#include "envs/via_point/via_point.hpp"

namespace corrmp {

struct ViaPointExpertParams {
  int train = 40;
  int validation = 10;

  template <class Fields>
  void describe(Fields& f) {
    f("train", train, "training demonstrations", in_range(1, 100000));
    f("validation", validation, "validation demonstrations", in_range(0, 100000));
  }
};

class ViaPointExpert : public DemonstrationSource {
 public:
  explicit ViaPointExpert(const ViaPointExpertParams& params) : params_(params) {}

  DemonstrationSplit collect(Environment* environment, Rng& rng) override;
  std::vector<std::string> segments() const override { return {"pre", "cor", "post", "full"}; }
  bool needs_environment() const override { return true; }
  std::string environment_type() const override { return "via_point"; }
  bool can_demonstrate() const override { return true; }
  Demonstration demonstrate(Environment& environment, const Scenario& scenario,
                            bool with_images) override;
  std::vector<MemoryNeed> memory_needs(const Environment* environment) const override {
    return expert_memory_needs(environment, {params_.train + params_.validation, 0});
  }
  int64_t longest_trajectory(const Environment* environment) const override {
    return expert_longest_trajectory(environment);
  }

 private:
  ViaPointExpertParams params_;
};

}  // namespace corrmp
