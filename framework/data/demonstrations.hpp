// Demonstrations: per-segment trajectories of a skill as the human (or its
// emulating expert) showed them, cut at the critical points into pre-MP, cor-MP
// and post-MP (paper, Section III "Method"). A single-segment demonstration is
// the monolithic case. Sources of demonstrations are registry components.
#pragma once

#include <Eigen/Core>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "core/memory_need.hpp"
#include "core/seeds.hpp"
#include "data/observation.hpp"

namespace corrmp {

// One segment of one demonstration. Row t of `x` holds the CNMP inputs of time
// step t (column 0 is time normalised to [0, 1], further columns task
// parameters), row t of `y` the outputs (for example gripper x, y, z in m).
struct SegmentTrajectory {
  std::string segment;  // "pre", "cor", "post", "full", ...
  Eigen::MatrixXd x;
  Eigen::MatrixXd y;
  Eigen::VectorXd context;  // the segment's context vector; may be empty
  Observation start;        // what was observed at the segment's start (critical point)
  // The segment's span in the whole skill's normalised time (its critical
  // points in a monolithic recording of the same demonstration); NaN where
  // the source does not know it.
  double phase_begin = std::numeric_limits<double>::quiet_NaN();
  double phase_end = std::numeric_limits<double>::quiet_NaN();
};

struct Demonstration {
  std::string scenario;  // JSON describing what was demonstrated
  std::vector<SegmentTrajectory> segments;
  std::string decision;  // the decision made at the critical point (a TaskReport label) where known

  const SegmentTrajectory* find(const std::string& segment) const {
    for (const auto& s : segments) {
      if (s.segment == segment) return &s;
    }
    return nullptr;
  }
};

struct DemonstrationSplit {
  std::vector<Demonstration> train;
  std::vector<Demonstration> validation;
};

// Where demonstrations come from: an expert in a simulated environment, files
// recorded by a researcher, or a synthetic family of curves. What a source can
// do is declared, so that a config asking for more fails at load, before
// anything runs (docs/architecture.md, "Load-time checks").
class Environment;

class DemonstrationSource {
 public:
  virtual ~DemonstrationSource() = default;
  // Draws (or loads) the demonstrations; `rng` is this component's own stream.
  // `environment` is the experiment's environment, or null when it has none;
  // experts collect in parallel, each thread in its own Environment::clone()
  // (data/expert_collection.hpp).
  virtual DemonstrationSplit collect(Environment* environment, Rng& rng) = 0;
  // The segments every demonstration holds; empty when only the data tells.
  virtual std::vector<std::string> segments() const { return {}; }
  // Sources whose demonstrations carry their own contexts (no extractor needed).
  virtual bool provides_contexts() const { return false; }
  // Sources that emulate an expert in an environment need one; the type
  // they demonstrate in ("" any).
  virtual bool needs_environment() const { return false; }
  virtual std::string environment_type() const { return ""; }
  // Whether the start observations carry camera images.
  virtual bool records_images() const { return false; }
  // Whether demonstrate() works: an expert shows one given scenario (the
  // evaluation's reference for the expected decision and the trajectory errors).
  virtual bool can_demonstrate() const { return false; }
  virtual Demonstration demonstrate(Environment& environment, const Scenario& scenario,
                                    bool with_images);
  // Goes into the demonstration cache key: bump it whenever the same
  // parameters would now give different demonstrations.
  virtual std::string version() const { return "1"; }
  // The memory the collected demonstrations will take with the declared sizes
  // (checked at load), and their longest trajectory when the config fixes it (else 0);
  // `environment` is the experiment's, or null.
  virtual std::vector<MemoryNeed> memory_needs(const Environment* /*environment*/) const {
    return {};
  }
  virtual int64_t longest_trajectory(const Environment* /*environment*/) const { return 0; }
};

}  // namespace corrmp
