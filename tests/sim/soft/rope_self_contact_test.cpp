#include "sim/soft/rope_self_contact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace corrmp {
namespace {

// A rope of `nodes` nodes as a random walk of steps about `step` long, kept in
// a box `box` wide: a small box crumples it into many deep contacts.
RopeContactState crumpled(std::uint64_t seed, int nodes, double step, double box) {
  std::mt19937_64 rng(seed);
  auto uniform = [&](double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(rng() >> 11) * 0x1.0p-53;
  };
  RopeContactState state;
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (int i = 0; i < nodes; ++i) {
    state.x.push_back(p);
    state.v.push_back(Eigen::Vector3d(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)));
    state.inverse_mass.push_back(uniform(0, 1) < 0.05 ? 0.0 : uniform(0.5, 2.0));
    Eigen::Vector3d next;
    do {
      next = p + step * Eigen::Vector3d(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
    } while (next.cwiseAbs().maxCoeff() > box / 2);
    p = next;
  }
  return state;
}

// A rope coiled as a helix whose turns lie `spacing` apart, a little noise on
// each node: a spacing just under the contact distance gives many shallow
// contacts, as a tightening knot does.
RopeContactState coiled(std::uint64_t seed, int nodes, double spacing) {
  std::mt19937_64 rng(seed);
  auto noise = [&] { return 1e-4 * (static_cast<double>(rng() >> 11) * 0x1.0p-52 - 1.0); };
  RopeContactState state;
  for (int i = 0; i < nodes; ++i) {
    const double angle = 0.3 * i;
    state.x.push_back(Eigen::Vector3d(0.3 * std::cos(angle) + noise(),
                                      0.3 * std::sin(angle) + noise(),
                                      spacing * angle / (2 * M_PI) + noise()));
    state.v.push_back(Eigen::Vector3d(noise(), noise(), -0.5));
    state.inverse_mass.push_back(1.0);
  }
  return state;
}

// The candidates' pass must be the all-pairs pass, bit for bit, pass after
// pass (each starting from the last one's sweep order): from loose coils to
// knots so tight that the nodes are pushed far enough for fresh candidates to
// be found midway, round after round, and for the all-pairs sweep to finish.
TEST(RopeSelfContact, TheCandidatesGiveExactlyTheAllPairsResults) {
  const RopeContactParams params{0.05, 0.5, 1.0 / 600.0};
  int passes_with_contacts = 0, passes_found_afresh = 0, passes_swept = 0;
  std::vector<std::pair<std::string, RopeContactState>> ropes;
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    const int nodes = seed % 4 == 3 ? 40 : 96;
    for (const double box : {0.3, 0.6, 1.5, 4.0, 20.0})
      ropes.emplace_back("crumpled in " + std::to_string(box), crumpled(seed, nodes, 0.1, box));
    for (const double spacing : {0.0999, 0.099, 0.098, 0.095, 0.09})
      ropes.emplace_back("coiled " + std::to_string(spacing), coiled(seed, nodes, spacing));
  }
  // One state carries its scratch from rope to rope, of either length.
  RopeContactState fast;
  for (const auto& [rope, start] : ropes) {
    fast.x = start.x;
    fast.v = start.v;
    fast.inverse_mass = start.inverse_mass;
    RopeContactState plain = start;
    for (int pass = 0; pass < 3; ++pass) {
      const bool fast_changed = resolve_self_contacts(fast, params);
      const bool plain_changed = resolve_self_contacts(plain, params, SelfContactSearch::all_pairs);
      ASSERT_EQ(fast_changed, plain_changed) << rope;
      passes_with_contacts += plain_changed;
      passes_found_afresh += fast.scratch.rounds > 0 && !fast.scratch.swept;
      passes_swept += fast.scratch.swept;
      for (size_t i = 0; i < plain.x.size(); ++i) {
        ASSERT_EQ(fast.x[i], plain.x[i]) << rope << ", node " << i;
        ASSERT_EQ(fast.v[i], plain.v[i]) << rope << ", node " << i;
      }
    }
  }
  EXPECT_GT(passes_with_contacts, 400);
  EXPECT_GT(passes_found_afresh, 10);  // finished on fresh candidates
  EXPECT_GT(passes_swept, 10);         // finished by the plain sweep
}

// A non-finite node goes to the plain sweep; the next, finite pass on the
// same state is exact again.
TEST(RopeSelfContact, ANonFiniteNodeIsPassedOnNotSorted) {
  RopeContactState state = crumpled(7, 40, 0.1, 0.5);
  const RopeContactState finite = state;
  state.x[20] = Eigen::Vector3d(NAN, 0, 0);
  RopeContactState plain = state;
  resolve_self_contacts(state, {0.05, 0.5, 1.0 / 600.0});
  resolve_self_contacts(plain, {0.05, 0.5, 1.0 / 600.0}, SelfContactSearch::all_pairs);
  auto same = [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return ((a.array() == b.array()) || (a.array().isNaN() && b.array().isNaN())).all();
  };
  for (size_t i = 0; i < state.x.size(); ++i) {
    EXPECT_TRUE(same(state.x[i], plain.x[i])) << i;
    EXPECT_TRUE(same(state.v[i], plain.v[i])) << i;
  }
  EXPECT_TRUE(state.scratch.swept);

  state.x = finite.x;
  state.v = finite.v;
  plain = finite;
  resolve_self_contacts(state, {0.05, 0.5, 1.0 / 600.0});
  resolve_self_contacts(plain, {0.05, 0.5, 1.0 / 600.0}, SelfContactSearch::all_pairs);
  for (size_t i = 0; i < state.x.size(); ++i) {
    EXPECT_EQ(state.x[i], plain.x[i]) << i;
    EXPECT_EQ(state.v[i], plain.v[i]) << i;
  }
}

}  // namespace
}  // namespace corrmp
