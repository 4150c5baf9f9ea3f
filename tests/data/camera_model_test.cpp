// Tests of the head-camera pinhole model: intrinsics from a field of view, look-at
// poses in the OpenCV convention, projection and back-projection.
#include "data/camera_model.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace corrmp {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

constexpr double kPi = 3.14159265358979323846;

TEST(CameraIntrinsics, FromVerticalFovPutsTheImageEdgesAtHalfTheFov) {
  const CameraIntrinsics k = CameraIntrinsics::from_vertical_fov(64, 48, kPi / 2.0);
  EXPECT_DOUBLE_EQ(k.fy, 24.0);  // tan(45 deg) = 1: the top edge is 24 px from the axis
  EXPECT_DOUBLE_EQ(k.fx, k.fy);
  EXPECT_DOUBLE_EQ(k.cx, 31.5);
  EXPECT_DOUBLE_EQ(k.cy, 23.5);
  // A ray fov/2 above the axis meets the top edge of the image (v = -0.5).
  const Eigen::Vector2d top =
      *project(k, Eigen::Isometry3d::Identity(), Eigen::Vector3d(0.0, -1.0, 1.0));
  EXPECT_NEAR(top.y(), -0.5, 1e-12);
}

TEST(CameraIntrinsics, ValidateNamesTheBadField) {
  CameraIntrinsics k = CameraIntrinsics::from_vertical_fov(32, 32, 1.0);
  k.far = k.near;
  EXPECT_THAT([&] { k.validate(); }, ThrowsMessage<std::invalid_argument>(HasSubstr("far")));
  k = CameraIntrinsics::from_vertical_fov(32, 32, 1.0);
  k.width = 0;
  EXPECT_THROW(k.validate(), std::invalid_argument);
  k = CameraIntrinsics::from_vertical_fov(32, 32, 1.0);
  k.fx = -1.0;
  EXPECT_THROW(k.validate(), std::invalid_argument);
  EXPECT_THROW(CameraIntrinsics::from_vertical_fov(32, 32, 0.0), std::invalid_argument);
  EXPECT_THROW(CameraIntrinsics::from_vertical_fov(32, 32, kPi), std::invalid_argument);
}

TEST(LookAt, ZPointsAtTheTargetAndYDownAgainstUp) {
  const Eigen::Vector3d eye(0.0, -1.0, 1.5);
  const Eigen::Vector3d target(0.2, 0.5, 0.7);
  const Eigen::Isometry3d pose = look_at(eye, target, Eigen::Vector3d::UnitZ());
  const Eigen::Matrix3d r = pose.linear();
  EXPECT_TRUE((r.transpose() * r).isIdentity(1e-12));
  EXPECT_NEAR(r.determinant(), 1.0, 1e-12);
  EXPECT_TRUE(pose.translation().isApprox(eye));
  EXPECT_TRUE(r.col(2).isApprox((target - eye).normalized()));
  EXPECT_NEAR(r.col(0).z(), 0.0, 1e-12);  // x stays horizontal
  EXPECT_LT(r.col(1).z(), 0.0);           // y (image down) points downwards in the world
  // The target is seen on the principal point.
  const CameraIntrinsics k = CameraIntrinsics::from_vertical_fov(64, 64, 1.0);
  const Eigen::Vector2d pixel = *project(k, pose, target);
  EXPECT_NEAR(pixel.x(), k.cx, 1e-9);
  EXPECT_NEAR(pixel.y(), k.cy, 1e-9);
}

TEST(LookAt, RejectsDegenerateInput) {
  const Eigen::Vector3d eye(1.0, 2.0, 3.0);
  EXPECT_THROW(look_at(eye, eye, Eigen::Vector3d::UnitZ()), std::invalid_argument);
  EXPECT_THROW(look_at(eye, eye + Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitZ()),
               std::invalid_argument);
}

TEST(Project, FollowsThePinholeFormulaAndRejectsPointsBehind) {
  CameraIntrinsics k;
  k.width = 100;
  k.height = 80;
  k.fx = 120.0;
  k.fy = 110.0;
  k.cx = 48.0;
  k.cy = 41.0;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(1.0, 0.0, 0.0);
  const Eigen::Vector2d pixel = *project(k, pose, Eigen::Vector3d(1.2, -0.1, 2.0));
  EXPECT_NEAR(pixel.x(), 120.0 * 0.2 / 2.0 + 48.0, 1e-12);
  EXPECT_NEAR(pixel.y(), 110.0 * -0.1 / 2.0 + 41.0, 1e-12);
  EXPECT_FALSE(project(k, pose, Eigen::Vector3d(1.0, 0.0, -1.0)).has_value());
  EXPECT_FALSE(project(k, pose, Eigen::Vector3d(2.0, 0.0, 0.0)).has_value());
}

TEST(BackProject, InvertsProjectionAtTheGivenDepth) {
  const CameraIntrinsics k = CameraIntrinsics::from_vertical_fov(64, 48, 0.9);
  const Eigen::Isometry3d pose = look_at(Eigen::Vector3d(0.3, -0.8, 1.2),
                                         Eigen::Vector3d(0.5, 0.1, 0.7), Eigen::Vector3d::UnitZ());
  const Eigen::Vector3d point(0.45, 0.2, 0.65);
  const Eigen::Vector2d pixel = *project(k, pose, point);
  const double depth = (pose.inverse() * point).z();
  EXPECT_TRUE(back_project(k, pose, pixel, depth).isApprox(point, 1e-12));
}

}  // namespace
}  // namespace corrmp
