// Knot determinant, linking number, winding number and far-away closure of rope
// polylines (paper, Section IV-C "Knotting with the real robot").
#include "envs/rope_knot/knot_check.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "envs/rope_knot/near_segment_pairs.hpp"
#include "envs/rope_knot/orientation.hpp"

namespace corrmp {
namespace {

using Points = std::vector<Eigen::Vector3d>;

constexpr double kPi = 3.14159265358979323846;

Eigen::Vector3d centroid(const Points& curve) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const auto& p : curve) sum += p;
  return sum / static_cast<double>(curve.size());
}

double extent_about(const Points& curve, const Eigen::Vector3d& centre) {
  double extent = 0.0;
  for (const auto& p : curve) extent = std::max(extent, (p - centre).norm());
  return extent;
}

void require_finite(const Points& curve, const char* where) {
  for (const auto& p : curve) {
    if (!p.allFinite()) throw std::invalid_argument(std::string(where) + ": non-finite node");
  }
}

// Relative to the polygon's size: vertices closer than kMergeDistance to the previous one are
// dropped, and a projection with a feature smaller than kDegenerateMargin is not generic. The
// merge is far coarser than the degeneracy so that a short edge left by it cannot make every
// projection degenerate (a node 1e-10 from its neighbour would).
constexpr double kMergeDistance = 1e-6;
constexpr double kDegenerateMargin = 1e-9;

// The closed polygon without consecutive (or first/last) near-duplicate vertices.
Points distinct_cyclic_vertices(const Points& polygon) {
  Eigen::Vector3d lo = polygon.front(), hi = polygon.front();
  for (const auto& p : polygon) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double tolerance = kMergeDistance * (hi - lo).norm();
  Points result;
  for (const auto& p : polygon) {
    if (result.empty() || (p - result.back()).norm() > tolerance) result.push_back(p);
  }
  while (result.size() > 1 && (result.back() - result.front()).norm() <= tolerance) {
    result.pop_back();
  }
  return result;
}

// ---- planar diagram -------------------------------------------------------

struct Crossing {
  double over_position;   // segment index + parameter along the over strand
  double under_position;  // segment index + parameter along the under strand
};

struct Diagram {
  std::vector<Crossing> crossings;
  double margin = 0.0;  // distance to the nearest degenerate projection
};

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

double point_segment_distance(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                              const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

double endpoints_to_segments_distance(const Eigen::Vector2d& a0, const Eigen::Vector2d& a1,
                                      const Eigen::Vector2d& b0, const Eigen::Vector2d& b1) {
  return std::min({point_segment_distance(a0, b0, b1), point_segment_distance(a1, b0, b1),
                   point_segment_distance(b0, a0, a1), point_segment_distance(b1, a0, a1)});
}

// Crossings of the polygon's projection along `view` and how far that projection
// is from a degenerate one (vertex on a crossing, touching or overlapping
// segments, two crossings at one point, equal heights at a crossing).
Diagram project(const Points& polygon, const Eigen::Vector3d& view) {
  const Eigen::Vector3d u = view.unitOrthogonal();
  const Eigen::Vector3d v = view.cross(u);
  const int n = static_cast<int>(polygon.size());
  std::vector<Eigen::Vector2d> flat(n);
  std::vector<double> height(n);
  for (int i = 0; i < n; ++i) {
    flat[i] = Eigen::Vector2d(polygon[i].dot(u), polygon[i].dot(v));
    height[i] = polygon[i].dot(view);
  }
  Diagram diagram;
  diagram.margin = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d& a0 = flat[i];
    const Eigen::Vector2d& a1 = flat[(i + 1) % n];
    const Eigen::Vector2d& a2 = flat[(i + 2) % n];
    diagram.margin = std::min(
        {diagram.margin, point_segment_distance(a2, a0, a1), point_segment_distance(a0, a1, a2)});
  }
  // Pairs farther apart than the margin so far can neither cross nor lower it.
  std::vector<std::vector<double>> stops_on_segment(n);
  for_each_near_segment_pair(flat, diagram.margin, [&](int i, int j) {
    if (j == i + 1 || (i == 0 && j == n - 1)) return;
    const Eigen::Vector2d& a0 = flat[i];
    const Eigen::Vector2d& a1 = flat[(i + 1) % n];
    const Eigen::Vector2d& b0 = flat[j];
    const Eigen::Vector2d& b1 = flat[(j + 1) % n];
    diagram.margin = std::min(diagram.margin, endpoints_to_segments_distance(a0, a1, b0, b1));
    // Exact signs decide whether the segments cross: rounded ones put crossings between
    // separate pieces of one straight line.
    if (orientation(a0, a1, b0) * orientation(a0, a1, b1) >= 0) return;
    if (orientation(b0, b1, a0) * orientation(b0, b1, a1) >= 0) return;
    const double o1 = cross2(a1 - a0, b0 - a0), o2 = cross2(a1 - a0, b1 - a0);
    const double o3 = cross2(b1 - b0, a0 - b0), o4 = cross2(b1 - b0, a1 - b0);
    const double s = std::clamp(o3 / (o3 - o4), 0.0, 1.0);
    const double t = std::clamp(o1 / (o1 - o2), 0.0, 1.0);
    const double height_a = height[i] + s * (height[(i + 1) % n] - height[i]);
    const double height_b = height[j] + t * (height[(j + 1) % n] - height[j]);
    diagram.margin = std::min(diagram.margin, std::abs(height_a - height_b));
    stops_on_segment[i].push_back(s * (a1 - a0).norm());
    stops_on_segment[j].push_back(t * (b1 - b0).norm());
    if (height_a > height_b) {
      diagram.crossings.push_back({i + s, j + t});
    } else {
      diagram.crossings.push_back({j + t, i + s});
    }
  });
  for (auto& stops : stops_on_segment) {
    std::sort(stops.begin(), stops.end());
    for (size_t k = 1; k < stops.size(); ++k) {
      diagram.margin = std::min(diagram.margin, stops[k] - stops[k - 1]);
    }
  }
  return diagram;
}

// Fixed, deterministic view directions spread over a hemisphere (golden angle
// spiral, offset so none is a coordinate axis or lies in a coordinate plane).
std::vector<Eigen::Vector3d> candidate_views() {
  constexpr int kCount = 16;
  const double golden_angle = kPi * (3.0 - std::sqrt(5.0));
  std::vector<Eigen::Vector3d> views;
  for (int k = 0; k < kCount; ++k) {
    const double z = 1.0 - (k + 0.5) / kCount;
    const double r = std::sqrt(1.0 - z * z);
    const double phi = 0.3 + k * golden_angle;
    views.push_back(Eigen::Vector3d(r * std::cos(phi), r * std::sin(phi), z).normalized());
  }
  return views;
}

Diagram generic_diagram(const Points& polygon) {
  Eigen::Vector3d lo = polygon.front(), hi = polygon.front();
  for (const auto& p : polygon) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  Diagram best;
  best.margin = -1.0;
  for (const auto& view : candidate_views()) {
    Diagram diagram = project(polygon, view);
    if (diagram.margin > best.margin) best = std::move(diagram);
  }
  if (!(best.margin > kDegenerateMargin * (hi - lo).norm())) {
    throw std::runtime_error(
        "knot_determinant: no generic projection (the polygon self-intersects or is degenerate)");
  }
  return best;
}

// Colouring matrix: one row per crossing, one column per arc (arcs run from one
// under-pass to the next along the polygon).
IntegerMatrix colouring_matrix(const std::vector<Crossing>& crossings) {
  const int n = static_cast<int>(crossings.size());
  std::vector<double> under(n);
  for (int c = 0; c < n; ++c) under[c] = crossings[c].under_position;
  std::sort(under.begin(), under.end());
  const auto arc_containing = [&](double position) {
    const int after =
        static_cast<int>(std::upper_bound(under.begin(), under.end(), position) - under.begin());
    return after == 0 ? n - 1 : after - 1;
  };
  IntegerMatrix matrix = IntegerMatrix::Zero(n, n);
  for (int c = 0; c < n; ++c) {
    const int outgoing = static_cast<int>(
        std::lower_bound(under.begin(), under.end(), crossings[c].under_position) - under.begin());
    const int incoming = (outgoing + n - 1) % n;
    matrix(c, arc_containing(crossings[c].over_position)) += 2;
    matrix(c, incoming) -= 1;
    matrix(c, outgoing) -= 1;
  }
  return matrix;
}

// ---- exact determinant ----------------------------------------------------

__extension__ using UInt128 = unsigned __int128;

std::uint64_t multiply_mod(std::uint64_t a, std::uint64_t b, std::uint64_t p) {
  return static_cast<std::uint64_t>((static_cast<UInt128>(a) * b) % p);
}

std::uint64_t power_mod(std::uint64_t base, std::uint64_t exponent, std::uint64_t p) {
  std::uint64_t result = 1;
  while (exponent > 0) {
    if (exponent & 1U) result = multiply_mod(result, base, p);
    base = multiply_mod(base, base, p);
    exponent >>= 1U;
  }
  return result;
}

// det(matrix) mod p by Gaussian elimination over GF(p), p prime < 2^62, as the
// residue of least absolute value.
std::int64_t determinant_mod(const IntegerMatrix& matrix, std::uint64_t p) {
  const int n = static_cast<int>(matrix.rows());
  const auto sp = static_cast<std::int64_t>(p);
  std::vector<std::vector<std::uint64_t>> a(n, std::vector<std::uint64_t>(n));
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) a[r][c] = static_cast<std::uint64_t>((matrix(r, c) % sp + sp) % sp);
  }
  std::uint64_t det = 1;
  for (int k = 0; k < n; ++k) {
    int pivot = k;
    while (pivot < n && a[pivot][k] == 0) ++pivot;
    if (pivot == n) return 0;
    if (pivot != k) {
      std::swap(a[pivot], a[k]);
      det = (p - det) % p;
    }
    det = multiply_mod(det, a[k][k], p);
    const std::uint64_t inverse = power_mod(a[k][k], p - 2, p);
    for (int r = k + 1; r < n; ++r) {
      if (a[r][k] == 0) continue;
      const std::uint64_t factor = multiply_mod(a[r][k], inverse, p);
      for (int c = k; c < n; ++c) {
        a[r][c] = (a[r][c] + p - multiply_mod(factor, a[k][c], p)) % p;
      }
    }
  }
  return det > p / 2 ? static_cast<std::int64_t>(det) - sp : static_cast<std::int64_t>(det);
}

// Signed solid angle swept by (b - a) / |b - a| for a on [p1, p2], b on [p3, p4].
double segment_pair_solid_angle(const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                                const Eigen::Vector3d& p3, const Eigen::Vector3d& p4) {
  const Eigen::Vector3d r13 = p3 - p1, r14 = p4 - p1, r23 = p3 - p2, r24 = p4 - p2;
  const Eigen::Vector3d sides[4] = {r13.cross(r14), r14.cross(r24), r24.cross(r23), r23.cross(r13)};
  const double scale =
      std::max({r13.squaredNorm(), r14.squaredNorm(), r23.squaredNorm(), r24.squaredNorm()});
  Eigen::Vector3d normals[4];
  for (int k = 0; k < 4; ++k) {
    const double length = sides[k].norm();
    if (length <= 1e-15 * scale) return 0.0;
    normals[k] = sides[k] / length;
  }
  // asin(n_k . n_k+1) = pi / 2 - angle(n_k, n_k+1); atan2 keeps it accurate near +-1.
  double omega = 0.0;
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector3d& n0 = normals[k];
    const Eigen::Vector3d& n1 = normals[(k + 1) % 4];
    omega += 0.5 * kPi - std::atan2(n0.cross(n1).norm(), n0.dot(n1));
  }
  const double orientation = (p4 - p3).cross(p2 - p1).dot(r13);
  if (orientation == 0.0) return 0.0;
  return orientation > 0.0 ? omega : -omega;
}

}  // namespace

Points close_far_away(const Points& open_curve, double radius) {
  if (open_curve.size() < 2) throw std::invalid_argument("close_far_away: fewer than 2 nodes");
  require_finite(open_curve, "close_far_away");
  const Eigen::Vector3d centre = centroid(open_curve);
  const double extent = extent_about(open_curve, centre);
  if (!(extent > 0.0)) throw std::invalid_argument("close_far_away: all nodes coincide");
  if (!(radius > extent) || !std::isfinite(radius)) {
    throw std::invalid_argument("close_far_away: radius " + std::to_string(radius) +
                                " must exceed the curve's extent " + std::to_string(extent));
  }
  // Radial exit direction of an end; its outward tangent when the end is the centroid.
  const auto exit_direction = [&](const Eigen::Vector3d& end, bool at_back) {
    Eigen::Vector3d direction = end - centre;
    if (direction.norm() > 1e-9 * extent) return Eigen::Vector3d(direction.normalized());
    const int count = static_cast<int>(open_curve.size());
    for (int k = 1; k < count; ++k) {
      direction = end - open_curve[at_back ? count - 1 - k : k];
      if (direction.norm() > 1e-9 * extent) return Eigen::Vector3d(direction.normalized());
    }
    return Eigen::Vector3d(Eigen::Vector3d::UnitX());
  };
  const Eigen::Vector3d last_exit = exit_direction(open_curve.back(), true);
  const Eigen::Vector3d first_exit = exit_direction(open_curve.front(), false);
  Eigen::Vector3d axis = last_exit.cross(first_exit);
  const double angle = std::atan2(axis.norm(), last_exit.dot(first_exit));
  axis = axis.norm() > 1e-9 ? axis.normalized() : last_exit.unitOrthogonal();
  const double max_step = std::min(kPi / 18.0, std::acos(extent / radius));
  const double steps = std::ceil(angle / max_step);
  if (steps > 100000.0) {
    throw std::invalid_argument("close_far_away: radius too close to the curve's extent");
  }
  Points closed = open_curve;
  closed.push_back(centre + radius * last_exit);
  const int arc_steps = static_cast<int>(steps);
  for (int k = 1; k < arc_steps; ++k) {
    closed.push_back(centre +
                     radius * (Eigen::AngleAxisd(angle * k / arc_steps, axis) * last_exit));
  }
  if (arc_steps >= 1) closed.push_back(centre + radius * first_exit);
  return closed;
}

int knot_determinant(const Points& closed_polygon) {
  if (closed_polygon.size() < 3) {
    throw std::invalid_argument("knot_determinant: fewer than 3 vertices");
  }
  require_finite(closed_polygon, "knot_determinant");
  const Points polygon = distinct_cyclic_vertices(closed_polygon);
  if (polygon.size() < 3) throw std::invalid_argument("knot_determinant: fewer than 3 vertices");
  const Diagram diagram = generic_diagram(polygon);
  if (diagram.crossings.size() < 2) return 1;
  const IntegerMatrix matrix = colouring_matrix(diagram.crossings);
  const int minor_size = static_cast<int>(matrix.rows()) - 1;
  const std::int64_t det =
      std::abs(exact_integer_determinant(matrix.topLeftCorner(minor_size, minor_size)));
  if (det > INT_MAX) throw std::runtime_error("knot_determinant: determinant exceeds int range");
  return static_cast<int>(det);
}

double gauss_linking_number(const Points& closed_a, const Points& closed_b) {
  if (closed_a.size() < 2 || closed_b.size() < 2) {
    throw std::invalid_argument("gauss_linking_number: a polygon has fewer than 2 vertices");
  }
  require_finite(closed_a, "gauss_linking_number");
  require_finite(closed_b, "gauss_linking_number");
  const size_t na = closed_a.size(), nb = closed_b.size();
  double total = 0.0;
  for (size_t i = 0; i < na; ++i) {
    for (size_t j = 0; j < nb; ++j) {
      total += segment_pair_solid_angle(closed_a[i], closed_a[(i + 1) % na], closed_b[j],
                                        closed_b[(j + 1) % nb]);
    }
  }
  return total / (4.0 * kPi);
}

double winding_number_about_line(const Points& curve, const Eigen::Vector3d& point,
                                 const Eigen::Vector3d& direction) {
  if (!(direction.norm() > 0.0) || !direction.allFinite()) {
    throw std::invalid_argument("winding_number_about_line: zero or non-finite direction");
  }
  require_finite(curve, "winding_number_about_line");
  const Eigen::Vector3d axis = direction.normalized();
  const Eigen::Vector3d u = axis.unitOrthogonal();
  const Eigen::Vector3d v = axis.cross(u);
  std::vector<Eigen::Vector2d> flat;
  for (const auto& p : curve) {
    const Eigen::Vector3d q = p - point;
    flat.emplace_back(q.dot(u), q.dot(v));
    if (flat.back().norm() == 0.0) {
      throw std::invalid_argument("winding_number_about_line: a node lies on the line");
    }
  }
  double angle = 0.0;
  for (size_t i = 1; i < flat.size(); ++i) {
    angle += std::atan2(cross2(flat[i - 1], flat[i]), flat[i - 1].dot(flat[i]));
  }
  return angle / (2.0 * kPi);
}

std::int64_t exact_integer_determinant(const IntegerMatrix& matrix) {
  if (matrix.rows() != matrix.cols()) {
    throw std::invalid_argument("exact_integer_determinant: matrix is not square");
  }
  const std::int64_t first = determinant_mod(matrix, (std::uint64_t{1} << 61) - 1);
  const std::int64_t second = determinant_mod(matrix, (std::uint64_t{1} << 62) - 57);
  if (first != second) {
    throw std::runtime_error("exact_integer_determinant: |det| exceeds 2^60");
  }
  return first;
}

KnotReport analyse_rope_on_bar(const Points& nodes, const Eigen::Vector3d& bar_point,
                               const Eigen::Vector3d& bar_direction) {
  if (nodes.size() < 2) throw std::invalid_argument("analyse_rope_on_bar: fewer than 2 nodes");
  KnotReport report;
  report.winding_number = winding_number_about_line(nodes, bar_point, bar_direction);
  const double extent = extent_about(nodes, centroid(nodes));
  report.determinant = knot_determinant(close_far_away(nodes, 10.0 * extent));
  return report;
}

}  // namespace corrmp
