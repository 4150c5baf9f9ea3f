// The rope's self-contact pass (paper, Section IV-C): pushes non-adjacent
// segments closer than two radii apart (by inverse mass), removes their
// approaching velocity and applies friction, one pair at a time in the order of
// (i, j), j >= i + 3, each pair seeing the nodes as the pairs before left them.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <utility>
#include <vector>

namespace corrmp {

// The rope's nodes, changed in place, and what a pass keeps for the next.
struct RopeContactState {
  std::vector<Eigen::Vector3d> x;  // positions
  std::vector<Eigen::Vector3d> v;  // velocities
  std::vector<double> inverse_mass;

  // Kept between passes to save work; whatever an earlier pass left here, on
  // this rope or another, gives the same results.
  struct Scratch {
    std::vector<Eigen::Vector3d> sum;  // per segment: x_i + x_i+1
    std::vector<int> order;            // segments sorted along `axis` at the last pass
    int axis = -1;
    std::vector<std::pair<int, int>> candidates;
    std::vector<std::uint64_t> marked;  // candidate pairs as bits, row i, column j; all 0
    std::vector<int> rows;              // the rows with marks
    std::vector<double> pushed;         // per node
    // What the last pass did: how often it found the candidates afresh midway,
    // and whether the plain sweep finished it.
    int rounds = 0;
    bool swept = false;
  } scratch;
};

struct RopeContactParams {
  double radius = 0;     // in the units of x
  double friction = 0;   // Coulomb coefficient between segments
  double time_step = 0;  // s, turns the push into a friction bound
};

// How the pairs are found. `candidates` (sweep and prune) gives exactly the
// results of `all_pairs` (every pair tested), faster; `all_pairs` is the
// reference it is tested against.
enum class SelfContactSearch { candidates, all_pairs };

// One pass; returns whether any pair was in contact (and the state changed).
bool resolve_self_contacts(RopeContactState& state, const RopeContactParams& params,
                           SelfContactSearch search = SelfContactSearch::candidates);

}  // namespace corrmp
