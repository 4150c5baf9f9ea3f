// Topological checks that decide whether a simulated rope (an open polyline of
// nodes) was knotted over the bar: winding number about the bar, knot
// determinant of the rope closed far away, Gauss linking number of closed
// polygons (paper, Section IV-C "Knotting with the real robot": the half hitch
// over a horizontal bar). All functions are pure and deterministic.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace corrmp {

using IntegerMatrix = Eigen::Matrix<std::int64_t, Eigen::Dynamic, Eigen::Dynamic>;

// Closes an open curve "at infinity". With c the centroid of the nodes, each end
// e leaves radially along d = (e - c) / |e - c| (the end tangent if e == c) to the
// exit point c + radius * d; the two exit points are joined by the shorter great
// circle arc of the sphere |x - c| = radius (any great circle for antipodal exits),
// sampled finely enough that its chords stay outside the ball holding the curve.
// Returns the nodes followed by the closing vertices; the last vertex joins the
// first (no repeated vertex). Requires radius > max |p_i - c|; use about 10x that.
// Assumption: the knot type so defined is that of the rope with its ends pulled
// straight away from its centroid; it is the meaningful one when the ends lie on
// the outside of the tangle (free rope ends), not when an end is buried inside it.
std::vector<Eigen::Vector3d> close_far_away(const std::vector<Eigen::Vector3d>& open_curve,
                                            double radius);

// Knot determinant |Delta(-1)| of a closed polygon (the last vertex joins the
// first): 1 for the unknot, 3 for the trefoil (overhand knot, half hitch slid off
// its object), 5 for the figure-eight.
// Method: project along the direction, among a fixed set, that maximises the
// smallest distance from a crossing to a vertex, between non-crossing segments,
// between crossings and between the two heights at a crossing (a generic diagram);
// split the diagram into arcs at the under-passes; each crossing gives one row of
// the colouring matrix, 2 * x_over - x_under_in - x_under_out (the Alexander
// matrix at t = -1); the determinant is |det| of that matrix with one row and one
// column deleted (1 for a diagram with fewer than two crossings).
// Vertices closer than 1e-6 of the polygon's size (bounding-box diagonal) to the previous
// one are merged first. Whether two projected segments cross is decided by exact orientation
// tests, so separate pieces of one straight edge never cross whatever the compiler contracts;
// a projection is generic when all those distances exceed 1e-9 of the size. Segment pairs are
// found through a grid, so the time grows about linearly with vertices on curves whose
// segments are short beside their size.
// Throws std::invalid_argument for fewer than 3 distinct vertices and
// std::runtime_error when no generic projection exists (self-intersecting curve).
int knot_determinant(const std::vector<Eigen::Vector3d>& closed_polygon);

// Gauss linking number Lk = (1 / 4 pi) sum_{i,j} Omega_ij of two closed polygons
// (the last vertex of each joins its first), Omega_ij being the signed solid angle
// swept by (a - b) / |a - b| for a on segment i of closed_a and b on segment j of
// closed_b, i.e. the Gauss integral (1 / 4 pi) int_A int_B (a - b) . (da x db) / |a - b|^3.
// For straight segments it is the area of the spherical quadrilateral with
// vertices the directions of the four vectors between the segment ends:
// sum_k asin(n_k . n_k+1) over the unit normals n_k of its sides (evaluated as
// pi / 2 - angle(n_k, n_k+1) for accuracy), signed by the orientation of the two
// segments. Exact for polygons, so the result is an integer up to rounding
// (about 1e-12); +1 for a right-handed Hopf link, sign flips with either orientation.
double gauss_linking_number(const std::vector<Eigen::Vector3d>& closed_a,
                            const std::vector<Eigen::Vector3d>& closed_b);

// Winding number of a polyline (open or not, its vertices in order, no implicit
// closing segment) about the line point + s * direction: the nodes are projected
// onto the plane normal to the line and the signed angles
// atan2(cross(q_i, q_i+1), dot(q_i, q_i+1)) between consecutive projected nodes
// q_i (relative to the line) are summed and divided by 2 pi. Positive for turns
// counter-clockwise as seen from the tip of `direction` (right-hand rule).
// Throws std::invalid_argument for a zero direction or a node on the line.
double winding_number_about_line(const std::vector<Eigen::Vector3d>& curve,
                                 const Eigen::Vector3d& point, const Eigen::Vector3d& direction);

// Exact determinant of a square integer matrix: Gaussian elimination modulo the
// primes 2^61 - 1 and 2^62 - 57, each result taken as the residue of least
// absolute value. Exact when |det| < 2^60; the two residues must agree (which a
// larger determinant passes only if |det| > 2^122), otherwise std::runtime_error.
// A colouring matrix with n crossings has |det| <= 6^(n / 2) (Hadamard), so the
// agreement is a proof of exactness for up to 94 crossings.
std::int64_t exact_integer_determinant(const IntegerMatrix& matrix);

struct KnotReport {
  double winding_number = 0.0;  // of the rope about the bar, in turns
  int determinant = 1;          // of the rope closed far away (radius 10x its extent)
  bool knotted() const { return determinant != 1; }
};

// Both checks for a rope of nodes hanging on the bar line bar_point + s * bar_direction.
// A half hitch has |winding_number| >= 1 and determinant 3; a plain wrap has
// |winding_number| >= 1 and determinant 1.
KnotReport analyse_rope_on_bar(const std::vector<Eigen::Vector3d>& nodes,
                               const Eigen::Vector3d& bar_point,
                               const Eigen::Vector3d& bar_direction);

}  // namespace corrmp
