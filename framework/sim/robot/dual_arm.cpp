// The dual-arm executor: inverse kinematics per arm, joint control of the whole robot.
#include "sim/robot/dual_arm.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <optional>
#include <utility>
#include <vector>

#include "core/config/config_error.hpp"

namespace corrmp {

namespace {

// A relative URDF path is taken from the working directory when it exists
// there, else from the source tree (as the scene files are).
std::string resolve_urdf(const std::string& path) {
  if (path.empty() || std::filesystem::path(path).is_absolute() || std::filesystem::exists(path))
    return path;
  const auto in_tree = std::filesystem::path(CORRMP_SOURCE_DIR) / path;
  return std::filesystem::exists(in_tree) ? in_tree.string() : path;
}

const char* arm_name(Arm arm) { return arm == Arm::left ? "left" : "right"; }

// `top` and the links below it, through fixed joints only when `fixed_only`,
// in model order.
std::vector<std::string> links_below(const RobotModel& model, const std::string& top,
                                     bool fixed_only) {
  std::vector<std::string> links{top};
  for (const RobotJoint& joint : model.joints) {
    if (fixed_only && joint.type != JointType::fixed) continue;
    if (std::find(links.begin(), links.end(), joint.parent) != links.end())
      links.push_back(joint.child);
  }
  return links;
}

const char* category_of(IkResult::Status status) {
  return status == IkResult::Status::joint_limit ? "joint limit" : "out of reach";
}

}  // namespace

struct DualArm::ArmState {
  ArmState(const RobotModel& model, const std::string& base, const std::string& tool,
           const IkParams& ik)
      : tool(tool), kinematics(model, base, tool, ik) {}

  std::string tool;
  int tool_link = -1;  // index into the model's links
  ArmKinematics kinematics;
  Eigen::VectorXd home;
  std::vector<int> joints;   // index of each arm joint in the robot's joint vector
  Eigen::VectorXd solution;  // the last IK solution: the next warm start
  // The target (base frame) `solution` solves in track(); unset after a reset or placement.
  std::optional<Eigen::Isometry3d> solved_target;
  Eigen::Matrix3d orientation = Eigen::Matrix3d::Identity();  // tool to world
  std::vector<std::string> links, hand;
};

DualArm::DualArm(const DualArmParams& params, double time_step) : params_(params) {
  const std::string urdf = resolve_urdf(params.urdf);
  if (!std::filesystem::is_regular_file(urdf)) {
    throw ConfigError(
        fmt::format("{}: {}", params.urdf,
                    std::filesystem::exists(urdf) ? "is not a regular file" : "no such URDF file"));
  }
  model_ = load_robot_model(urdf);
  for (const RobotLink& link : model_.links) shape_count_ += link.collisions.size();
  if (params.base_position.size() != 3) {
    throw ConfigError(fmt::format("{}: base_position has {} values, not 3", params.urdf,
                                  params.base_position.size()));
  }
  // The robot's controller runs at the task's tick; a different one asked for
  // (the default aside, which cannot be told from no value) would be ignored.
  if (params.control.time_step != RobotDynamicsParams{}.time_step &&
      params.control.time_step != time_step) {
    throw ConfigError(
        fmt::format("{}: control.time_step {:.6g} s: the robot steps at the task's tick ({:.6g} "
                    "s); leave it out",
                    params.urdf, params.control.time_step, time_step));
  }
  RobotDynamicsParams control = params.control;
  control.time_step = time_step;
  Eigen::Isometry3d root = Eigen::Isometry3d::Identity();
  root.translation() =
      Eigen::Vector3d(params.base_position[0], params.base_position[1], params.base_position[2]);
  try {
    std::vector<std::pair<std::string, std::string>> allowed;
    const std::vector<std::string>& touching = params.touching_links;
    for (size_t i = 0; i < touching.size(); ++i) {
      for (size_t j = i + 1; j < touching.size(); ++j)
        allowed.emplace_back(touching[i], touching[j]);
    }
    dynamics_ = std::make_unique<RobotDynamics>(model_, control, root, allowed);
  } catch (const std::invalid_argument& e) {
    throw ConfigError(fmt::format("{}: {}", params.urdf, e.what()));
  }
  base_link_ = dynamics_->link_index(params.base_link);
  const std::string* tools[2] = {&params.left_tool, &params.right_tool};
  const std::vector<double>* homes[2] = {&params.left_home, &params.right_home};
  for (Arm arm : {Arm::left, Arm::right}) {
    const int a = static_cast<int>(arm);
    auto state = std::make_unique<ArmState>(model_, params.base_link, *tools[a], params.ik);
    const ArmKinematics& kinematics = state->kinematics;
    const std::vector<double>& home = *homes[a];
    if (static_cast<int>(home.size()) != kinematics.joints()) {
      throw ConfigError(fmt::format("{}: {}_home has {} values, the {} arm has {} joints",
                                    params.urdf, arm_name(arm), home.size(), arm_name(arm),
                                    kinematics.joints()));
    }
    state->tool_link = dynamics_->link_index(*tools[a]);
    state->home = Eigen::Map<const Eigen::VectorXd>(home.data(), kinematics.joints());
    for (int j = 0; j < kinematics.joints(); ++j) {
      const std::string& joint = kinematics.joint_names()[j];
      if (state->home[j] < kinematics.lower()[j] || state->home[j] > kinematics.upper()[j]) {
        throw ConfigError(fmt::format(
            "{}: {}_home[{}] = {} is outside joint '{}''s limits [{}, {}]", params.urdf,
            arm_name(arm), j, state->home[j], joint, kinematics.lower()[j], kinematics.upper()[j]));
      }
      state->joints.push_back(dynamics_->joint_index(joint));
    }
    const std::vector<int> chain = model_.chain(params.base_link, *tools[a]);
    std::vector<int> movable;
    for (int j : chain)
      if (model_.joints[j].type != JointType::fixed) movable.push_back(j);
    state->links = links_below(model_, model_.joints[movable.front()].child, false);
    state->hand = links_below(model_, model_.joints[movable.back()].child, true);
    state->hand.erase(state->hand.begin());
    arms_[a] = std::move(state);
  }
  reset();
}

DualArm::~DualArm() = default;

void DualArm::reset() {
  Eigen::VectorXd q = Eigen::VectorXd::Zero(dynamics_->dof());
  for (const auto& arm : arms_) {
    for (size_t j = 0; j < arm->joints.size(); ++j) q[arm->joints[j]] = arm->home[j];
  }
  dynamics_->reset(q);
  const Eigen::Isometry3d base = dynamics_->link_pose(base_link_);
  for (const auto& arm : arms_) {
    arm->solution = arm->home;
    arm->solved_target.reset();
    arm->orientation = base.linear() * arm->kinematics.forward(arm->home).linear();
  }
  max_tracking_error_ = 0.0;
  failure_detail_.clear();
}

void DualArm::set_tool_orientation(Arm arm, const Eigen::Matrix3d& orientation) {
  arms_[static_cast<int>(arm)]->orientation = orientation;
}

std::string DualArm::place_tool(Arm arm, const Eigen::Vector3d& position) {
  ArmState& state = *arms_[static_cast<int>(arm)];
  Eigen::Isometry3d target = Eigen::Isometry3d::Identity();
  target.linear() = state.orientation;
  target.translation() = position;
  const IkResult result =
      state.kinematics.solve(dynamics_->link_pose(base_link_).inverse() * target, state.solution);
  if (result.status != IkResult::Status::ok) {
    failure_detail_ = fmt::format(
        "{} arm: no joint positions for the tool at ({:.3f}, {:.3f}, "
        "{:.3f}) m ({})",
        arm_name(arm), position.x(), position.y(), position.z(), to_string(result.status));
    return category_of(result.status);
  }
  Eigen::VectorXd q = dynamics_->targets();
  for (size_t j = 0; j < state.joints.size(); ++j) q[state.joints[j]] = result.q[j];
  dynamics_->reset(q);
  state.solution = result.q;
  state.solved_target.reset();
  failure_detail_.clear();
  return "";
}

std::string DualArm::track(const Eigen::Vector3d& left_target,
                           const Eigen::Vector3d& right_target) {
  failure_detail_.clear();
  const Eigen::Isometry3d base_inverse = dynamics_->link_pose(base_link_).inverse();
  Eigen::VectorXd q = dynamics_->targets();
  for (Arm arm : {Arm::left, Arm::right}) {
    ArmState& state = *arms_[static_cast<int>(arm)];
    Eigen::Isometry3d target = Eigen::Isometry3d::Identity();
    target.linear() = state.orientation;
    target.translation() = arm == Arm::left ? left_target : right_target;
    const Eigen::Isometry3d in_base = base_inverse * target;
    if (state.solved_target && state.solved_target->matrix() == in_base.matrix()) {
      ++ik_stats_.reused;
      for (size_t j = 0; j < state.joints.size(); ++j) q[state.joints[j]] = state.solution[j];
      continue;
    }
    const auto started = std::chrono::steady_clock::now();
    const IkResult result = state.kinematics.solve(in_base, state.solution);
    ++ik_stats_.solves;
    if (solve_times_) {
      solve_times_->add(
          std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
    }
    if (result.status != IkResult::Status::ok) {
      ++ik_stats_.failures;
      const Eigen::Vector3d& p = target.translation();
      failure_detail_ = fmt::format(
          "{} arm: no joint positions for the tool at ({:.3f}, {:.3f}, {:.3f}) m ({}; closest "
          "{:.3g} m, {:.3g} rad away)",
          arm_name(arm), p.x(), p.y(), p.z(), to_string(result.status), result.position_residual,
          result.orientation_residual);
      return category_of(result.status);
    }
    state.solution = result.q;
    state.solved_target = in_base;
    for (size_t j = 0; j < state.joints.size(); ++j) q[state.joints[j]] = result.q[j];
  }
  dynamics_->set_targets(q);
  dynamics_->step();
  max_tracking_error_ = std::max(
      max_tracking_error_, (dynamics_->positions() - dynamics_->targets()).cwiseAbs().maxCoeff());
  failure_detail_ = dynamics_->failure_detail();
  return dynamics_->check();
}

std::string DualArm::reach(const Eigen::Vector3d& left_target,
                           const Eigen::Vector3d& right_target) const {
  const Eigen::Isometry3d base_inverse = dynamics_->link_pose(base_link_).inverse();
  for (Arm arm : {Arm::left, Arm::right}) {
    const ArmState& state = *arms_[static_cast<int>(arm)];
    Eigen::Isometry3d target = Eigen::Isometry3d::Identity();
    target.linear() = state.orientation;
    target.translation() = arm == Arm::left ? left_target : right_target;
    const IkResult result = state.kinematics.solve(base_inverse * target, state.solution);
    if (result.status != IkResult::Status::ok) {
      const Eigen::Vector3d& p = target.translation();
      return fmt::format(
          "{}: {} arm: no joint positions for the tool at ({:.3f}, {:.3f}, {:.3f}) m",
          category_of(result.status), arm_name(arm), p.x(), p.y(), p.z());
    }
  }
  return "";
}

double DualArm::time() const { return dynamics_->time(); }

Eigen::Isometry3d DualArm::tool_pose(Arm arm) const {
  return dynamics_->link_pose(arms_[static_cast<int>(arm)]->tool_link);
}

const std::vector<std::string>& DualArm::arm_links(Arm arm) const {
  return arms_[static_cast<int>(arm)]->links;
}

const std::vector<std::string>& DualArm::hand_links(Arm arm) const {
  return arms_[static_cast<int>(arm)]->hand;
}

std::vector<PlacedShape> DualArm::shapes() const {
  const std::vector<Eigen::Isometry3d> poses = shape_poses();
  std::vector<PlacedShape> placed;
  for (const RobotLink& link : model_.links) {
    for (const RobotShape& shape : link.collisions) {
      placed.push_back({link.name, shape});
      placed.back().shape.origin = poses.at(placed.size() - 1);
    }
  }
  return placed;
}

std::vector<Eigen::Isometry3d> DualArm::shape_poses() const {
  std::vector<Eigen::Isometry3d> poses;
  poses.reserve(shape_count_);
  for (size_t i = 0; i < model_.links.size(); ++i) {
    const RobotLink& link = model_.links[i];
    if (link.collisions.empty()) continue;
    const Eigen::Isometry3d pose = dynamics_->link_pose(static_cast<int>(i));
    for (const RobotShape& shape : link.collisions) poses.push_back(pose * shape.origin);
  }
  return poses;
}

}  // namespace corrmp
