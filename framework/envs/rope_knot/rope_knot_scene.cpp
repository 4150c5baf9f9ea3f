// The rope-knotting scene (paper, Section IV-C): set-up, scenario sampling,
// tracking of gripper rows and the knot outcome.
#include "envs/rope_knot/rope_knot_scene.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "sim/robot/base_offset.hpp"
#include "sim/robot/robot_params.hpp"
#include "sim/robot/robot_render.hpp"
#include "sim/soft/soft_render.hpp"

namespace corrmp {

namespace {

Eigen::Vector3d vec3(const std::vector<double>& v, const char* what) {
  if (v.size() != 3)
    throw std::invalid_argument(fmt::format("RopeKnotParams::{}: needs 3 values", what));
  return Eigen::Vector3d(v[0], v[1], v[2]);
}

// Simulated time after a reset the right hand's noise knots cover; it holds
// its last value after that (s).
constexpr double kNoiseHorizon = 60.0;

// The longest the arms may take from home to the start positions (s).
constexpr double kArmTransitTime = 3.0;

double value_or_zero(const Scenario& scenario, const std::string& key) {
  const auto it = scenario.find(key);
  return it == scenario.end() ? 0.0 : it->second;
}

// The seed of the right hand's waypoint noise: a whole number in [0, 2^53].
uint64_t noise_seed(double value) {
  if (!(value >= 0.0 && value <= 9007199254740992.0 && std::floor(value) == value)) {
    throw std::invalid_argument(fmt::format(
        "RopeKnotScene::reset: noise_seed {} is not a whole number in [0, 2^53]", value));
  }
  return static_cast<uint64_t>(value);
}

// The rope nodes of the weight's start and of the right gripper's grasp for a
// scenario's offsets.
struct LoadAndGrasp {
  int load = 0;
  int grasp = 0;
  bool fits(int nodes) const { return load >= 0 && grasp > load + 2 && grasp < nodes - 2; }
};

LoadAndGrasp load_and_grasp(const RopeKnotParams& params, double grasp_offset, double span_offset) {
  const double step = params.rope.length / (params.rope.nodes - 1);
  LoadAndGrasp out;
  out.load = static_cast<int>(std::lround((params.load_arc - span_offset) / step));
  out.grasp = static_cast<int>(std::lround((params.load_arc + params.span + grasp_offset) / step));
  return out;
}

// A list of 3 values per point, with at least one point.
void check_points(const std::vector<double>& v, const char* key) {
  if (v.empty() || v.size() % 3 != 0) {
    throw std::invalid_argument(fmt::format(
        "RopeKnotScene: motion.{} needs 3 values per point and at least one point, got {} values",
        key, v.size()));
  }
}

// Every scenario sample() can draw must fit the rope (reset's condition), at
// the corners of the grasp and span ranges.
void check_scenarios_fit(const RopeKnotParams& params) {
  for (const double grasp_offset : {-params.grasp_range, params.grasp_range}) {
    for (const double span_offset : {-params.span_range, params.span_range}) {
      const LoadAndGrasp nodes = load_and_grasp(params, grasp_offset, span_offset);
      if (!nodes.fits(params.rope.nodes)) {
        throw std::invalid_argument(fmt::format(
            "RopeKnotScene: grasp_range {} and span_range {} (with load_arc, span, rope.length): "
            "at grasp_offset {} and span_offset {} the weight at node {} and grasp node {} do not "
            "fit a rope of {} nodes",
            params.grasp_range, params.span_range, grasp_offset, span_offset, nodes.load,
            nodes.grasp, params.rope.nodes));
      }
    }
  }
}

// Fingers pointing down (-z), closing along x.
Eigen::Matrix3d top_grasp() {
  Eigen::Matrix3d r;
  r << 1, 0, 0, 0, -1, 0, 0, 0, -1;
  return r;
}

// Fingers pointing along +y, closing along x.
Eigen::Matrix3d side_grasp() {
  Eigen::Matrix3d r;
  r << 1, 0, 0, 0, 0, 1, 0, -1, 0;
  return r;
}

}  // namespace

RopeKnotScene::RopeKnotScene(const RopeKnotParams& params) : params_(params) {
  vec3(params.bar_centre, "bar_centre");
  vec3(params.right_start_offset, "right_start_offset");
  vec3(params.left_start_offset, "left_start_offset");
  vec3(params.drift_range, "drift_range");
  const RopeKnotMotion& m = params.motion;
  for (const auto& [key, v] : {std::pair{"pinch_approach", &m.pinch_approach},
                               {"pinch", &m.pinch},
                               {"left_pull", &m.left_pull},
                               {"left_retreat", &m.left_retreat},
                               {"beside_end", &m.beside_end},
                               {"nominal_end", &m.nominal_end},
                               {"tighten", &m.tighten},
                               {"clear", &m.clear}}) {
    vec3(*v, (std::string("motion.") + key).c_str());
  }
  check_points(m.right_loop, "right_loop");
  check_points(m.right_tuck, "right_tuck");
  check_scenarios_fit(params);
  vec3(params.base_offset_range, "base_offset_range");
  if (moves_base(params.base_offset_range) && !params.robot.on_arms()) {
    throw std::invalid_argument(
        "RopeKnotScene: base_offset_range moves the robot's base: it needs robot.type dual_arm");
  }
  if (!(params.waypoint_noise_period > 0.0) || kNoiseHorizon / params.waypoint_noise_period > 1e6) {
    throw std::invalid_argument(fmt::format(
        "RopeKnotScene: waypoint_noise_period {} needs to be positive and at least {} s",
        params.waypoint_noise_period, kNoiseHorizon / 1e6));
  }
  reset({});
}

RopeKnotScene::~RopeKnotScene() = default;

Eigen::Vector3d RopeKnotScene::bar_centre() const { return vec3(params_.bar_centre, "bar_centre"); }

Scenario RopeKnotScene::sample(Rng& rng) const {
  Scenario s;
  s["grasp_offset"] = rng.uniform(-params_.grasp_range, params_.grasp_range);
  s["span_offset"] = rng.uniform(-params_.span_range, params_.span_range);
  s["drift_x"] = rng.uniform(-params_.drift_range[0], params_.drift_range[0]);
  s["drift_y"] = rng.uniform(-params_.drift_range[1], params_.drift_range[1]);
  s["drift_z"] = rng.uniform(-params_.drift_range[2], params_.drift_range[2]);
  // Drawn last: the other keys stay those of a given rng stream.
  s["noise_seed"] = static_cast<double>(rng.uniform_int(0, (int64_t{1} << 31) - 1));
  draw_base_offset(params_.base_offset_range, rng, s);
  return s;
}

void RopeKnotScene::reset(const Scenario& scenario) {
  left_.reset();
  right_.reset();
  rope_.reset();
  arms_.reset();
  fault_.clear();
  arm_failure_.clear();
  executed_.resize(0, 8);
  world_ = std::make_unique<SoftWorld>(params_.world);
  const Eigen::Vector3d bar = bar_centre();
  world_->add_bar("bar", bar, params_.bar_radius, params_.bar_length, params_.bar_friction);

  const RopeParams& rp = params_.rope;
  const int n = rp.nodes;
  const double step = rp.length / (n - 1);
  const LoadAndGrasp nodes = load_and_grasp(params_, value_or_zero(scenario, "grasp_offset"),
                                            value_or_zero(scenario, "span_offset"));
  const int load = nodes.load;
  const int grasp = nodes.grasp;
  if (!nodes.fits(n)) {
    throw std::invalid_argument(fmt::format(
        "RopeKnotScene::reset: weight at node {} and grasp node {} do not fit a rope of {} nodes",
        load, grasp, n));
  }
  drift_ = Eigen::Vector3d(value_or_zero(scenario, "drift_x"), value_or_zero(scenario, "drift_y"),
                           value_or_zero(scenario, "drift_z"));
  noise_knots_.clear();
  right_noise_.setZero();
  const auto seed = scenario.find("noise_seed");
  if (seed != scenario.end() && params_.waypoint_noise > 0.0) {
    Rng rng(mix64(noise_seed(seed->second)));
    const double a = params_.waypoint_noise;
    const int knots =
        static_cast<int>(std::ceil(kNoiseHorizon / params_.waypoint_noise_period)) + 1;
    for (int k = 0; k < knots; ++k) {
      const double x = rng.uniform(-a, a);
      const double y = rng.uniform(-a, a);
      const double z = rng.uniform(-a, a);
      noise_knots_.emplace_back(x, y, z);
    }
  } else if (seed != scenario.end()) {
    noise_seed(seed->second);
  }

  // Both parts hang from the right gripper: the tail straight down, the
  // standing part down and towards -y.
  const Eigen::Vector3d r0 = bar + vec3(params_.right_start_offset, "right_start_offset");
  const Eigen::Vector3d down(0, 0, -1);
  const Eigen::Vector3d slant = Eigen::Vector3d(0, -0.4, -1).normalized();
  std::vector<Eigen::Vector3d> positions(n);
  for (int i = 0; i <= grasp; ++i) positions[i] = r0 + slant * step * (grasp - i);
  for (int i = grasp; i < n; ++i) positions[i] = r0 + down * step * (i - grasp);

  rope_ = std::make_unique<Rope>(*world_, rp, positions);
  const int load_nodes = std::max(1, static_cast<int>(std::lround(params_.load_length / step)));
  for (int i = load; i < std::min(load + load_nodes, grasp); ++i) {
    rope_->set_mass(i, params_.load_mass / load_nodes);
  }
  const Eigen::Vector3d l0 = bar + vec3(params_.left_start_offset, "left_start_offset");
  Eigen::Vector3d right_start = r0, left_start = l0;
  if (params_.robot.on_arms()) {
    reset_arms(scenario, l0, r0);
    right_start = arms_->tool_position(Arm::right);
    left_start = arms_->tool_position(Arm::left);
  }
  right_ = std::make_unique<AnchorGripper>(*rope_, params_.gripper, top_grasp(), right_start);
  left_ = std::make_unique<AnchorGripper>(*rope_, params_.gripper, side_grasp(), left_start);
  right_->close();
  enclosed_ = -1;
  near_miss_ = false;
  drifting_ = false;
  const int settle = static_cast<int>(std::lround(params_.settle_time / world_->time_step()));
  for (int t = 0; t < settle && fault_.empty(); ++t) tick(left_point(), r0);
}

void RopeKnotScene::reset_arms(const Scenario& scenario, const Eigen::Vector3d& left,
                               const Eigen::Vector3d& right) {
  // A fresh robot every reset: a trial replays bit for bit.
  arms_ = build_robot(with_base_offset(params_.robot.dual_arm, scenario), world_->time_step());
  arms_->time_solves_into(ik_times_);
  arms_->set_tool_orientation(Arm::left, side_grasp());
  arms_->set_tool_orientation(Arm::right, top_grasp());
  // The commanded points until the arms move: the start, also when it is out of reach.
  left_target_ = left;
  right_target_ = right;
  arm_failure_ = arms_->reach(left, right);
  if (!arm_failure_.empty()) {
    fault_ = arm_failure_;
    return;
  }
  // From home to the start positions at the grippers' speed before the rope
  // is held (the home poses are the start's for the configured base, so this
  // takes no tick there).
  left_target_ = arms_->tool_position(Arm::left);
  right_target_ = arms_->tool_position(Arm::right);
  const double reach = params_.gripper.max_speed * world_->time_step();
  const double tolerance = 2.0 * params_.robot.dual_arm.ik.position_tolerance;
  const int most = static_cast<int>(std::lround(kArmTransitTime / world_->time_step()));
  for (int t = 0; t < most; ++t) {
    if ((arms_->tool_position(Arm::left) - left).norm() < tolerance &&
        (arms_->tool_position(Arm::right) - right).norm() < tolerance) {
      break;
    }
    const Eigen::Vector3d dl = left - left_target_, dr = right - right_target_;
    left_target_ += dl.norm() > reach ? (dl * (reach / dl.norm())).eval() : dl;
    right_target_ += dr.norm() > reach ? (dr * (reach / dr.norm())).eval() : dr;
    const std::string failure = arms_->track(left_target_, right_target_);
    if (!failure.empty()) {
      arm_failure_ = fmt::format("{}: {}", failure, arms_->failure_detail());
      fault_ = arm_failure_;
      return;
    }
  }
  left_target_ = left;
  right_target_ = right;
}

void RopeKnotScene::time_ik_solves_into(std::shared_ptr<IkSolveTimes> times) {
  ik_times_ = std::move(times);
  if (arms_) arms_->time_solves_into(ik_times_);
}

Eigen::Vector3d RopeKnotScene::left_point() const {
  return arms_ ? left_target_ : left_->position();
}

Eigen::Vector3d RopeKnotScene::right_point() const {
  return arms_ ? right_target_ : right_->position();
}

void RopeKnotScene::tick(const Eigen::Vector3d& left, const Eigen::Vector3d& right) {
  if (arms_) {
    left_target_ = left;
    right_target_ = right;
    const std::string failure = arms_->track(left, right);
    if (!failure.empty()) {
      arm_failure_ = fmt::format("{}: {}", failure, arms_->failure_detail());
      fault_ = arm_failure_;
      return;
    }
    left_->tick_to(arms_->tool_position(Arm::left));
    right_->tick_to(arms_->tool_position(Arm::right));
  } else {
    left_->tick_to(left);
    right_->tick_to(right);
  }
  world_->step();
  if (std::lround(world_->time() / world_->time_step()) % 20 == 0) fault_ = world_->blow_up();
}

std::string RopeKnotScene::set_grips(bool left_closed, bool right_closed) {
  if (left_closed && !left_->closed()) {
    near_miss_ = left_->near_miss();
    enclosed_ = left_->close();
  }
  if (right_closed && !right_->closed()) right_->close();
  if (!left_closed && left_->closed()) {
    left_->open();
    // Letting go of the standing part: the enclose record is that of a later
    // close (the one meant for the free end).
    if (!drifting_) {
      enclosed_ = -1;
      near_miss_ = false;
    }
    drifting_ = true;
  }
  if (!right_closed && right_->closed()) right_->open();
  // Hold still while a release ramps out.
  while ((left_->releasing() || right_->releasing()) && fault_.empty()) {
    tick(left_point(), right_point());
  }
  return fault_;
}

Eigen::Vector3d RopeKnotScene::noise_at(double time) const {
  if (noise_knots_.empty()) return Eigen::Vector3d::Zero();
  const double s = std::max(0.0, time / params_.waypoint_noise_period);
  const size_t k = static_cast<size_t>(std::floor(s));
  if (k + 1 >= noise_knots_.size()) return noise_knots_.back();
  const double a = s - static_cast<double>(k);
  return (1.0 - a) * noise_knots_[k] + a * noise_knots_[k + 1];
}

std::string RopeKnotScene::execute(const Eigen::MatrixXd& rows) {
  if (rows.cols() != 8) {
    throw std::invalid_argument(
        fmt::format("RopeKnotScene::execute: rows have {} columns, not 8", rows.cols()));
  }
  if (!rows.allFinite()) throw std::invalid_argument("RopeKnotScene::execute: non-finite row");
  const double reach = params_.gripper.max_speed * world_->time_step();
  executed_.resize(rows.rows(), 8);
  Eigen::Index reached = 0;
  for (Eigen::Index k = 0; k < rows.rows() && fault_.empty(); ++k) {
    const Eigen::Vector3d left_target = rows.row(k).segment<3>(0).transpose() + left_drift();
    Eigen::Vector3d right_target = rows.row(k).segment<3>(4).transpose();
    if (!noise_knots_.empty()) {
      right_noise_ = noise_at(world_->time());
      right_target += right_noise_;
    }
    while (fault_.empty()) {
      const Eigen::Vector3d dl = left_target - left_point();
      const Eigen::Vector3d dr = right_target - right_point();
      if (dl.norm() < 1e-9 && dr.norm() < 1e-9) break;
      tick(left_point() + (dl.norm() > reach ? (dl * (reach / dl.norm())).eval() : dl),
           right_point() + (dr.norm() > reach ? (dr * (reach / dr.norm())).eval() : dr));
    }
    if (fault_.empty()) set_grips(rows(k, 3) >= 0.5, rows(k, 7) >= 0.5);
    if (fault_.empty()) {
      const Eigen::Vector3d left = left_position(), right = right_position();
      executed_.row(reached++) << left.x(), left.y(), left.z(), left_closed() ? 1.0 : 0.0,
          right.x(), right.y(), right.z(), right_closed() ? 1.0 : 0.0;
    }
  }
  executed_.conservativeResize(reached, 8);
  if (fault_.empty()) fault_ = world_->blow_up();
  return fault_;
}

Eigen::Vector3d RopeKnotScene::left_position() const { return left_->position(); }
Eigen::Vector3d RopeKnotScene::left_drift() const {
  return drifting_ ? drift_ : Eigen::Vector3d::Zero();
}

Eigen::Vector3d RopeKnotScene::left_command() const { return left_point() - left_drift(); }
Eigen::Vector3d RopeKnotScene::right_position() const { return right_->position(); }
Eigen::Vector3d RopeKnotScene::right_command() const { return right_point() - right_noise_; }
bool RopeKnotScene::left_closed() const { return left_->closed(); }
bool RopeKnotScene::right_closed() const { return right_->closed(); }
std::vector<Eigen::Vector3d> RopeKnotScene::rope_nodes() const { return rope_->nodes(); }
Eigen::Vector3d RopeKnotScene::rope_end() const { return rope_->end_point(); }
Eigen::Vector3d RopeKnotScene::end_offset() const { return rope_end() - left_position(); }
double RopeKnotScene::time() const { return world_->time(); }

RenderScene RopeKnotScene::render_scene() const {
  RenderScene scene = soft_render_scene(*world_, *rope_, {left_.get(), right_.get()});
  if (arms_) add_robot(scene, arms_->shapes(), params_.robot.unseen_links);
  return scene;
}

RopeKnotOutcome RopeKnotScene::outcome() const {
  RopeKnotOutcome out;
  if (!arm_failure_.empty()) {
    out.failure = arm_failure_.substr(0, arm_failure_.find(':'));
    return out;
  }
  if (!fault_.empty()) {
    out.failure = "physics fault";
    return out;
  }
  try {
    out.report = analyse_rope_on_bar(rope_nodes(), bar_centre(), Eigen::Vector3d::UnitY());
  } catch (const std::exception&) {
    out.failure = "physics fault";
    return out;
  }
  out.knot =
      out.report.determinant == 3 && std::abs(out.report.winding_number) >= params_.min_winding;
  if (enclosed_ <= 0) {
    out.knot = false;
    out.failure = near_miss_ ? "near miss" : "missed enclose";
  } else if (!out.knot) {
    out.failure = "knot lost while tightening";
  }
  return out;
}

}  // namespace corrmp
