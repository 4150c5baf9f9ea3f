// Tests of the Bullet world: determinism, resting contact, contact queries,
// blow-up detection, and scene files.
#include "sim/bullet_world.hpp"

#include <gtest/gtest.h>

#include "config/test_files.hpp"
#include "core/config/config_error.hpp"

namespace corrmp {
namespace {

SceneBodySpec body(const std::string& name, std::vector<double> size, std::vector<double> position,
                   double mass) {
  SceneBodySpec spec;
  spec.name = name;
  spec.size = std::move(size);
  spec.position = std::move(position);
  spec.mass = mass;
  return spec;
}

SceneDescription table_and_box() {
  SceneDescription scene;
  scene.bodies.push_back(body("table", {1.0, 1.0, 0.04}, {0, 0, -0.02}, 0.0));
  scene.bodies.push_back(body("box", {0.04, 0.04, 0.04}, {0.01, 0.02, 0.1}, 0.2));
  return scene;
}

TEST(BulletWorld, ABoxFallsOntoTheTableAndRestsThereTouchingIt) {
  BulletWorld world(PhysicsParams{});
  world.add_scene(table_and_box());
  const int box = world.find("box"), table = world.find("table");
  for (int i = 0; i < 480; ++i) world.step();
  EXPECT_NEAR(world.position(box).z(), 0.02, 2e-3);
  EXPECT_NEAR(world.position(box).x(), 0.01, 1e-4);
  EXPECT_LT(world.linear_velocity(box).norm(), 1e-3);
  EXPECT_TRUE(world.touching(box, table));
  EXPECT_NEAR(world.time(), 2.0, 1e-9);
  EXPECT_EQ(world.blow_up(), "");
}

TEST(BulletWorld, SameSceneAndStepsGiveIdenticalStates) {
  auto simulate = [] {
    BulletWorld world(PhysicsParams{});
    world.add_scene(table_and_box());
    SceneBodySpec pusher = body("pusher", {0.02, 0.02, 0.02}, {-0.05, 0.02, 0.02}, 0.0);
    const int p = world.add_body(pusher, true);
    for (int i = 0; i < 400; ++i) {
      Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
      pose.translation() = Eigen::Vector3d(-0.05 + 0.0004 * i, 0.02, 0.02);
      world.set_pose(p, pose);
      world.step();
    }
    return world.pose(world.find("box")).matrix();
  };
  const Eigen::Matrix4d first = simulate();
  EXPECT_EQ(first, simulate());
  EXPECT_GT(first(0, 3), 0.05);  // the kinematic pusher moved the box
}

TEST(BulletWorld, BlowUpsAreReportedNotCrashes) {
  BulletWorld world(PhysicsParams{});
  world.add_scene(table_and_box());
  Eigen::Isometry3d far = Eigen::Isometry3d::Identity();
  far.translation() = Eigen::Vector3d(1e3, 0, 0);
  world.place(world.find("box"), far);
  EXPECT_NE(world.blow_up().find("physics blow-up: body 'box'"), std::string::npos);
  Eigen::Isometry3d nan = Eigen::Isometry3d::Identity();
  nan.translation() = Eigen::Vector3d(std::nan(""), 0, 0);
  world.place(world.find("box"), nan);
  EXPECT_NE(world.blow_up().find("non-finite"), std::string::npos);
}

TEST(SceneDescription, LoadsTheCorridorSceneAndRejectsBadFiles) {
  const SceneDescription scene =
      load_scene(std::string(PROJECT_DIR) + "/assets/scenes/corridor.yaml");
  EXPECT_EQ(scene.body("object").mass, 0.2);
  EXPECT_EQ(scene.body("corridor_left").size.size(), 3u);
  testing::TempDir dir;
  const auto bad = dir.write("s.yaml", "bodies:\n  - {name: a, shape: sphere, size: [1, 2]}\n");
  EXPECT_EQ(testing::config_error_of([&] { load_scene(bad); }),
            bad + ":2:36: bodies[0].size: a sphere needs 1 sizes, got 2");
  const auto typo =
      dir.write("t.yaml", "bodies:\n  - {name: a, size: [1, 1, 1], colr: [1, 0, 0]}\n");
  EXPECT_NE(testing::config_error_of([&] { load_scene(typo); }).find("did you mean 'colour'"),
            std::string::npos);
}

}  // namespace
}  // namespace corrmp
