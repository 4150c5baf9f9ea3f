#include "sim/robot/robot_model.hpp"

#include <tinyxml.h>
#include <urdf_parser/urdf_parser.h>

#include <console_bridge/console.h>

#include <mutex>

#include "core/config/config_error.hpp"
#include "core/file_error.hpp"
#include "core/file_read.hpp"

namespace corrmp {
namespace {

// Keeps the first error urdfdom reports through console_bridge (its only
// channel for what is wrong); warnings and below are dropped.
class FirstErrorCapture : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR && first_error.empty())
      first_error = text;
  }
  std::string first_error;
};

// console_bridge's handler is process-wide, so parses take turns.
urdf::ModelInterfaceSharedPtr parse_capturing_errors(const std::string& text, std::string& error) {
  static std::mutex parse_mutex;
  std::lock_guard<std::mutex> lock(parse_mutex);
  FirstErrorCapture capture;
  console_bridge::useOutputHandler(&capture);
  urdf::ModelInterfaceSharedPtr model;
  try {
    model = urdf::parseURDF(text);
  } catch (...) {
    console_bridge::restorePreviousOutputHandler();
    throw;
  }
  console_bridge::restorePreviousOutputHandler();
  error = capture.first_error.empty() ? "not a valid URDF robot" : capture.first_error;
  return model;
}

Eigen::Isometry3d isometry_of(const urdf::Pose& pose) {
  Eigen::Isometry3d result = Eigen::Isometry3d::Identity();
  result.translation() << pose.position.x, pose.position.y, pose.position.z;
  result.linear() =
      Eigen::Quaterniond(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z)
          .normalized()
          .toRotationMatrix();
  return result;
}

class Reader {
 public:
  Reader(std::string path, const urdf::ModelInterface& urdf)
      : path_(std::move(path)), urdf_(urdf) {}

  [[noreturn]] void fail(const std::string& what) const { throw ConfigError(path_ + ": " + what); }

  RobotShape shape_of(const std::string& link, const urdf::GeometrySharedPtr& geometry,
                      const urdf::Pose& origin) const {
    if (!geometry) fail("link '" + link + "': a shape without geometry");
    RobotShape shape;
    shape.origin = isometry_of(origin);
    switch (geometry->type) {
      case urdf::Geometry::BOX: {
        const auto& box = static_cast<const urdf::Box&>(*geometry);
        shape.kind = RobotShape::Kind::box;
        shape.size << box.dim.x, box.dim.y, box.dim.z;
        break;
      }
      case urdf::Geometry::CYLINDER: {
        const auto& cylinder = static_cast<const urdf::Cylinder&>(*geometry);
        shape.kind = RobotShape::Kind::cylinder;
        shape.size << cylinder.radius, cylinder.length, 0.0;
        break;
      }
      case urdf::Geometry::SPHERE: {
        shape.kind = RobotShape::Kind::sphere;
        shape.size << static_cast<const urdf::Sphere&>(*geometry).radius, 0.0, 0.0;
        break;
      }
      default:
        fail("link '" + link + "': mesh geometry is not supported (use box, cylinder or sphere)");
    }
    const int dimensions = shape.kind == RobotShape::Kind::box        ? 3
                           : shape.kind == RobotShape::Kind::cylinder ? 2
                                                                      : 1;
    if (!(shape.size.head(dimensions).array() > 0.0).all())
      fail("link '" + link + "': a shape with a size that is not positive");
    return shape;
  }

  // A visual's colour: its own material, else the robot's material of that name.
  Eigen::Vector3f colour_of(const urdf::Visual& visual, const Eigen::Vector3f& fallback) const {
    urdf::MaterialSharedPtr material = visual.material;
    if (!material && !visual.material_name.empty())
      material = urdf_.getMaterial(visual.material_name);
    if (!material) return fallback;
    const urdf::Color& c = material->color;
    return Eigen::Vector3f(c.r, c.g, c.b).cwiseMax(0.0f).cwiseMin(1.0f);
  }

  // Collision shapes take the colour of the link's first visual.
  RobotLink link_of(const urdf::Link& source) const {
    RobotLink link;
    link.name = source.name;
    if (source.inertial) {
      const urdf::Inertial& in = *source.inertial;
      if (!(in.mass >= 0.0)) fail("link '" + link.name + "': negative mass");
      link.mass = in.mass;
      link.inertial_origin = isometry_of(in.origin);
      link.inertia << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
    }
    for (const auto& visual : source.visual_array) {
      if (!visual) continue;
      RobotShape shape = shape_of(link.name, visual->geometry, visual->origin);
      shape.colour = colour_of(*visual, shape.colour);
      link.visuals.push_back(shape);
    }
    for (const auto& collision : source.collision_array) {
      if (!collision) continue;
      RobotShape shape = shape_of(link.name, collision->geometry, collision->origin);
      if (!link.visuals.empty()) shape.colour = link.visuals.front().colour;
      link.collisions.push_back(shape);
    }
    return link;
  }

  RobotJoint joint_of(const urdf::Joint& source) const {
    const std::string where = "joint '" + source.name + "': ";
    RobotJoint joint;
    joint.name = source.name;
    joint.parent = source.parent_link_name;
    joint.child = source.child_link_name;
    joint.origin = isometry_of(source.parent_to_joint_origin_transform);
    switch (source.type) {
      case urdf::Joint::FIXED:
        joint.type = JointType::fixed;
        return joint;
      case urdf::Joint::REVOLUTE:
        joint.type = JointType::revolute;
        break;
      case urdf::Joint::PRISMATIC:
        joint.type = JointType::prismatic;
        break;
      case urdf::Joint::CONTINUOUS:
        // Inverse kinematics and joint control need position limits.
        fail(where + "continuous joints are not supported (use revolute with limits)");
      case urdf::Joint::FLOATING:
        fail(where + "floating joints are not supported (fixed, revolute or prismatic)");
      case urdf::Joint::PLANAR:
        fail(where + "planar joints are not supported (fixed, revolute or prismatic)");
      default:
        fail(where + "unsupported joint type (fixed, revolute or prismatic)");
    }
    const Eigen::Vector3d axis(source.axis.x, source.axis.y, source.axis.z);
    if (!(axis.norm() > 1e-9)) fail(where + "zero axis");
    joint.axis = axis.normalized();
    if (!source.limits) fail(where + "a movable joint without limits");
    const urdf::JointLimits& limits = *source.limits;
    if (!(limits.lower < limits.upper))
      fail(where + "lower limit " + std::to_string(limits.lower) + " is not below upper limit " +
           std::to_string(limits.upper));
    if (!(limits.velocity > 0.0)) fail(where + "velocity limit must be positive");
    if (!(limits.effort > 0.0)) fail(where + "effort limit must be positive");
    joint.lower = limits.lower;
    joint.upper = limits.upper;
    joint.velocity = limits.velocity;
    joint.effort = limits.effort;
    return joint;
  }

  // Links and joints depth first from the root, so every joint follows the one
  // that made its parent link.
  void add_subtree(const urdf::Link& link, RobotModel& model) const {
    model.links.push_back(link_of(link));
    for (const auto& joint : link.child_joints) {
      model.joints.push_back(joint_of(*joint));
      const urdf::LinkConstSharedPtr child = urdf_.getLink(joint->child_link_name);
      if (!child) fail("joint '" + joint->name + "': missing child link");
      add_subtree(*child, model);
    }
  }

 private:
  std::string path_;
  const urdf::ModelInterface& urdf_;
};

std::string read_urdf_text(const std::string& path) {
  try {
    return read_whole_file(path);
  } catch (const FileError& error) {
    throw ConfigError(error.what());
  }
}

void check_xml(const std::string& path, const std::string& text) {
  TiXmlDocument document;
  document.Parse(text.c_str());
  if (document.Error())
    throw ConfigError(path + ": malformed XML at line " + std::to_string(document.ErrorRow()) +
                      ", column " + std::to_string(document.ErrorCol()) + ": " +
                      document.ErrorDesc());
}

}  // namespace

int RobotModel::link_index(const std::string& link) const {
  for (size_t i = 0; i < links.size(); ++i)
    if (links[i].name == link) return static_cast<int>(i);
  return -1;
}

int RobotModel::joint_index(const std::string& joint) const {
  for (size_t i = 0; i < joints.size(); ++i)
    if (joints[i].name == joint) return static_cast<int>(i);
  return -1;
}

std::vector<int> RobotModel::chain(const std::string& base, const std::string& tip) const {
  auto fail = [&](const std::string& why) -> std::vector<int> {
    throw ConfigError(source + ": no chain from '" + base + "' to '" + tip + "' (" + why + ")");
  };
  if (link_index(base) < 0) return fail("no link '" + base + "'");
  if (link_index(tip) < 0) return fail("no link '" + tip + "'");
  std::vector<int> upward;
  std::string link = tip;
  while (link != base) {
    int parent_joint = -1;
    for (size_t j = 0; j < joints.size(); ++j)
      if (joints[j].child == link) parent_joint = static_cast<int>(j);
    if (parent_joint < 0) return fail("'" + tip + "' is not below '" + base + "'");
    upward.push_back(parent_joint);
    link = joints[parent_joint].parent;
  }
  return std::vector<int>(upward.rbegin(), upward.rend());
}

RobotModel load_robot_model(const std::string& path) {
  const std::string text = read_urdf_text(path);
  check_xml(path, text);
  std::string error;
  const urdf::ModelInterfaceSharedPtr urdf = parse_capturing_errors(text, error);
  if (!urdf || !urdf->getRoot()) throw ConfigError(path + ": invalid URDF: " + error);
  RobotModel model;
  model.name = urdf->getName();
  model.source = path;
  model.root = urdf->getRoot()->name;
  Reader(path, *urdf).add_subtree(*urdf->getRoot(), model);
  return model;
}

}  // namespace corrmp
