// Hostile inputs to run_experiment that reach past the YAML loader: sizes whose
// products overflowed or exhausted memory, names that became paths, lists that were silently
// accepted. Each ends in exit 2 with one line naming the key, before any database exists.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "support/report_tool.hpp"
#include "support/sanitized_build.hpp"

namespace corrmp {
namespace {

using testing::run_experiment_tool;
using testing::TempDir;
using testing::ToolOutcome;

std::string config(const std::string& name) {
  return std::string(PROJECT_DIR) + "/configs/" + name;
}

TEST(HostileConfigs, AbsurdSizesNamesAndListsAreConfigErrorsBeforeAnythingIsWritten) {
  TempDir dir;
  const std::string tiny = dir.write(
      "tiny.yaml",
      "experiment: {name: tiny}\ndemonstrations: {type: curve_family, train: 4, validation: 2, "
      "time_steps: 10}\npolicy:\n  type: segmented_cnmp\n  network: {width: 8}\n"
      "  training: {updates: 20, validate_every: 10}\n");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {config("corridor_pc.yaml") + " 'policy.segments=[]'",
       "policy.segments: lists no segment: a segmented policy needs at least one"},
      {config("corridor_pc.yaml") + " policy.segments.2.name=cor",
       "policy.segments[2].name: segment 'cor' is listed twice"},
      {config("corridor_pc.yaml") + " policy.segments.0.name=../../../../x",
       "policy.segments[0].name: '../../../../x' is not a valid name (it names files)"},
      {config("corridor_mono.yaml") + " policy.segment=../x",
       "policy.segment: '../x' is not a valid name"},
      {tiny + " context.type=perfect 'context.segments=[{segment: full, state: [x]}]'",
       "context.type: 'perfect' reads state values (x), but there is no environment section"},
      {tiny + " demonstrations.context_min=2", "demonstrations.context_max: is below context_min"},
      {config("corridor_pc.yaml") + " environment.scene=assets/scenes/nope.yaml",
       "environment.scene: scene file 'assets/scenes/nope.yaml' does not exist"},
      {config("corridor_pc.yaml") + " environment.scene=assets",
       "environment.scene: scene file 'assets' is not a regular file"},
      {config("corridor_ae.yaml") + " context.network.channels=2",
       "context.network.channels: must be 3 (RGB) or 1 (grey), not 2"},
      {config("corridor_ae.yaml") + " context.network.image_size=100000",
       "context.network.image_size: value 100000 is out of range"},
      {config("corridor_ae.yaml") + " context.network.latent_size=1000000000",
       "context.network.latent_size: value 1000000000 is out of range"},
      {config("corridor_pc.yaml") + " demonstrations.train=2000000000",
       "demonstrations.train: value 2000000000 is out of range"},
      {config("corridor_pc.yaml") + " environment.pre_points=2000000000",
       "environment.pre_points: value 2000000000 is out of range"},
      {config("corridor_pc.yaml") + " policy.training.batch_size=2000000000",
       "policy.training.batch_size: value 2000000000 is out of range"},
      // Noise or contexts that make the demonstrations non-finite.
      {config("curves_demo.yaml") + " demonstrations.noise=1e308",
       "demonstrations.noise: value 1e308 is out of range"},
      {config("curves_demo.yaml") + " demonstrations.context_max=1e308",
       "demonstrations.context_max: value 1e308 is out of range"},
      // Values that would make a simulation run for ever.
      {config("rope_color.yaml") + " environment.settle_time=1e9",
       "environment.settle_time: value 1e9 is out of range: must be in [0, 10]"},
      {config("rope_color.yaml") + " environment.gripper.max_speed=1e-9",
       "environment.gripper.max_speed: value 1e-9 is out of range"},
      {config("corridor_pc.yaml") + " environment.gripper.max_speed=1e-9",
       "environment.gripper.max_speed: value 1e-9 is out of range"},
      // Each value in range, their product not: the memory estimate refuses it.
      {config("corridor_ae.yaml") +
           " context.network.image_size=1024 'context.network.filters=[4096,4096,4096,4096,4096]'",
       "context.network.batch_size: the declared sizes need about"},
      {tiny + " demonstrations.time_steps=100000 policy.training.batch_size=1048576 "
              "policy.training.max_targets=100000 policy.network.width=4096",
       "policy.training.batch_size: the declared sizes need about"},
      // An expert's recordings: camera images at every segment start, and trajectories.
      {config("corridor_ae.yaml") + " environment.camera.width=2048 environment.camera.height=2048"
                                    " demonstrations.train=100000 demonstrations.validation=100000",
       "demonstrations.train: the declared sizes need about"},
      {config("rope_color.yaml") + " environment.camera.width=2048 environment.camera.height=2048"
                                   " demonstrations.train=100000",
       "RGB-D images of 2048x2048 pixels"},
      {config("corridor_pc.yaml") + " environment.pre_points=10000 environment.cor_points=10000"
                                    " environment.post_points=10000 demonstrations.train=100000",
       "demonstrations of 60000 trajectory points"},
  };
  for (const auto& [args, expected] : cases) {
    const ToolOutcome outcome = run_experiment_tool(dir, args);
    EXPECT_EQ(outcome.exit_code, 2) << args << "\n" << outcome.err;
    EXPECT_NE(outcome.err.find(expected), std::string::npos)
        << "expected: " << expected << "\ngot: " << outcome.err;
    EXPECT_EQ(std::count(outcome.err.begin(), outcome.err.end(), '\n'), 1) << outcome.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("r.sqlite"))) << args;
  }
}

using testing::kSanitized;

// The CNMP's own weights count in the memory estimate: the widest, deepest network (about 500
// million parameters) does not fit in 8 GiB and is refused at load, naming the network's key.
TEST(HostileConfigs, ANetworkTooLargeForTheMemoryIsAConfigError) {
  if (kSanitized) GTEST_SKIP() << "a sanitizer's shadow memory cannot run under ulimit -v";
  TempDir dir;
  // One update and its validation: without the estimate, the failure would come at once.
  const std::string big = dir.write(
      "big.yaml", "include: [" + config("curves_demo.yaml") +
                      "]\npolicy:\n  network: {width: 4096, encoder_layers: 16, decoder_layers: "
                      "16}\n  training: {updates: 1, validate_every: 1}\n");
  const ToolOutcome outcome =
      testing::run_tool(dir, "ulimit -v 8388608; " + std::string(RUN_EXPERIMENT_BIN) + " " + big +
                                 " --db " + dir.file("r.sqlite") + " --out " + dir.file("runs"));
  EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
  EXPECT_EQ(outcome.err.rfind(big + ":3:", 0), 0u) << outcome.err;
  EXPECT_NE(outcome.err.find(": policy.network.width: the declared sizes need about"),
            std::string::npos)
      << outcome.err;
  EXPECT_NE(outcome.err.find("width 4096, 16 encoder and 16 decoder layers"), std::string::npos)
      << outcome.err;
  EXPECT_EQ(std::count(outcome.err.begin(), outcome.err.end(), '\n'), 1) << outcome.err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("r.sqlite")));
}

// max_targets and max_observations larger than any trajectory mean "all points": the batch
// buffers are sized by the data, not by their product with batch_size (which overflowed an
// int and crashed).
TEST(HostileConfigs, HugeTargetAndObservationCountsTrainOnAllPoints) {
  TempDir dir;
  const std::string tiny = dir.write(
      "tiny.yaml",
      "experiment: {name: tiny}\ndemonstrations: {type: curve_family, train: 4, validation: 2, "
      "time_steps: 10}\npolicy:\n  type: segmented_cnmp\n  network: {width: 8}\n"
      "  training: {updates: 20, validate_every: 10, batch_size: 8}\n");
  const ToolOutcome outcome = run_experiment_tool(
      dir,
      tiny + " policy.training.max_targets=268435456 policy.training.max_observations=2000000000");
  EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
}

}  // namespace
}  // namespace corrmp
