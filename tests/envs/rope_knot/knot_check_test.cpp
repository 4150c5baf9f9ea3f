// Tests of the rope knot checks (paper, Section IV-C "Knotting with the real
// robot") on constructed curves with known knot types, links and windings.
#include "envs/rope_knot/knot_check.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

#include "core/seeds.hpp"

namespace corrmp {
namespace {

using Points = std::vector<Eigen::Vector3d>;

constexpr double kPi = 3.14159265358979323846;

Points sample_closed(const std::function<Eigen::Vector3d(double)>& curve, int count) {
  Points points;
  for (int k = 0; k < count; ++k) points.push_back(curve(2.0 * kPi * k / count));
  return points;
}

Points trefoil(int count) {
  return sample_closed(
      [](double t) {
        return Eigen::Vector3d(std::sin(t) + 2 * std::sin(2 * t), std::cos(t) - 2 * std::cos(2 * t),
                               -std::sin(3 * t));
      },
      count);
}

Points figure_eight(int count) {
  return sample_closed(
      [](double t) {
        const double r = 2 + std::cos(2 * t);
        return Eigen::Vector3d(r * std::cos(3 * t), r * std::sin(3 * t), std::sin(4 * t));
      },
      count);
}

Points torus_knot_2(int q, int count) {
  return sample_closed(
      [q](double t) {
        const double r = 2 + std::cos(q * t);
        return Eigen::Vector3d(r * std::cos(2 * t), r * std::sin(2 * t), std::sin(q * t));
      },
      count);
}

Points circle(const Eigen::Vector3d& centre, const Eigen::Vector3d& e1, const Eigen::Vector3d& e2,
              int count) {
  return sample_closed([&](double t) { return centre + std::cos(t) * e1 + std::sin(t) * e2; },
                       count);
}

// Piecewise-linear resampling by arc length to `count` nodes (open or closed).
Points resample(const Points& curve, int count, bool closed) {
  Points path = curve;
  if (closed) path.push_back(curve.front());
  std::vector<double> length{0.0};
  for (size_t i = 1; i < path.size(); ++i) {
    length.push_back(length.back() + (path[i] - path[i - 1]).norm());
  }
  Points result;
  const int intervals = closed ? count : count - 1;
  size_t segment = 1;
  for (int k = 0; k < count; ++k) {
    const double target = length.back() * k / intervals;
    while (segment + 1 < path.size() && length[segment] < target) ++segment;
    const double span = length[segment] - length[segment - 1];
    const double s = span > 0 ? (target - length[segment - 1]) / span : 0.0;
    result.push_back(path[segment - 1] +
                     std::clamp(s, 0.0, 1.0) * (path[segment] - path[segment - 1]));
  }
  return result;
}

Points transformed(const Points& curve, const Eigen::Matrix3d& rotation,
                   const Eigen::Vector3d& shift) {
  Points result;
  for (const auto& p : curve) result.push_back(rotation * p + shift);
  return result;
}

Points reversed(Points curve) {
  std::reverse(curve.begin(), curve.end());
  return curve;
}

std::vector<Eigen::Matrix3d> test_rotations() {
  return {Eigen::Matrix3d::Identity(),
          Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix(),
          Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitX()).toRotationMatrix(),
          Eigen::AngleAxisd(2.9, Eigen::Vector3d(-1, 0.5, 0.2).normalized()).toRotationMatrix()};
}

// An unknot whose projections have many crossings: an open arc rising
// monotonically in z through random (x, y), closed by a path outside its
// cylinder (over the top, down the side, back under the bottom).
Points crumpled_unknot(std::uint64_t seed, int count) {
  Rng rng(seed);
  Points points;
  for (int k = 0; k < count; ++k) {
    points.emplace_back(rng.uniform(-1, 1), rng.uniform(-1, 1), 2.0 * k / count);
  }
  points.emplace_back(3, 0.1, points.back().z());
  points.emplace_back(3, 0.1, points.front().z());
  return points;
}

// An overhand knot in a straight-ish open rope: the trefoil cut open at its
// outermost point t = pi / 3, each end led radially out and then along the
// tangent there in opposite directions, with a small wiggle on the tails.
Points open_overhand_rope(int count) {
  const auto knot = [](double t) {
    return Eigen::Vector3d(std::sin(t) + 2 * std::sin(2 * t), std::cos(t) - 2 * std::cos(2 * t),
                           -std::sin(3 * t));
  };
  const double cut = kPi / 3, gap = 0.15, out = 1.0, tail = 6.0;
  const Eigen::Vector3d radial = Eigen::Vector3d(knot(cut).x(), knot(cut).y(), 0).normalized();
  const Eigen::Vector3d tangent = Eigen::Vector3d::UnitZ().cross(radial);
  const Eigen::Vector3d start = knot(cut + gap), end = knot(cut + 2 * kPi - gap);
  const auto wiggle = [](double s) { return Eigen::Vector3d(0, 0, 0.2 * std::sin(1.7 * s)); };
  Points rope;
  for (int k = 20; k >= 1; --k) {
    const double s = tail * k / 20;
    rope.push_back(start + out * radial + s * tangent + wiggle(s));
  }
  for (int k = 0; k <= 200; ++k) rope.push_back(knot(cut + gap + (2 * kPi - 2 * gap) * k / 200));
  for (int k = 1; k <= 20; ++k) {
    const double s = tail * k / 20;
    rope.push_back(end + out * radial - s * tangent + wiggle(s));
  }
  return resample(rope, count, false);
}

// A rope hanging down in front of the bar (the x axis), wrapped once around it
// (over the top, behind, under) while advancing along it, hanging down again.
Points rope_wrapped_once(int count) {
  const double r = 0.03, pitch = 0.05, drop = 0.3;
  Points rope;
  rope.emplace_back(0, r, -drop);
  for (int k = 0; k <= 60; ++k) {
    const double angle = 2 * kPi * k / 60;
    rope.emplace_back(pitch * k / 60, r * std::cos(angle), r * std::sin(angle));
  }
  rope.emplace_back(pitch, r, -drop);
  return resample(rope, count, false);
}

// Each edge of the closed polygon split into `pieces` exactly collinear pieces.
Points split_edges(const Points& polygon, int pieces) {
  Points result;
  const size_t n = polygon.size();
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d& a = polygon[i];
    const Eigen::Vector3d& b = polygon[(i + 1) % n];
    for (int k = 0; k < pieces; ++k) result.push_back(a + (double(k) / pieces) * (b - a));
  }
  return result;
}

// An unknotted open rope: a perfectly straight standing part (nodes exactly on a line), then
// one loop back over it and away, shifted and, if `rotate`, turned by `angle` about `axis`.
struct StraightPartRope {
  int pieces;
  double half_length, crossing_x, height, width, angle;
  Eigen::Vector3d axis, shift;
  bool rotate;
};

Points rope_looping_over_a_straight_part(const StraightPartRope& p) {
  Points rope;
  for (int k = 0; k <= p.pieces; ++k) {
    rope.emplace_back(-p.half_length + 2 * p.half_length * k / p.pieces, 0.0, 0.0);
  }
  for (int k = 1; k <= 40; ++k) {
    const double s = k / 40.0;
    const double x = p.half_length + (p.crossing_x - p.half_length) * s;
    rope.emplace_back(x + 0.05 * std::sin(kPi * s), -p.width * std::cos(kPi * s),
                      p.height * std::sin(kPi * s) + 0.05);
  }
  for (int k = 1; k <= 20; ++k) {
    rope.emplace_back(p.crossing_x - 0.02 * k, p.width + 0.05 * k, 0.05 - 0.01 * k);
  }
  const Eigen::Matrix3d rotation =
      p.rotate ? Eigen::AngleAxisd(p.angle, p.axis.normalized()).toRotationMatrix()
               : Eigen::Matrix3d::Identity();
  return transformed(rope, rotation, p.shift);
}

StraightPartRope random_straight_part_rope(std::uint64_t seed) {
  Rng rng(seed);
  StraightPartRope p;
  p.pieces = std::array<int, 3>{8, 16, 31}[seed % 3];
  p.half_length = 1.0 + 0.3 * rng.uniform(-1, 1);
  p.crossing_x = 0.5 * rng.uniform(-1, 1);
  p.height = 0.2 + 0.1 * rng.uniform(-1, 1);
  p.width = 0.3 + 0.1 * rng.uniform(-1, 1);
  p.angle = kPi * rng.uniform(-1, 1);
  p.axis = Eigen::Vector3d(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
  p.shift = Eigen::Vector3d(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
  p.rotate = rng.uniform() < 0.5;
  return p;
}

TEST(KnotDeterminant, UnknotsHaveDeterminantOne) {
  EXPECT_EQ(knot_determinant(circle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 50)), 1);
  EXPECT_EQ(knot_determinant(crumpled_unknot(7, 30)), 1);
  EXPECT_EQ(knot_determinant(crumpled_unknot(11, 40)), 1);
}

TEST(KnotDeterminant, TrefoilIsThree) { EXPECT_EQ(knot_determinant(trefoil(120)), 3); }

TEST(KnotDeterminant, FigureEightIsFive) { EXPECT_EQ(knot_determinant(figure_eight(150)), 5); }

TEST(KnotDeterminant, TorusKnotsTwoQHaveDeterminantQ) {
  for (int q : {3, 5, 7, 9}) EXPECT_EQ(knot_determinant(torus_knot_2(q, 40 * q)), q) << q;
}

TEST(KnotDeterminant, MirrorImageHasTheSameDeterminant) {
  Points mirrored = trefoil(120);
  for (auto& p : mirrored) p.z() = -p.z();
  EXPECT_EQ(knot_determinant(mirrored), 3);
}

TEST(KnotDeterminant, InvariantUnderRotationAndShift) {
  for (const auto& rotation : test_rotations()) {
    const Eigen::Vector3d shift(0.3, -2.0, 5.0);
    EXPECT_EQ(knot_determinant(transformed(trefoil(120), rotation, shift)), 3);
    EXPECT_EQ(knot_determinant(transformed(figure_eight(150), rotation, shift)), 5);
    EXPECT_EQ(knot_determinant(transformed(crumpled_unknot(7, 30), rotation, shift)), 1);
    EXPECT_EQ(knot_determinant(
                  close_far_away(transformed(open_overhand_rope(120), rotation, shift), 100.0)),
              3);
  }
}

TEST(KnotDeterminant, InvariantUnderResampling) {
  EXPECT_EQ(knot_determinant(resample(trefoil(120), 500, true)), 3);
  EXPECT_EQ(knot_determinant(resample(figure_eight(150), 600, true)), 5);
  EXPECT_EQ(knot_determinant(close_far_away(resample(open_overhand_rope(120), 400, false), 100.0)),
            3);
}

TEST(KnotDeterminant, RepeatedClosingVertexIsIgnored) {
  Points polygon = trefoil(120);
  polygon.push_back(polygon.front());
  EXPECT_EQ(knot_determinant(polygon), 3);
}

TEST(KnotDeterminant, RejectsDegenerateInput) {
  EXPECT_THROW(knot_determinant({{0, 0, 0}, {1, 0, 0}}), std::invalid_argument);
  EXPECT_THROW(knot_determinant({{0, 0, 0}, {1, 0, 0}, {1, 0, 0}}), std::invalid_argument);
  // Two edges passing through one point: no projection separates them.
  const Points self_intersecting{{-1, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, -1, 0}};
  EXPECT_THROW(knot_determinant(self_intersecting), std::runtime_error);
}

// Rounded orientation tests under multiply-add contraction put crossings between separate
// pieces of one straight edge; the determinant must not depend on how edges are split.
TEST(KnotDeterminant, EdgesSplitIntoCollinearRunsKeepTheDeterminant) {
  for (const auto& rotation : test_rotations()) {
    for (int pieces : {2, 8, 16}) {
      const Eigen::Vector3d shift(0.1, 0.2, -0.3);
      EXPECT_EQ(
          knot_determinant(split_edges(
              transformed(circle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 9), rotation, shift), pieces)),
          1)
          << pieces;
      for (int q : {3, 5, 7}) {
        for (int vertices : {2 * q + 1, 13, 20}) {
          EXPECT_EQ(knot_determinant(split_edges(
                        transformed(torus_knot_2(q, vertices), rotation, shift), pieces)),
                    q)
              << "q " << q << ", " << vertices << " vertices, " << pieces << " pieces";
        }
      }
    }
  }
}

TEST(KnotDeterminant, NearDuplicateNodesAreMergedNotDegenerate) {
  Rng rng(3);
  for (double gap : {1e-13, 1e-12, 1e-11, 1e-10, 1e-9, 3e-9, 1e-7}) {
    const Points knot = trefoil(120);
    Points with_duplicates;
    for (size_t i = 0; i < knot.size(); ++i) {
      with_duplicates.push_back(knot[i]);
      const Eigen::Vector3d direction(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
      // The trefoil's size (bounding box diagonal) is about 6.
      if (i % 7 == 3) with_duplicates.push_back(knot[i] + 6 * gap * direction.normalized());
    }
    EXPECT_EQ(knot_determinant(with_duplicates), 3) << gap;
  }
}

TEST(KnotDeterminant, LongPolygonsGiveTheSameDeterminant) {
  EXPECT_EQ(knot_determinant(torus_knot_2(5, 4000)), 5);
  EXPECT_EQ(knot_determinant(resample(figure_eight(150), 3000, true)), 5);
}

TEST(CloseFarAway, KeepsTheNodesAndClosesOnTheSphere) {
  const Points rope = open_overhand_rope(120);
  const Points closed = close_far_away(rope, 100.0);
  ASSERT_GT(closed.size(), rope.size() + 1);
  for (size_t i = 0; i < rope.size(); ++i) EXPECT_EQ(closed[i], rope[i]);
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const auto& p : rope) centre += p;
  centre /= static_cast<double>(rope.size());
  for (size_t i = rope.size(); i < closed.size(); ++i) {
    EXPECT_NEAR((closed[i] - centre).norm(), 100.0, 1e-9);
  }
  EXPECT_NEAR((closed[rope.size()] - centre).normalized().dot((rope.back() - centre).normalized()),
              1.0, 1e-12);
}

TEST(CloseFarAway, StraightLineClosesToAnUnknot) {
  Points line;
  for (int k = 0; k < 30; ++k) line.emplace_back(0.1 * k, 0.0, 0.0);
  EXPECT_EQ(knot_determinant(close_far_away(line, 30.0)), 1);
}

TEST(CloseFarAway, RejectsTooSmallRadius) {
  const Points line{{0, 0, 0}, {1, 0, 0}, {2, 0.5, 0}};
  EXPECT_THROW(close_far_away(line, 0.5), std::invalid_argument);
  EXPECT_THROW(close_far_away({{0, 0, 0}}, 5.0), std::invalid_argument);
}

TEST(OpenRope, OverhandKnotClosedFarAwayIsATrefoil) {
  EXPECT_EQ(knot_determinant(close_far_away(open_overhand_rope(100), 100.0)), 3);
}

TEST(OpenRope, TwoOverhandKnotsInSeriesHaveDeterminantNine) {
  // Both knots have the same handedness (a granny knot) or opposite (a square knot).
  const Points first = open_overhand_rope(120);
  const Eigen::Vector3d along = (first.back() - first.front()).normalized();
  for (double mirror : {1.0, -1.0}) {
    Points rope = first;
    for (const auto& p : first) {
      const Eigen::Vector3d shifted = p + 20.0 * along;
      rope.emplace_back(shifted.x(), shifted.y(), mirror * shifted.z());
    }
    EXPECT_EQ(knot_determinant(close_far_away(rope, 300.0)), 9) << mirror;
  }
}

TEST(OpenRope, NearlyFlatOverhandIsStillATrefoil) {
  Points rope = open_overhand_rope(120);
  for (auto& p : rope) p.z() *= 0.02;
  EXPECT_EQ(knot_determinant(close_far_away(rope, 100.0)), 3);
}

TEST(OpenRope, WrapAroundTheBarIsNotAKnot) {
  const KnotReport report =
      analyse_rope_on_bar(rope_wrapped_once(100), {-1, 0, 0}, Eigen::Vector3d::UnitX());
  EXPECT_NEAR(report.winding_number, 1.0, 1e-9);
  EXPECT_EQ(report.determinant, 1);
  EXPECT_FALSE(report.knotted());
}

TEST(OpenRope, LoopOverAPerfectlyStraightStandingPartIsNeverKnotted) {
  // Two whose standing part a rounded orientation test under multiply-add contraction finds
  // crossing itself, then 300 drawn at random.
  std::vector<StraightPartRope> ropes{
      {31, 0.94543669252865636, -0.20217768787618406, 0.10189860867043188, 0.35928280913565586, 0.0,
       Eigen::Vector3d::UnitX(),
       Eigen::Vector3d(0.67823715223773817, 0.089804753037272977, -0.91782948522156127), false},
      {8, 1.1468052427196029, -0.15604425682085571, 0.21246093527152868, 0.39405268411169531,
       3.14 * 0.31114831222125483,
       Eigen::Vector3d(-0.7860720412475003, -0.96104024595649118, -0.92020969579310163),
       Eigen::Vector3d(-0.20687707084095963, 0.57972259468631138, -0.011607688672445438), true}};
  for (std::uint64_t seed = 0; seed < 300; ++seed) ropes.push_back(random_straight_part_rope(seed));
  for (size_t k = 0; k < ropes.size(); ++k) {
    const KnotReport report =
        analyse_rope_on_bar(rope_looping_over_a_straight_part(ropes[k]), {0, 0, -5}, {1, 0, 0});
    EXPECT_EQ(report.determinant, 1) << "rope " << k;
  }
}

TEST(OpenRope, OverhandReportIsKnotted) {
  const KnotReport report =
      analyse_rope_on_bar(open_overhand_rope(100), {0, 0, 0}, Eigen::Vector3d::UnitZ());
  EXPECT_EQ(report.determinant, 3);
  EXPECT_TRUE(report.knotted());
}

TEST(LinkingNumber, HopfLinkIsPlusOrMinusOne) {
  const Points a = circle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 64);
  const Points b = circle({1, 0, 0}, {1, 0, 0}, {0, 0, 1}, 64);
  const double lk = gauss_linking_number(a, b);
  EXPECT_NEAR(std::abs(lk), 1.0, 1e-9);
  EXPECT_NEAR(gauss_linking_number(b, a), lk, 1e-9);
  EXPECT_NEAR(gauss_linking_number(reversed(a), b), -lk, 1e-9);
}

TEST(LinkingNumber, RightHandedHopfLinkIsPlusOne) {
  // a turns counter-clockwise about +z; b passes up (+z) through a's disc.
  const Points a = circle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 64);
  const Points b = circle({1, 0, 0}, {-1, 0, 0}, {0, 0, 1}, 64);
  EXPECT_NEAR(gauss_linking_number(a, b), 1.0, 1e-9);
}

TEST(LinkingNumber, SeparatedCirclesAreUnlinked) {
  const Points a = circle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 64);
  const Points far = circle({3, 0, 0}, {1, 0, 0}, {0, 0, 1}, 64);
  const Points interlocked_plane = circle({0.2, 0.1, 0.5}, {1, 0, 0}, {0, 1, 0}, 64);
  EXPECT_NEAR(gauss_linking_number(a, far), 0.0, 1e-9);
  EXPECT_NEAR(gauss_linking_number(a, interlocked_plane), 0.0, 1e-9);
}

TEST(LinkingNumber, DoubleWindingThroughACircleIsTwo) {
  const Points a = circle({0, 0, 0}, {3, 0, 0}, {0, 3, 0}, 64);
  // (2,1) torus curve: winds twice around a's core circle.
  const Points b = sample_closed(
      [](double t) {
        const double r = 3 + std::cos(2 * t);
        return Eigen::Vector3d(r * std::cos(t), r * std::sin(t), std::sin(2 * t));
      },
      200);
  EXPECT_NEAR(std::abs(gauss_linking_number(a, b)), 2.0, 1e-9);
}

TEST(LinkingNumber, InvariantUnderRotation) {
  const Points a = circle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 64);
  const Points b = circle({1, 0, 0}, {-1, 0, 0}, {0, 0, 1}, 64);
  for (const auto& rotation : test_rotations()) {
    EXPECT_NEAR(gauss_linking_number(transformed(a, rotation, {1, 2, 3}),
                                     transformed(b, rotation, {1, 2, 3})),
                1.0, 1e-9);
  }
}

TEST(WindingNumber, CountsSignedTurnsAboutTheLine) {
  Points helix;
  for (int k = 0; k <= 300; ++k) {
    const double t = 6 * kPi * k / 300;
    helix.emplace_back(std::cos(t), std::sin(t), 0.1 * t);
  }
  const Eigen::Vector3d origin(0, 0, 0), up(0, 0, 1);
  EXPECT_NEAR(winding_number_about_line(helix, origin, up), 3.0, 1e-12);
  EXPECT_NEAR(winding_number_about_line(reversed(helix), origin, up), -3.0, 1e-12);
  EXPECT_NEAR(winding_number_about_line(helix, origin, -2.0 * up), -3.0, 1e-12);
  EXPECT_NEAR(winding_number_about_line(helix, {5, 0, 0}, up), 0.0, 1e-12);
}

TEST(WindingNumber, RopeWrappedOnceIsOneAndRotationInvariant) {
  for (const auto& rotation : test_rotations()) {
    const Points rope = transformed(rope_wrapped_once(100), rotation, {0.1, 0.2, 0.3});
    const Eigen::Vector3d point =
        rotation * Eigen::Vector3d(-1, 0, 0) + Eigen::Vector3d(0.1, 0.2, 0.3);
    EXPECT_NEAR(winding_number_about_line(rope, point, rotation * Eigen::Vector3d::UnitX()), 1.0,
                1e-9);
  }
}

TEST(WindingNumber, RejectsBadLine) {
  const Points curve{{1, 0, 0}, {0, 1, 0}};
  EXPECT_THROW(winding_number_about_line(curve, {0, 0, 0}, {0, 0, 0}), std::invalid_argument);
  EXPECT_THROW(winding_number_about_line(curve, {1, 0, 5}, {0, 0, 1}), std::invalid_argument);
}

TEST(ExactIntegerDeterminant, MatchesKnownValues) {
  const int n = 80;
  IntegerMatrix path = IntegerMatrix::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    path(i, i) = 2;
    if (i + 1 < n) path(i, i + 1) = path(i + 1, i) = -1;
  }
  EXPECT_EQ(exact_integer_determinant(path), n + 1);
  IntegerMatrix scaled = 3 * IntegerMatrix::Identity(30, 30);
  scaled(0, 0) = -3;
  std::int64_t power = -1;
  for (int i = 0; i < 30; ++i) power *= 3;
  EXPECT_EQ(exact_integer_determinant(scaled), power);
  EXPECT_EQ(exact_integer_determinant(IntegerMatrix(0, 0)), 1);
  IntegerMatrix singular(2, 2);
  singular << 2, 4, 1, 2;
  EXPECT_EQ(exact_integer_determinant(singular), 0);
}

TEST(ExactIntegerDeterminant, RejectsTooLargeDeterminant) {
  EXPECT_THROW(exact_integer_determinant(3 * IntegerMatrix::Identity(50, 50)), std::runtime_error);
  EXPECT_THROW(exact_integer_determinant(IntegerMatrix::Zero(2, 3)), std::invalid_argument);
}

}  // namespace
}  // namespace corrmp
