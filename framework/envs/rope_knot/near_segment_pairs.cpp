#include "envs/rope_knot/near_segment_pairs.hpp"

#include <algorithm>
#include <cmath>

namespace corrmp {
namespace {

struct Box {
  Eigen::Vector2d lo, hi;
};

bool overlap(const Box& a, const Box& b) {
  return a.lo.x() <= b.hi.x() && b.lo.x() <= a.hi.x() && a.lo.y() <= b.hi.y() &&
         b.lo.y() <= a.hi.y();
}

}  // namespace

void for_each_near_segment_pair(const std::vector<Eigen::Vector2d>& flat, double reach,
                                const std::function<void(int, int)>& visit) {
  const int n = static_cast<int>(flat.size());
  if (n < 2) return;
  std::vector<Box> boxes(n);
  Eigen::Vector2d lo = flat.front(), hi = flat.front();
  std::vector<double> extents(n);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d& a = flat[i];
    const Eigen::Vector2d& b = flat[(i + 1) % n];
    const Eigen::Vector2d grow = Eigen::Vector2d::Constant(0.5 * reach);
    boxes[i] = {a.cwiseMin(b) - grow, a.cwiseMax(b) + grow};
    lo = lo.cwiseMin(boxes[i].lo);
    hi = hi.cwiseMax(boxes[i].hi);
    extents[i] = (boxes[i].hi - boxes[i].lo).maxCoeff();
  }
  // Cells about as wide as the median grown box (a few long segments, such as a closure far
  // away, do not coarsen it), and at most about 12n of them.
  std::nth_element(extents.begin(), extents.begin() + n / 2, extents.end());
  const Eigen::Vector2d size = hi - lo;
  double cell = std::max(extents[n / 2], std::sqrt(size.x() * size.y() / (4.0 * n)));
  if (!(cell > 0.0)) cell = size.maxCoeff();
  const auto cells_along = [&](double length) {
    return static_cast<int>(std::min(4.0 * n, std::floor(length / cell))) + 1;
  };
  const int columns = cells_along(size.x()), rows = cells_along(size.y());
  const auto column_of = [&](double x) {
    return std::clamp(static_cast<int>((x - lo.x()) / cell), 0, columns - 1);
  };
  const auto row_of = [&](double y) {
    return std::clamp(static_cast<int>((y - lo.y()) / cell), 0, rows - 1);
  };
  std::vector<std::vector<int>> members(static_cast<size_t>(columns) * rows);
  for (int i = 0; i < n; ++i) {
    for (int r = row_of(boxes[i].lo.y()); r <= row_of(boxes[i].hi.y()); ++r) {
      for (int c = column_of(boxes[i].lo.x()); c <= column_of(boxes[i].hi.x()); ++c) {
        members[static_cast<size_t>(r) * columns + c].push_back(i);
      }
    }
  }
  // A pair is visited in the one cell holding the low corner of its boxes' overlap.
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < columns; ++c) {
      const std::vector<int>& here = members[static_cast<size_t>(r) * columns + c];
      for (size_t p = 0; p < here.size(); ++p) {
        for (size_t q = p + 1; q < here.size(); ++q) {
          const Box& a = boxes[here[p]];
          const Box& b = boxes[here[q]];
          if (!overlap(a, b)) continue;
          if (column_of(std::max(a.lo.x(), b.lo.x())) != c) continue;
          if (row_of(std::max(a.lo.y(), b.lo.y())) != r) continue;
          visit(std::min(here[p], here[q]), std::max(here[p], here[q]));
        }
      }
    }
  }
}

}  // namespace corrmp
