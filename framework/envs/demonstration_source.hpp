// Where demonstrations come from: an expert in a simulated environment, files
// recorded by a researcher, or a synthetic family of curves. Sources are
// registry components (docs/architecture.md, "Components"); what a source can
// do is declared, so that a config asking for more fails at load, before
// anything runs (docs/architecture.md, "Load-time checks").
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/memory_need.hpp"
#include "core/seeds.hpp"
#include "data/demonstrations.hpp"
#include "envs/environment.hpp"

namespace corrmp {

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
