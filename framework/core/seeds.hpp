// Reproducible randomness. One root seed per run; every component draws from its
// own stream derived from the root seed and the component's name, so adding
// draws in one component never shifts another. The generator and the
// distributions are written here (not std:: distributions, whose outputs differ
// between standard libraries), so a seed gives the same numbers everywhere.
#pragma once

#include <cstdint>
#include <string_view>

namespace corrmp {

// FNV-1a 64-bit hash of a string.
uint64_t fnv1a64(std::string_view text, uint64_t hash = 0xcbf29ce484222325ULL);

// SplitMix64 finaliser: a bijective mix of 64 bits.
uint64_t mix64(uint64_t value);

// xoshiro256** generator (Blackman & Vigna) seeded through SplitMix64.
class Rng {
 public:
  using result_type = uint64_t;
  explicit Rng(uint64_t seed);

  uint64_t operator()();
  static constexpr uint64_t min() { return 0; }
  static constexpr uint64_t max() { return ~0ULL; }

  double uniform();                             // [0, 1)
  double uniform(double lo, double hi);         // [lo, hi)
  int64_t uniform_int(int64_t lo, int64_t hi);  // inclusive, unbiased
  double normal(double mean = 0.0, double stddev = 1.0);

 private:
  uint64_t state_[4];
  bool has_spare_normal_ = false;
  double spare_normal_ = 0.0;
};

class SeedTree {
 public:
  explicit SeedTree(uint64_t root) : root_(root) {}
  uint64_t root() const { return root_; }
  // The seed of the stream called `name` ("policy", "evaluation", ...).
  uint64_t seed_for(std::string_view name) const;
  Rng stream(std::string_view name) const { return Rng(seed_for(name)); }

 private:
  uint64_t root_;
};

}  // namespace corrmp
