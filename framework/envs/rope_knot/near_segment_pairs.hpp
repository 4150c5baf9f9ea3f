// Pairs of segments of a planar polygon that lie within a distance of each other, found
// through a uniform grid instead of testing all pairs.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <vector>

namespace corrmp {

// Calls visit(i, j), i < j, once for every pair of segments i = (flat[i], flat[i + 1]) and j
// of the closed polygon `flat` (the last vertex joins the first) whose bounding boxes, each
// grown by reach / 2 on every side, overlap: every pair that crosses or whose segments come
// within `reach` of each other is visited, and in a polygon whose segments are short beside its
// size few others are. Neighbouring segments are visited too; the order of calls is fixed by
// the input. Memory is O(n); time is about linear in n for such polygons and at worst that of
// testing all pairs. Requires reach >= 0 (an infinite reach visits every pair).
void for_each_near_segment_pair(const std::vector<Eigen::Vector2d>& flat, double reach,
                                const std::function<void(int, int)>& visit);

}  // namespace corrmp
