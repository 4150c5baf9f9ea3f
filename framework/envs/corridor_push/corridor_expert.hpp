// Demonstrator `corridor_expert`: emulates the human teacher of the paper's
// Section IV-A. pre-MP pushes the object along +y in front of the corridor;
// at the critical point the expert compares the corridor's x with the object's:
// beyond the tolerance it pushes the object further (+x, from its near side) or
// pulls it back (-x, working from its far side), else it does not correct (it
// still goes round to the side, but moves the object by nothing);
// post-MP pushes the object through the corridor. Each demonstration records
// the gripper's x, y, z of every segment, the observations at the segment
// starts (with head-camera images when asked) and the decision, plus the whole
// skill as one recording at a fixed rate (the monolithic baseline's data).
// Like a human's, the expert's tempo varies from stroke to stroke (each
// straight move between waypoints), so the critical points fall at different
// times of the whole recording. Each segment is normalised in time between its
// own critical points: its ends are aligned across demonstrations, while the
// timing inside it still varies.
#pragma once

#include <string>
#include <vector>

#include "core/config/field_rule.hpp"
#include "envs/corridor_push/corridor_push.hpp"
#include "envs/demonstration_source.hpp"
#include "envs/expert_memory.hpp"

namespace corrmp {

struct CorridorExpertParams {
  int train = 100;
  int validation = 100;
  bool images = true;
  int max_attempts_factor = 2;
  double tempo_variation = 0.25;

  template <class Fields>
  void describe(Fields& f) {
    f("train", train, "training demonstrations (the paper: 100)", in_range(1, 100000));
    f("validation", validation, "validation demonstrations (the paper: 100)", in_range(0, 100000));
    f("images", images, "capture head-camera images after pre-MP and after cor-MP");
    f("max_attempts_factor", max_attempts_factor,
      "scenarios tried per wanted demonstration before giving up (failed ones are dropped)",
      in_range(1, 1000));
    f("tempo_variation", tempo_variation,
      "a human's tempo varies: each stroke takes up to this fraction more or less time "
      "(uniform); 0 makes every demonstration of a scenario identical",
      in_range(0.0, 0.9));
  }
};

class CorridorExpert : public DemonstrationSource {
 public:
  explicit CorridorExpert(const CorridorExpertParams& params) : params_(params) {}

  DemonstrationSplit collect(Environment* environment, Rng& rng) override;
  std::vector<std::string> segments() const override { return {"pre", "cor", "post", "full"}; }
  bool needs_environment() const override { return true; }
  std::string environment_type() const override { return "corridor_push"; }
  bool records_images() const override { return params_.images; }
  bool can_demonstrate() const override { return true; }
  std::vector<MemoryNeed> memory_needs(const Environment* environment) const override {
    return expert_memory_needs(environment,
                               {params_.train + params_.validation, params_.images ? 2 : 0});
  }
  int64_t longest_trajectory(const Environment* environment) const override {
    return expert_longest_trajectory(environment);
  }
  // 5: the first per-source version (the pipeline's global key was at v4);
  // 6: every attempt draws from its own stream (parallel collection).
  std::string version() const override { return "6"; }
  // At the expert's nominal tempo (the evaluation's reference).
  Demonstration demonstrate(Environment& environment, const Scenario& scenario,
                            bool with_images) override;
  // With `tempo_rng`, every stroke's duration is drawn (tempo_variation), as a
  // human's varies; without, the nominal tempo.
  Demonstration demonstrate(Environment& environment, const Scenario& scenario, bool with_images,
                            Rng* tempo_rng) const;

  // The correction the expert makes at the critical point.
  static std::string decide(const CorridorPush& env);
  // Waypoints of each segment from the environment's current state.
  static std::vector<Eigen::Vector3d> pre_waypoints(const CorridorPush& env);
  static std::vector<Eigen::Vector3d> cor_waypoints(const CorridorPush& env,
                                                    const std::string& decision);
  // Per-edge slowness of the cor-MP path: the expert pushes slowly.
  static std::vector<double> cor_slowness();
  static std::vector<Eigen::Vector3d> post_waypoints(const CorridorPush& env);

 private:
  double tempo_factor(Rng& rng) const;

  CorridorExpertParams params_;
};

}  // namespace corrmp
