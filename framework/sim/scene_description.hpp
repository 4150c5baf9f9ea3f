// Scenes described in YAML under assets/scenes/: the table-top bodies of a task
// (table, object, corridor walls, ...) with shapes, poses, colours, masses and
// friction. Read with the strict config reader, so a typo names file:line.
// Paper, Section IV-A (the simulated push-through-corridor set-up).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/config/field_rule.hpp"

namespace corrmp {

struct SceneBodySpec {
  std::string name;
  std::string shape = "box";
  std::vector<double> size;  // box: [x, y, z] full extents; cylinder, capsule: [radius, height]
                             // (along z); sphere: [radius]
  std::vector<double> position{0.0, 0.0, 0.0};
  std::vector<double> rpy{0.0, 0.0, 0.0};  // roll, pitch, yaw in radians
  std::vector<double> colour{0.7, 0.7, 0.7};
  double mass = 0.0;  // 0: static
  double friction = 0.5;
  double restitution = 0.0;

  template <class Fields>
  void describe(Fields& f) {
    f("name", name, "unique name the environment refers to", required());
    f("shape", shape, "primitive shape", one_of({"box", "cylinder", "capsule", "sphere"}));
    f("size", size, "box [x, y, z]; cylinder/capsule [radius, height]; sphere [radius] (m)",
      required().above(0.0));
    f("position", position, "centre [x, y, z] in the world frame (m)");
    f("rpy", rpy, "orientation as roll, pitch, yaw (rad)");
    f("colour", colour, "RGB in [0, 1]", in_range(0.0, 1.0));
    f("mass", mass, "kg; 0 makes the body static", at_least(0.0));
    f("friction", friction, "Coulomb friction coefficient", at_least(0.0));
    f("restitution", restitution, "bounciness", in_range(0.0, 1.0));
  }

  Eigen::Vector3d position_vector() const { return {position[0], position[1], position[2]}; }
};

struct SceneDescription {
  std::vector<SceneBodySpec> bodies;

  template <class Fields>
  void describe(Fields& f) {
    f("bodies", bodies, "the bodies of the scene", required());
  }

  const SceneBodySpec& body(const std::string& name) const;
};

// Loads and validates a scene file (sizes per shape, vector lengths, unique names);
// throws ConfigError naming file:line:column and the key path.
SceneDescription load_scene(const std::string& path);

}  // namespace corrmp
