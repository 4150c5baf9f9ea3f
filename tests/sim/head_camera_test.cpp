// Tests of the head camera over a Bullet world: bodies appear in their colours
// where the pinhole model puts them, with the right depth.
#include "sim/head_camera.hpp"

#include <gtest/gtest.h>

namespace corrmp {
namespace {

TEST(HeadCamera, SeesTheCorridorSceneObjectInItsColourAtItsDepth) {
  BulletWorld world(PhysicsParams{});
  world.add_scene(load_scene(std::string(PROJECT_DIR) + "/assets/scenes/corridor.yaml"));
  HeadCameraParams params;
  params.width = params.height = 96;
  HeadCamera camera(params);
  const RgbdImage image = camera.capture(world);
  ASSERT_EQ(image.rgb.rows, 96);
  const Eigen::Vector3d top_of_object(0.45, -0.20, 0.04);
  const auto pixel = project(camera.intrinsics(), camera.world_from_camera(), top_of_object);
  ASSERT_TRUE(pixel.has_value());
  const int u = static_cast<int>(std::lround(pixel->x())),
            v = static_cast<int>(std::lround(pixel->y()));
  const cv::Vec3b rgb = image.rgb.at<cv::Vec3b>(v, u);
  EXPECT_GT(rgb[0], 2 * rgb[1]) << "expected the red object at (" << u << ", " << v << ")";
  EXPECT_GT(rgb[0], 2 * rgb[2]);
  const double expected_depth = (camera.world_from_camera().inverse() * top_of_object).z();
  EXPECT_NEAR(image.depth.at<float>(v, u), expected_depth, 0.01);
  // A corridor wall is blue.
  const auto wall =
      project(camera.intrinsics(), camera.world_from_camera(), Eigen::Vector3d(0.408, 0.12, 0.04));
  ASSERT_TRUE(wall.has_value());
  const cv::Vec3b blue = image.rgb.at<cv::Vec3b>(static_cast<int>(std::lround(wall->y())),
                                                 static_cast<int>(std::lround(wall->x())));
  EXPECT_GT(blue[2], 2 * blue[0]);
}

}  // namespace
}  // namespace corrmp
