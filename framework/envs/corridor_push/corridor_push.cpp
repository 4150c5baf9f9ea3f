// The push-through-corridor environment.
#include "envs/corridor_push/corridor_push.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "core/parameter_error.hpp"
#include "sim/robot/arm_gripper.hpp"
#include "sim/robot/base_offset.hpp"
#include "sim/robot/robot_run_metrics.hpp"

namespace corrmp {

namespace {

// The task's own failure reasons start with these (its failure categories on the arms).
constexpr const char* kTouchedCorridor = "the object touched the corridor";
constexpr const char* kStoppedShort = "the object stopped";

// Scene files are looked up relative to the working directory, then to the
// source tree, so configs work from any directory.
std::string resolve_asset(const std::string& path) {
  if (std::filesystem::exists(path) || std::filesystem::path(path).is_absolute()) return path;
  const auto in_tree = std::filesystem::path(CORRMP_SOURCE_DIR) / path;
  return std::filesystem::exists(in_tree) ? in_tree.string() : path;
}

// The scene file with the bodies the task needs; a missing or incomplete one is refused at
// load, naming the config key.
SceneDescription load_task_scene(const std::string& configured) {
  const std::string path = resolve_asset(configured);
  if (!std::filesystem::is_regular_file(path)) {
    throw ParameterError(
        "scene",
        fmt::format("scene file '{}' {}", configured,
                    std::filesystem::exists(path) ? "is not a regular file" : "does not exist"));
  }
  SceneDescription scene = load_scene(path);
  for (const char* body : {"corridor_left", "corridor_right", "object", "table"}) {
    const bool present = std::any_of(scene.bodies.begin(), scene.bodies.end(),
                                     [&](const SceneBodySpec& b) { return b.name == body; });
    if (!present) {
      throw ParameterError(
          "scene", fmt::format("scene file '{}' has no body called '{}'", configured, body));
    }
  }
  return scene;
}

// The tool pointing down (tool z = world -z), its fingers closing along world x.
Eigen::Matrix3d fingers_down() { return Eigen::Vector3d(1.0, -1.0, -1.0).asDiagonal(); }

}  // namespace

CorridorPush::CorridorPush(const CorridorPushParams& params)
    : params_(params), scene_(load_task_scene(params.scene)) {
  if (moves_base(params.base_offset_range) && !params.robot.on_arms()) {
    throw ParameterError("base_offset_range",
                         "base_offset_range moves the robot's base: it needs robot.type dual_arm");
  }
  const double left = scene_.body("corridor_left").position[0];
  const double right = scene_.body("corridor_right").position[0];
  nominal_corridor_x_ = (left + right) / 2;
  reset(Scenario{{"corridor_offset", 0.0}, {"object_dx", 0.0}, {"object_dy", 0.0}});
}

CorridorPush::~CorridorPush() = default;

std::unique_ptr<Environment> CorridorPush::clone() const {
  auto copy = std::make_unique<CorridorPush>(params_);
  copy->ik_times_ = ik_times_;
  return copy;
}

TaskReport CorridorPush::report() const {
  TaskReport report;
  report.trajectory_columns = {"x", "y", "z"};
  report.error_unit = "cm";  // the paper's Table II; trajectories are in metres
  report.error_scale = 100.0;
  report.error_segments = {"cor", "post"};  // the paper's Table II
  report.decision_segment = "cor";
  report.decision_labels = {"push", "none", "pull"};
  report.plot_horizontal = 1;  // top view: y to the right, x up
  report.plot_vertical = 0;
  if (params_.robot.on_arms()) {
    report.failure_categories = {"out of reach",   "joint limit",   "self collision",
                                 "tracking error", "physics fault", kBlowUpFailure,
                                 kTouchedCorridor, kStoppedShort};
  }
  return report;
}

Scenario CorridorPush::sample_scenario(Rng& rng) const {
  const double half = params_.corridor_range / 2;
  Scenario scenario{{"corridor_offset", rng.uniform(-half, half)}};
  const double noise = params_.object_noise;
  scenario["object_dx"] = noise > 0 ? rng.uniform(-noise, noise) : 0.0;
  scenario["object_dy"] = noise > 0 ? rng.uniform(-noise, noise) : 0.0;
  draw_base_offset(params_.base_offset_range, rng, scenario);
  return scenario;
}

void CorridorPush::reset(const Scenario& scenario) {
  scenario_ = scenario;
  gripper_.reset();
  robot_.reset();
  world_ = std::make_unique<BulletWorld>(params_.physics);
  SceneDescription scene = scene_;
  for (auto& body : scene.bodies) {
    if (body.name == "corridor_left" || body.name == "corridor_right") {
      body.position[0] += scenario.at("corridor_offset");
    } else if (body.name == "object") {
      body.position[0] += scenario.at("object_dx");
      body.position[1] += scenario.at("object_dy");
    }
  }
  world_->add_scene(scene);
  object_ = world_->find("object");
  wall_left_ = world_->find("corridor_left");
  wall_right_ = world_->find("corridor_right");
  touched_corridor_ = false;
  failure_.clear();
  executed_.resize(0, 3);
  if (params_.robot.on_arms()) {
    // A fresh robot every reset, as the world is, so every trial replays alike; its base
    // moved by the scenario's offset (the scene stays where it is in the world).
    robot_ =
        build_robot(with_base_offset(params_.robot.dual_arm, scenario), params_.physics.time_step);
    robot_->time_solves_into(ik_times_);
    const Arm arm = params_.robot.driving_arm();
    robot_->set_tool_orientation(arm, fingers_down());
    failure_ = robot_->place_tool(arm, start_position());
    gripper_ = std::make_unique<ArmGripper>(*world_, params_.gripper, *robot_, arm);
  } else {
    gripper_ = std::make_unique<KinematicGripper>(*world_, params_.gripper, start_position());
  }
  for (int i = 0; i < params_.settle_ticks; ++i) world_->step();
}

Eigen::Vector3d CorridorPush::start_position() const {
  const SceneBodySpec& object = scene_.body("object");
  return {object.position[0],
          object.position[1] - object_half_size() - tool_half_width_y() - 2.5 * params_.standoff,
          params_.lift_height};
}

std::vector<SegmentInfo> CorridorPush::segments() const {
  return {{"pre", params_.pre_points}, {"cor", params_.cor_points}, {"post", params_.post_points}};
}

Eigen::RowVectorXd CorridorPush::effector_position() const {
  return gripper_->position().transpose();
}

std::string CorridorPush::execute(const std::string&, const Eigen::MatrixXd& trajectory) {
  executed_.resize(0, 3);
  if (!failure_.empty()) return failure_;
  const TrackingResult result = gripper_->follow(trajectory, [&] {
    if (world_->touching(object_, wall_left_) || world_->touching(object_, wall_right_)) {
      touched_corridor_ = true;
    }
    return std::string();
  });
  executed_ = result.reached;
  if (!result.ok) {
    failure_ = result.failure;
    return failure_;
  }
  for (int i = 0; i < params_.settle_ticks && failure_.empty(); ++i) {
    world_->step();
    failure_ = world_->blow_up();
  }
  return failure_;
}

std::vector<std::string> CorridorPush::state_names() const {
  return {"corridor_x", "corridor_y", "gripper_x", "gripper_y",
          "gripper_z",  "object_x",   "object_y"};
}

Observation CorridorPush::observe(bool with_image) {
  Observation observation;
  const Eigen::Vector3d tool = gripper_->position();
  const Eigen::Vector3d object = object_position();
  observation.state = {{"gripper_x", tool.x()},         {"gripper_y", tool.y()},
                       {"gripper_z", tool.z()},         {"object_x", object.x()},
                       {"object_y", object.y()},        {"corridor_x", corridor_x()},
                       {"corridor_y", corridor_mid_y()}};
  if (with_image) {
    if (!camera_) camera_ = std::make_unique<HeadCamera>(params_.camera);
    RgbdImage image = camera_->capture(*world_);
    observation.rgb = image.rgb;
    observation.depth = image.depth;
  }
  return observation;
}

Outcome CorridorPush::outcome() const {
  Outcome outcome{true, "", {}, {}};
  if (!failure_.empty()) {
    outcome = {false, failure_, {}, {}};
  } else if (touched_corridor_) {
    outcome = {false, kTouchedCorridor, {}, {}};
  } else if (object_position().y() <= corridor_mid_y()) {
    outcome = {false,
               fmt::format("{} {:.1f} cm before the corridor's midpoint", kStoppedShort,
                           100 * (corridor_mid_y() - object_position().y())),
               {},
               {}};
  }
  if (robot_) add_robot_details(*robot_, outcome.details);
  return outcome;
}

Environment::RunAdditions CorridorPush::run_additions(const std::vector<EvaluatedTrial>& trials,
                                                      const std::string& label) const {
  if (!params_.robot.on_arms()) return {};
  return {robot_run_metrics(trials), ik_time_log_line(*ik_times_, label)};
}

std::string CorridorPush::classify_decision(const Eigen::MatrixXd& trajectory) const {
  const double displacement = trajectory(trajectory.rows() - 1, 0) - trajectory(0, 0);
  const double threshold = params_.tolerance / 2;
  if (displacement > threshold) return "push";
  if (displacement < -threshold) return "pull";
  return "none";
}

double CorridorPush::corridor_x() const {
  return (world_->position(wall_left_).x() + world_->position(wall_right_).x()) / 2;
}

double CorridorPush::corridor_mid_y() const { return world_->position(wall_left_).y(); }

Eigen::Vector3d CorridorPush::object_position() const { return world_->position(object_); }

double CorridorPush::object_half_size() const { return scene_.body("object").size[0] / 2; }

double CorridorPush::tool_half_width_x() const { return params_.gripper.finger_size[0]; }

double CorridorPush::tool_half_width_y() const { return params_.gripper.finger_size[1] / 2; }

}  // namespace corrmp
