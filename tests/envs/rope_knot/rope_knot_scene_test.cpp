// Tests of the simulated rope-knotting task (paper, Section IV-C): the
// scripted half hitch with the correction ties a knot, without it a strongly
// perturbed scenario misses the enclose, a post-MP that never closes reports a
// missed enclose, a trial replays bitwise, the right hand's waypoint noise
// stays within its amplitude and leaves unseeded trials untouched, bad
// parameters fail at construction. Two disabled tools: the success survey and
// pictures of a trial.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <utility>
#include <vector>

#include "core/config/config_loader.hpp"
#include "core/config/config_reader.hpp"
#include "envs/rope_knot/rope_knot_scene.hpp"
#include "envs/rope_knot/rope_knot_script.hpp"
#include "sim/render/offscreen_renderer.hpp"
#include "sim/render/rgbd_png.hpp"

namespace corrmp {
namespace {

int env_int(const char* name, int fallback) {
  const char* v = std::getenv(name);
  return v ? std::atoi(v) : fallback;
}

double env_double(const char* name, double fallback) {
  const char* v = std::getenv(name);
  return v ? std::atof(v) : fallback;
}

Scenario perturbed(double grasp, double span, double dx, double dy, double dz) {
  return {{"grasp_offset", grasp},
          {"span_offset", span},
          {"drift_x", dx},
          {"drift_y", dy},
          {"drift_z", dz}};
}

TEST(RopeKnotScene, NominalScriptedTrialTiesAHalfHitch) {
  RopeKnotScene scene(RopeKnotParams{});
  Eigen::Vector3d misalignment;
  const RopeKnotOutcome outcome = scripted_trial(scene, {}, true, &misalignment);
  EXPECT_TRUE(outcome.knot) << outcome.failure;
  EXPECT_EQ(outcome.failure, "");
  EXPECT_EQ(outcome.report.determinant, 3);
  EXPECT_GE(std::abs(outcome.report.winding_number), 0.75);
  // The nominal pre-MP ends with the free end in the open gap.
  EXPECT_LT(misalignment.norm(), 0.015);
}

TEST(RopeKnotScene, CorrectionTiesTheKnotInPerturbedScenarios) {
  RopeKnotScene scene(RopeKnotParams{});
  for (const Scenario& scenario : {perturbed(0.035, 0.037, 0.03, 0.01, 0.005),
                                   perturbed(-0.03, -0.03, -0.025, 0.035, -0.02)}) {
    Eigen::Vector3d misalignment;
    const RopeKnotOutcome outcome = scripted_trial(scene, scenario, true, &misalignment);
    EXPECT_GT(misalignment.norm(), 0.03) << scenario_json(scenario);
    EXPECT_TRUE(outcome.knot) << scenario_json(scenario) << ": " << outcome.failure;
  }
}

TEST(RopeKnotScene, WithoutCorrectionAStronglyPerturbedScenarioMisses) {
  RopeKnotScene scene(RopeKnotParams{});
  // The hand drifts 2.1 cm along the closing axis: a finger lands on the rope.
  const RopeKnotOutcome near = scripted_trial(scene, perturbed(0, 0, 0.021, 0, 0), false);
  EXPECT_FALSE(near.knot);
  EXPECT_EQ(near.failure, "near miss");
  // A short tail hangs above the gap and the hand falls short along +y.
  const RopeKnotOutcome missed = scripted_trial(scene, perturbed(0.04, 0, 0, -0.04, 0), false);
  EXPECT_FALSE(missed.knot);
  EXPECT_EQ(missed.failure, "missed enclose");
}

TEST(RopeKnotScene, APostMpThatNeverClosesTheLeftGripperMissesTheEnclose) {
  // The left gripper did close once, on the standing part during the pre-MP;
  // that grab is not the enclose of the free end.
  RopeKnotScene scene(RopeKnotParams{});
  ASSERT_EQ(scene.execute(pre_waypoints(scene.params())), "");
  Eigen::MatrixXd post = post_waypoints(scene.params(), scene.left_command());
  post.col(3).setZero();
  scene.execute(post);
  EXPECT_FALSE(scene.left_closed());
  const RopeKnotOutcome outcome = scene.outcome();
  EXPECT_FALSE(outcome.knot);
  EXPECT_EQ(outcome.failure, "missed enclose");
}

// The whole scripted trial (reset, pre-MP, correction, post-MP, outcome) in
// two fresh scenes: the same outcome and bitwise the same rope.
TEST(RopeKnotScene, ATrialReplaysBitwise) {
  auto run = [] {
    RopeKnotScene scene(RopeKnotParams{});
    const RopeKnotOutcome outcome =
        scripted_trial(scene, perturbed(0.01, -0.02, 0.01, -0.01, 0.01), true);
    return std::make_pair(outcome, scene.rope_nodes());
  };
  const auto [outcome_a, a] = run();
  const auto [outcome_b, b] = run();
  EXPECT_EQ(outcome_a.knot, outcome_b.knot);
  EXPECT_EQ(outcome_a.failure, outcome_b.failure);
  EXPECT_EQ(outcome_a.report.determinant, outcome_b.report.determinant);
  EXPECT_EQ(outcome_a.report.winding_number, outcome_b.report.winding_number);
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].x(), b[i].x());
    EXPECT_EQ(a[i].y(), b[i].y());
    EXPECT_EQ(a[i].z(), b[i].z());
  }
}

TEST(RopeKnotScene, SampledScenariosStayInTheirRanges) {
  const RopeKnotParams params;
  RopeKnotScene scene(params);
  Rng rng(7);
  for (int i = 0; i < 50; ++i) {
    const Scenario s = scene.sample(rng);
    EXPECT_LE(std::abs(s.at("grasp_offset")), params.grasp_range);
    EXPECT_LE(std::abs(s.at("span_offset")), params.span_range);
    EXPECT_LE(std::abs(s.at("drift_x")), params.drift_range[0]);
    EXPECT_LE(std::abs(s.at("drift_y")), params.drift_range[1]);
    EXPECT_LE(std::abs(s.at("drift_z")), params.drift_range[2]);
  }
}

// The first rows of the pre-MP (the loop over the bar), one call per row;
// after each row `check(row)` runs.
template <class Check>
void execute_loop_rows(RopeKnotScene& scene, Check check) {
  const Eigen::MatrixXd pre = pre_waypoints(scene.params());
  for (Eigen::Index k = 0; k < 40; ++k) {
    ASSERT_EQ(scene.execute(pre.row(k)), "") << "row " << k;
    check(pre.row(k));
  }
}

void expect_bitwise_equal(const std::vector<Eigen::Vector3d>& a,
                          const std::vector<Eigen::Vector3d>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].x(), b[i].x()) << i;
    EXPECT_EQ(a[i].y(), b[i].y()) << i;
    EXPECT_EQ(a[i].z(), b[i].z()) << i;
  }
}

// The right gripper's positions after each loop row and the rope at the end.
std::pair<std::vector<Eigen::Vector3d>, std::vector<Eigen::Vector3d>> loop_run(
    const RopeKnotParams& params, const Scenario& scenario) {
  RopeKnotScene scene(params);
  scene.reset(scenario);
  std::vector<Eigen::Vector3d> right;
  execute_loop_rows(scene, [&](const Eigen::RowVectorXd&) {
    right.push_back(scene.right_position());
    EXPECT_TRUE(scene.right_noise().isZero(0.0));
  });
  return {right, scene.rope_nodes()};
}

TEST(RopeKnotScene, WithoutNoiseSeedOrAmplitudeTheRightHandTracksItsRowsAsBefore) {
  const Scenario plain = perturbed(0.01, -0.02, 0.01, -0.01, 0.01);
  Scenario seeded = plain;
  seeded["noise_seed"] = 12345;
  RopeKnotParams quiet;
  quiet.waypoint_noise = 0.0;
  const auto [right_plain, rope_plain] = loop_run(RopeKnotParams{}, plain);
  const auto [right_quiet, rope_quiet] = loop_run(quiet, seeded);
  expect_bitwise_equal(right_plain, right_quiet);
  expect_bitwise_equal(rope_plain, rope_quiet);
}

TEST(RopeKnotScene, WaypointNoiseMovesTheRightHandWithinItsAmplitude) {
  const RopeKnotParams params;
  ASSERT_GT(params.waypoint_noise, 0.0);
  RopeKnotScene scene(params);
  Scenario scenario;
  scenario["noise_seed"] = 7;
  scene.reset(scenario);
  double largest = 0.0;
  execute_loop_rows(scene, [&](const Eigen::RowVectorXd& row) {
    const Eigen::Vector3d commanded = row.segment<3>(4).transpose();
    const Eigen::Vector3d error = scene.right_position() - commanded;
    EXPECT_LE(error.cwiseAbs().maxCoeff(), params.waypoint_noise + 1e-9);
    EXPECT_LT((error - scene.right_noise()).norm(), 1e-8);
    EXPECT_LT((scene.right_command() - commanded).norm(), 1e-8);
    largest = std::max(largest, error.cwiseAbs().maxCoeff());
  });
  EXPECT_GT(largest, 0.2 * params.waypoint_noise);
}

TEST(RopeKnotScene, TheSameNoiseSeedReplaysBitwiseAndAnotherDiffers) {
  auto run = [](double seed) {
    RopeKnotScene scene(RopeKnotParams{});
    scene.reset({{"noise_seed", seed}});
    std::vector<Eigen::Vector3d> right;
    execute_loop_rows(scene,
                      [&](const Eigen::RowVectorXd&) { right.push_back(scene.right_position()); });
    return right;
  };
  const std::vector<Eigen::Vector3d> a = run(2024), b = run(2024), c = run(2025);
  expect_bitwise_equal(a, b);
  double apart = 0.0;
  for (size_t i = 0; i < a.size(); ++i) apart = std::max(apart, (a[i] - c[i]).norm());
  EXPECT_GT(apart, 1e-4);
}

// noise_seed is drawn after the other keys: a given rng stream gives the same
// grasp, span and drift as before it existed.
TEST(RopeKnotScene, SamplingTheNoiseSeedKeepsTheOtherKeys) {
  const RopeKnotParams params;
  RopeKnotScene scene(params);
  Rng rng(11);
  for (int i = 0; i < 20; ++i) {
    Rng before = rng;
    const double grasp = before.uniform(-params.grasp_range, params.grasp_range);
    const double span = before.uniform(-params.span_range, params.span_range);
    const double dx = before.uniform(-params.drift_range[0], params.drift_range[0]);
    const double dy = before.uniform(-params.drift_range[1], params.drift_range[1]);
    const double dz = before.uniform(-params.drift_range[2], params.drift_range[2]);
    const Scenario s = scene.sample(rng);
    EXPECT_EQ(s.at("grasp_offset"), grasp);
    EXPECT_EQ(s.at("span_offset"), span);
    EXPECT_EQ(s.at("drift_x"), dx);
    EXPECT_EQ(s.at("drift_y"), dy);
    EXPECT_EQ(s.at("drift_z"), dz);
    const double seed = s.at("noise_seed");
    EXPECT_EQ(seed, std::floor(seed));
    EXPECT_GE(seed, 0.0);
    EXPECT_LT(seed, 2147483648.0);
    EXPECT_EQ(seed, static_cast<double>(before.uniform_int(0, (int64_t{1} << 31) - 1)));
    EXPECT_EQ(rng(), before());
  }
}

TEST(RopeKnotScene, ResetRefusesANoiseSeedThatIsNotAWholeNumber) {
  RopeKnotScene scene(RopeKnotParams{});
  for (const double seed : {-1.0, 0.5, std::nan("")}) {
    EXPECT_THROW(scene.reset({{"noise_seed", seed}}), std::invalid_argument) << seed;
  }
  RopeKnotParams quiet;
  quiet.waypoint_noise = 0.0;
  RopeKnotScene quiet_scene(quiet);
  EXPECT_THROW(quiet_scene.reset({{"noise_seed", 0.5}}), std::invalid_argument);
}

// The message of the std::invalid_argument the constructor throws, or "".
std::string construction_error(const RopeKnotParams& params) {
  try {
    RopeKnotScene scene(params);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(RopeKnotScene, MotionListsOfPartPointsFailAtConstruction) {
  RopeKnotParams params;
  params.motion.right_loop.pop_back();
  EXPECT_NE(construction_error(params).find("right_loop"), std::string::npos);
  params = RopeKnotParams{};
  params.motion.right_tuck.clear();
  EXPECT_NE(construction_error(params).find("right_tuck"), std::string::npos);
  params = RopeKnotParams{};
  params.motion.tighten.push_back(0.0);
  EXPECT_NE(construction_error(params).find("tighten"), std::string::npos);
}

TEST(RopeKnotScene, ScenarioRangesThatDoNotFitTheRopeFailAtConstruction) {
  RopeKnotParams params;
  // At grasp_offset +0.2 the grasp node is past the end of the 0.95 m rope.
  params.grasp_range = 0.2;
  EXPECT_NE(construction_error(params).find("grasp_range"), std::string::npos);
  // At span_offset +0.1 the weight would start before the rope's first node.
  params = RopeKnotParams{};
  params.span_range = 0.1;
  EXPECT_NE(construction_error(params).find("span_range"), std::string::npos);
}

// A colour of two values is a config error (and no out-of-bounds read later).
TEST(RopeKnotScene, ConfigRejectsShortColoursAndVectors) {
  const std::string path =
      (std::filesystem::temp_directory_path() /
       ("rope_knot_scene_test_" +
        std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + ".yaml"))
          .string();
  for (const char* yaml :
       {"gripper: {colour: [0.1, 0.2]}\n", "rope: {end_colour: [0.1, 0.2, 0.3, 0.4]}\n",
        "drift_range: [0.01, 0.01]\n", "motion: {nominal_end: [0.0, 0.1]}\n"}) {
    std::ofstream(path) << yaml;
    ConfigNode root = load_config(path, {});
    RopeKnotParams params;
    EXPECT_THROW(ConfigReader::read(root, "", params), ConfigError) << yaml;
  }
  std::filesystem::remove(path);
}

TEST(RopeKnotScene, ExecuteRefusesRowsOfTheWrongWidth) {
  RopeKnotScene scene(RopeKnotParams{});
  EXPECT_THROW(scene.execute(Eigen::MatrixXd::Zero(3, 7)), std::invalid_argument);
}

// Knot success with and without the correction over random scenarios
// (ROPE_NOISE overrides waypoint_noise, in m):
//   ROPE_TRIALS=20 ROPE_SEED=1 test_rope_knot_scene
//     --gtest_also_run_disabled_tests --gtest_filter='*DISABLED_Survey*'
TEST(RopeKnotSurvey, DISABLED_Survey) {
  const int trials = env_int("ROPE_TRIALS", 20);
  Rng rng(env_int("ROPE_SEED", 1));
  RopeKnotParams params;
  params.waypoint_noise = env_double("ROPE_NOISE", params.waypoint_noise);
  std::printf("waypoint_noise %.4f m\n", params.waypoint_noise);
  RopeKnotScene scene(params);
  std::map<std::string, int> with, without;
  int knots_with = 0, knots_without = 0;
  for (int t = 0; t < trials; ++t) {
    const Scenario scenario = scene.sample(rng);
    Eigen::Vector3d off;
    const RopeKnotOutcome a = scripted_trial(scene, scenario, true, &off);
    const RopeKnotOutcome b = scripted_trial(scene, scenario, false);
    knots_with += a.knot;
    knots_without += b.knot;
    ++with[a.knot ? "knot" : a.failure];
    ++without[b.knot ? "knot" : b.failure];
    std::printf(
        "trial %2d grasp %+.3f span %+.3f drift %+.3f %+.3f %+.3f | offset %+.3f %+.3f %+.3f"
        " | with: %s det %d w %.2f | without: %s det %d w %.2f\n",
        t, scenario.at("grasp_offset"), scenario.at("span_offset"), scenario.at("drift_x"),
        scenario.at("drift_y"), scenario.at("drift_z"), off.x(), off.y(), off.z(),
        a.knot ? "knot" : a.failure.c_str(), a.report.determinant, a.report.winding_number,
        b.knot ? "knot" : b.failure.c_str(), b.report.determinant, b.report.winding_number);
  }
  std::printf("with correction: %d/%d knots; without: %d/%d\n", knots_with, trials, knots_without,
              trials);
  for (const auto& [k, v] : with) std::printf("  with: %s %d\n", k.c_str(), v);
  for (const auto& [k, v] : without) std::printf("  without: %s %d\n", k.c_str(), v);
}

// Renders the nominal scripted trial to ROPE_PNG_DIR, one picture per segment.
TEST(RopeKnotSurvey, DISABLED_Pictures) {
  const char* dir = std::getenv("ROPE_PNG_DIR");
  if (dir == nullptr) GTEST_SKIP() << "set ROPE_PNG_DIR";
  RopeKnotScene scene(RopeKnotParams{});
  Scenario scenario;
  scenario["drift_x"] = env_int("ROPE_DX_MM", 0) / 1000.0;
  scenario["grasp_offset"] = env_int("ROPE_GRASP_MM", 0) / 1000.0;
  scene.reset(scenario);
  OffscreenRenderer renderer(CameraIntrinsics::from_vertical_fov(480, 480, 0.9));
  const Eigen::Vector3d b = scene.bar_centre();
  const int view = env_int("ROPE_VIEW", 0);
  const Eigen::Vector3d eye = view == 0   ? b + Eigen::Vector3d(-0.7, -0.35, 0.1)
                              : view == 1 ? b + Eigen::Vector3d(0.0, -0.8, -0.1)
                                          : b + Eigen::Vector3d(-0.8, 0.0, -0.1);
  const auto camera = look_at(eye, b + Eigen::Vector3d(0, 0.05, -0.12), Eigen::Vector3d::UnitZ());
  auto shot = [&](const std::string& name) {
    write_png(renderer.render(scene.render_scene(), camera), std::string(dir) + "/" + name + ".png",
              std::string(dir) + "/" + name + "_depth.png");
  };
  shot("0_start");
  const Eigen::MatrixXd pre = pre_waypoints(scene.params());
  const int half = env_int("ROPE_PRE_ROWS", pre.rows());
  scene.execute(pre.topRows(half));
  shot("1_pre_part");
  scene.execute(pre.bottomRows(pre.rows() - half));
  shot("2_critical");
  scene.execute(correction_waypoints(scene, correction_offset(scene)));
  shot("3_corrected");
  const Eigen::MatrixXd post = post_waypoints(scene.params(), scene.left_position());
  const int part = env_int("ROPE_POST_ROWS", post.rows() / 2);
  scene.execute(post.topRows(part));
  shot("4_post_part");
  scene.execute(post.bottomRows(post.rows() - part));
  shot("5_end");
  const RopeKnotOutcome out = scene.outcome();
  std::printf("outcome: %s det %d winding %.2f\n", out.knot ? "knot" : out.failure.c_str(),
              out.report.determinant, out.report.winding_number);
}

}  // namespace
}  // namespace corrmp
