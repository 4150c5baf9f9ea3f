// The rope's self-contact pass.
#include "sim/soft/rope_self_contact.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

namespace corrmp {

namespace {

// Closest points of segments [p0, p1] and [q0, q1]: parameters s and t in [0, 1].
// A zero-length segment is a point (its parameter is 0).
void closest_parameters(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                        const Eigen::Vector3d& q0, const Eigen::Vector3d& q1, double& s,
                        double& t) {
  const Eigen::Vector3d d1 = p1 - p0;
  const Eigen::Vector3d d2 = q1 - q0;
  const Eigen::Vector3d r = p0 - q0;
  const double a = d1.squaredNorm();
  const double e = d2.squaredNorm();
  const double f = d2.dot(r);
  const double c = d1.dot(r);
  const double b = d1.dot(d2);
  constexpr double kTiny = 1e-24;  // squared length of a zero-length segment
  if (a <= kTiny && e <= kTiny) {
    s = t = 0.0;
    return;
  }
  if (a <= kTiny) {
    s = 0.0;
    t = std::clamp(f / e, 0.0, 1.0);
    return;
  }
  if (e <= kTiny) {
    t = 0.0;
    s = std::clamp(-c / a, 0.0, 1.0);
    return;
  }
  const double denom = a * e - b * b;
  s = denom > 1e-12 * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
  t = (b * s + f) / e;
  if (t < 0.0) {
    t = 0.0;
    s = std::clamp(-c / a, 0.0, 1.0);
  } else if (t > 1.0) {
    t = 1.0;
    s = std::clamp((b - c) / a, 0.0, 1.0);
  }
}

// The pairs (i, j), j >= i + 3, from `from` on in the order of (i, j), whose
// segment midpoint sums lie within `window` of each other, into
// scratch.candidates; false (and no pairs) when a node is not finite, as a
// sort needs finite keys.
bool find_candidates(const std::vector<Eigen::Vector3d>& x, double window, std::pair<int, int> from,
                     RopeContactState::Scratch& scratch) {
  std::vector<std::pair<int, int>>& candidates = scratch.candidates;
  candidates.clear();
  const int segments = static_cast<int>(x.size()) - 1;
  if (segments <= 0) return true;
  std::vector<Eigen::Vector3d>& sum = scratch.sum;
  sum.resize(segments);
  for (int i = 0; i < segments; ++i) {
    sum[i] = x[i] + x[i + 1];
    if (!sum[i].allFinite()) return false;
  }
  Eigen::Vector3d lo = sum[0], hi = sum[0];
  for (const Eigen::Vector3d& s : sum) lo = lo.cwiseMin(s), hi = hi.cwiseMax(s);
  int axis = 0;  // swept along the axis the rope spans most
  (hi - lo).maxCoeff(&axis);
  // The last order along the same axis is nearly sorted: insertion sort finishes it.
  std::vector<int>& order = scratch.order;
  auto before = [&](int a, int b) { return sum[a][axis] < sum[b][axis]; };
  if (static_cast<int>(order.size()) == segments && scratch.axis == axis) {
    for (int a = 1; a < segments; ++a) {
      const int moving = order[a];
      int b = a;
      for (; b > 0 && before(moving, order[b - 1]); --b) order[b] = order[b - 1];
      order[b] = moving;
    }
  } else {
    order.resize(segments);
    for (int i = 0; i < segments; ++i) order[i] = i;
    std::sort(order.begin(), order.end(), before);
    scratch.axis = axis;
  }
  // Found pairs are marked in a bit matrix (row i, column j), whose marked
  // rows read in order give them in the order of (i, j) without a sort; reading
  // clears it again, so only its marked rows cost anything.
  const size_t words = (segments + 63) / 64;
  std::vector<std::uint64_t>& marked = scratch.marked;
  if (marked.size() != segments * words) marked.assign(segments * words, 0);
  std::vector<int>& rows = scratch.rows;
  rows.clear();
  for (int a = 0; a < segments; ++a) {
    for (int b = a + 1; b < segments && sum[order[b]][axis] - sum[order[a]][axis] <= window; ++b) {
      const std::pair<int, int> pair = std::minmax(order[a], order[b]);
      if (pair.second >= pair.first + 3 && pair >= from &&
          (sum[pair.first] - sum[pair.second]).squaredNorm() <= window * window) {
        marked[pair.first * words + pair.second / 64] |= std::uint64_t{1} << (pair.second % 64);
        rows.push_back(pair.first);
      }
    }
  }
  std::sort(rows.begin(), rows.end());
  rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
  for (const int i : rows) {
    for (size_t w = 0; w < words; ++w) {
      std::uint64_t& word = marked[i * words + w];
      for (std::uint64_t bits = word; bits != 0; bits &= bits - 1)
        candidates.emplace_back(i, static_cast<int>(w * 64) + __builtin_ctzll(bits));
      word = 0;
    }
  }
  return true;
}

}  // namespace

bool resolve_self_contacts(RopeContactState& state, const RopeContactParams& params,
                           SelfContactSearch search) {
  std::vector<Eigen::Vector3d>& x = state.x;
  std::vector<Eigen::Vector3d>& v = state.v;
  const std::vector<double>& im = state.inverse_mass;
  const int n = static_cast<int>(x.size());
  const double contact = 2.0 * params.radius;
  double longest = 0;
  for (int i = 0; i + 1 < n; ++i) longest = std::max(longest, (x[i + 1] - x[i]).norm());
  const double reach = longest + contact;
  bool changed = false;
  // Per node, a bound on how far it has been pushed since the candidates were
  // found; `moved` is the largest.
  std::vector<double>& pushed = state.scratch.pushed;
  pushed.assign(n, 0.0);
  double moved = 0;

  // Segments i and j (j >= i + 3) in contact are resolved at once, in the
  // order of (i, j); returns whether they were.
  auto resolve = [&](int i, int j) {
    if ((x[i] + x[i + 1] - x[j] - x[j + 1]).squaredNorm() > 4.0 * reach * reach) return false;
    double s = 0, t = 0;
    closest_parameters(x[i], x[i + 1], x[j], x[j + 1], s, t);
    const Eigen::Vector3d p = x[i] + s * (x[i + 1] - x[i]);
    const Eigen::Vector3d q = x[j] + t * (x[j + 1] - x[j]);
    Eigen::Vector3d normal = p - q;
    const double distance = normal.norm();
    if (distance >= contact || distance < 1e-9) return false;
    normal /= distance;
    const int k[4] = {i, i + 1, j, j + 1};
    const double w[4] = {1 - s, s, -(1 - t), -t};
    double weight = 0;
    for (int m = 0; m < 4; ++m) weight += w[m] * w[m] * im[k[m]];
    if (weight <= 0) return false;
    const double push = (contact - distance) / weight;
    Eigen::Vector3d relative = Eigen::Vector3d::Zero();
    for (int m = 0; m < 4; ++m) relative += w[m] * v[k[m]];
    const double approach = relative.dot(normal);
    const double normal_impulse = approach < 0 ? -approach / weight : 0.0;
    const Eigen::Vector3d tangential = relative - approach * normal;
    const double slide = tangential.norm();
    Eigen::Vector3d friction = Eigen::Vector3d::Zero();
    if (slide > 1e-12) {
      const double stop = slide / weight;
      const double limit = params.friction * (normal_impulse + push / params.time_step);
      friction = -std::min(stop, limit) * tangential / slide;
    }
    for (int m = 0; m < 4; ++m) {
      const double scale = w[m] * im[k[m]];
      x[k[m]] += scale * push * normal;
      v[k[m]] += scale * (normal_impulse * normal + friction);
      pushed[k[m]] += std::abs(scale * push);
      if (!(pushed[k[m]] <= moved)) moved = pushed[k[m]];  // a NaN push too
    }
    return changed = true;
  };

  // Every pair from (i0, j0) on, in order: the plain sweep.
  auto resolve_all_from = [&](int i0, int j0) {
    for (int i = i0; i + 1 < n; ++i)
      for (int j = i == i0 ? j0 : i + 3; j + 1 < n; ++j) resolve(i, j);
  };

  // The same pairs in the same order, found faster: a pair whose segment
  // midpoint sums (x_i + x_i+1) lie further apart than 2 reach + slack when
  // the candidates are found cannot pass resolve()'s first test while each of
  // its four nodes has been pushed less than slack / 4 since. Once a node has
  // been pushed past half of that, the remaining pairs' candidates are found
  // afresh; after kRounds rounds the plain sweep finishes the pass.
  constexpr int kRounds = 8;
  const double slack = contact;
  const double window = 2.0 * reach + slack;
  std::pair<int, int> next{0, 3};  // the first pair not yet resolved
  state.scratch.rounds = 0;
  state.scratch.swept = true;
  if (search == SelfContactSearch::all_pairs || !std::isfinite(window)) {
    resolve_all_from(next.first, next.second);
    return changed;
  }
  state.scratch.swept = false;
  for (int round = 0;; ++round) {
    state.scratch.rounds = round;
    if (round == kRounds || !find_candidates(x, window, next, state.scratch)) {
      state.scratch.swept = true;
      resolve_all_from(next.first, next.second);
      return changed;
    }
    std::fill(pushed.begin(), pushed.end(), 0.0);
    moved = 0;
    bool pushed_far = false;
    for (const auto& [i, j] : state.scratch.candidates) {
      if (resolve(i, j) && !(4.0 * moved <= 0.5 * slack)) {
        next = {i, j + 1};
        pushed_far = true;
        break;
      }
    }
    if (!pushed_far) return changed;
  }
}

}  // namespace corrmp
