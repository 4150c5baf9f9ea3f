// Tessellation of the unit primitives (see unit_meshes.hpp).
#include "sim/render/unit_meshes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace corrmp {
namespace {

constexpr double kPi = 3.14159265358979323846;

void check_segments(int segments) {
  if (segments < 3) {
    throw std::invalid_argument(fmt::format("mesh: need at least 3 segments, got {}", segments));
  }
}

void add_triangle(TriangleMesh& mesh, const Eigen::Vector3f& a, const Eigen::Vector3f& b,
                  const Eigen::Vector3f& c, const Eigen::Vector3f& na, const Eigen::Vector3f& nb,
                  const Eigen::Vector3f& nc) {
  mesh.positions.insert(mesh.positions.end(), {a, b, c});
  mesh.normals.insert(mesh.normals.end(), {na, nb, nc});
}

// Point on the unit sphere at latitude phi (from the equator) and longitude theta.
Eigen::Vector3f sphere_point(double phi, double theta) {
  return Eigen::Vector3d(std::cos(phi) * std::cos(theta), std::cos(phi) * std::sin(theta),
                         std::sin(phi))
      .cast<float>();
}

// Latitude bands of the unit sphere between phi_min and phi_max; a triangle that
// collapses at a pole is left out. The vertex normal is the position.
TriangleMesh sphere_bands(int segments, int bands, double phi_min, double phi_max) {
  TriangleMesh mesh;
  const bool south_pole = phi_min <= -0.5 * kPi;
  const bool north_pole = phi_max >= 0.5 * kPi;
  for (int j = 0; j < bands; ++j) {
    const double phi0 = phi_min + (phi_max - phi_min) * j / bands;
    const double phi1 = j + 1 == bands ? phi_max : phi_min + (phi_max - phi_min) * (j + 1) / bands;
    for (int i = 0; i < segments; ++i) {
      const double theta0 = 2.0 * kPi * i / segments;
      const double theta1 = 2.0 * kPi * (i + 1) / segments;
      const Eigen::Vector3f a = sphere_point(phi0, theta0);
      const Eigen::Vector3f b = sphere_point(phi0, theta1);
      const Eigen::Vector3f c = sphere_point(phi1, theta1);
      const Eigen::Vector3f d = sphere_point(phi1, theta0);
      if (j > 0 || !south_pole) add_triangle(mesh, a, b, c, a, b, c);
      if (j + 1 < bands || !north_pole) add_triangle(mesh, a, c, d, a, c, d);
    }
  }
  return mesh;
}

}  // namespace

TriangleMesh unit_box_mesh() {
  TriangleMesh mesh;
  for (int axis = 0; axis < 3; ++axis) {
    const Eigen::Vector3f eb = Eigen::Vector3f::Unit((axis + 1) % 3);
    const Eigen::Vector3f ec = Eigen::Vector3f::Unit((axis + 2) % 3);
    for (const float sign : {1.0f, -1.0f}) {
      const Eigen::Vector3f n = sign * Eigen::Vector3f::Unit(axis);
      // (eb, ec, n) is right-handed, so (-,-), (+,-), (+,+), (-,+) in (eb, ec) runs
      // counter-clockwise around +n; the -n face takes the mirror order.
      Eigen::Vector3f corners[4] = {n - eb - ec, n + eb - ec, n + eb + ec, n - eb + ec};
      if (sign < 0.0f) std::swap(corners[1], corners[3]);
      add_triangle(mesh, corners[0], corners[1], corners[2], n, n, n);
      add_triangle(mesh, corners[0], corners[2], corners[3], n, n, n);
    }
  }
  return mesh;
}

TriangleMesh unit_tube_mesh(int segments) {
  check_segments(segments);
  TriangleMesh mesh;
  for (int i = 0; i < segments; ++i) {
    const Eigen::Vector3f n0 = sphere_point(0.0, 2.0 * kPi * i / segments);
    const Eigen::Vector3f n1 = sphere_point(0.0, 2.0 * kPi * (i + 1) / segments);
    const Eigen::Vector3f up = Eigen::Vector3f::UnitZ();
    add_triangle(mesh, n0 - up, n1 - up, n1 + up, n0, n1, n1);
    add_triangle(mesh, n0 - up, n1 + up, n0 + up, n0, n1, n0);
  }
  return mesh;
}

TriangleMesh unit_cylinder_mesh(int segments) {
  TriangleMesh mesh = unit_tube_mesh(segments);
  const Eigen::Vector3f up = Eigen::Vector3f::UnitZ();
  for (int i = 0; i < segments; ++i) {
    const Eigen::Vector3f r0 = sphere_point(0.0, 2.0 * kPi * i / segments);
    const Eigen::Vector3f r1 = sphere_point(0.0, 2.0 * kPi * (i + 1) / segments);
    add_triangle(mesh, up, r0 + up, r1 + up, up, up, up);
    add_triangle(mesh, -up, r1 - up, r0 - up, -up, -up, -up);
  }
  return mesh;
}

TriangleMesh unit_sphere_mesh(int segments) {
  check_segments(segments);
  return sphere_bands(segments, std::max(2, segments / 2), -0.5 * kPi, 0.5 * kPi);
}

TriangleMesh unit_hemisphere_mesh(int segments) {
  check_segments(segments);
  return sphere_bands(segments, std::max(1, segments / 4), 0.0, 0.5 * kPi);
}

}  // namespace corrmp
