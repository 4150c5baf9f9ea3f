// Tests of the unit primitive meshes: closed where they should be, outward winding,
// unit normals, vertices on the unit surfaces.
#include "sim/render/unit_meshes.hpp"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <cmath>
#include <stdexcept>

namespace corrmp {
namespace {

// Signed volume by the divergence theorem: positive for a closed, outward-wound mesh.
double signed_volume(const TriangleMesh& mesh) {
  double volume = 0.0;
  for (size_t i = 0; i < mesh.positions.size(); i += 3) {
    const Eigen::Vector3d a = mesh.positions[i].cast<double>();
    const Eigen::Vector3d b = mesh.positions[i + 1].cast<double>();
    const Eigen::Vector3d c = mesh.positions[i + 2].cast<double>();
    volume += a.dot(b.cross(c)) / 6.0;
  }
  return volume;
}

// Every triangle's geometric normal agrees with its vertex normals (outward winding),
// and every vertex normal has unit length.
void expect_consistent_normals(const TriangleMesh& mesh) {
  ASSERT_EQ(mesh.positions.size(), mesh.normals.size());
  ASSERT_EQ(mesh.positions.size() % 3, 0u);
  for (size_t i = 0; i < mesh.positions.size(); i += 3) {
    const Eigen::Vector3f face = (mesh.positions[i + 1] - mesh.positions[i])
                                     .cross(mesh.positions[i + 2] - mesh.positions[i]);
    ASSERT_GT(face.norm(), 0.0f) << "degenerate triangle " << i / 3;
    for (size_t j = i; j < i + 3; ++j) {
      EXPECT_NEAR(mesh.normals[j].norm(), 1.0f, 1e-5f);
      EXPECT_GT(face.dot(mesh.normals[j]), 0.0f) << "triangle " << i / 3 << " is wound inwards";
    }
  }
}

TEST(UnitMeshes, BoxIsTheClosedCubeOfSide2) {
  const TriangleMesh box = unit_box_mesh();
  EXPECT_EQ(box.positions.size(), 36u);
  EXPECT_NEAR(signed_volume(box), 8.0, 1e-5);
  expect_consistent_normals(box);
  for (const Eigen::Vector3f& p : box.positions) EXPECT_FLOAT_EQ(p.cwiseAbs().maxCoeff(), 1.0f);
}

TEST(UnitMeshes, CylinderIsClosedAndApproachesPiTimes2) {
  const TriangleMesh cylinder = unit_cylinder_mesh(16);
  // A regular 16-gon of circumradius 1 has area 8 sin(2 pi / 16).
  EXPECT_NEAR(signed_volume(cylinder), 2.0 * 8.0 * std::sin(2.0 * EIGEN_PI / 16.0), 1e-4);
  expect_consistent_normals(cylinder);
  EXPECT_EQ(unit_tube_mesh(16).positions.size(), 16u * 6u);
}

TEST(UnitMeshes, SphereAndHemispheresLieOnTheUnitSphere) {
  const TriangleMesh sphere = unit_sphere_mesh(16);
  expect_consistent_normals(sphere);
  const double volume = signed_volume(sphere);
  EXPECT_GT(volume, 0.85 * 4.0 / 3.0 * EIGEN_PI);
  EXPECT_LT(volume, 4.0 / 3.0 * EIGEN_PI);
  for (const Eigen::Vector3f& p : sphere.positions) EXPECT_NEAR(p.norm(), 1.0f, 1e-5f);

  const TriangleMesh hemisphere = unit_hemisphere_mesh(16);
  expect_consistent_normals(hemisphere);
  for (const Eigen::Vector3f& p : hemisphere.positions) {
    EXPECT_NEAR(p.norm(), 1.0f, 1e-5f);
    EXPECT_GE(p.z(), 0.0f);
  }
}

TEST(UnitMeshes, RejectFewerThanThreeSegments) {
  EXPECT_THROW(unit_cylinder_mesh(2), std::invalid_argument);
  EXPECT_THROW(unit_sphere_mesh(2), std::invalid_argument);
  EXPECT_THROW(unit_hemisphere_mesh(0), std::invalid_argument);
  EXPECT_NO_THROW(unit_sphere_mesh(3));
}

}  // namespace
}  // namespace corrmp
