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
  int columns = 1, rows = 1;
  if (std::isfinite(cell) && cell > 0.0 && size.allFinite()) {
    columns = static_cast<int>(std::min(4.0 * n, std::floor(size.x() / cell))) + 1;
    rows = static_cast<int>(std::min(4.0 * n, std::floor(size.y() / cell))) + 1;
  } else {
    cell = 1.0;  // one cell: every pair is tested
  }
  // A cell index, clamped before the conversion (a NaN or huge quotient stays in range).
  const auto index = [cell](double offset, int count) {
    const double q = std::floor(offset / cell);
    if (!(q > 0.0)) return 0;
    return q >= count - 1 ? count - 1 : static_cast<int>(q);
  };
  const auto column_of = [&](double x) { return index(x - lo.x(), columns); };
  const auto row_of = [&](double y) { return index(y - lo.y(), rows); };
  // Many long segments among short ones would each fill a row or column of cells: past a
  // budget of memberships, one cell (all pairs, as many tests as without a grid) is cheaper.
  double memberships = 0.0;
  for (const Box& box : boxes) {
    memberships += (row_of(box.hi.y()) - row_of(box.lo.y()) + 1.0) *
                   (column_of(box.hi.x()) - column_of(box.lo.x()) + 1.0);
  }
  if (memberships > 32.0 * n) columns = rows = 1;
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
