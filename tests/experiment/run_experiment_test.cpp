// End-to-end tests of the run_experiment command: exit codes, one-line config
// errors with nothing written to the database, run directories, determinism.
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "experiment/registries.hpp"
#include "store/result_store.hpp"
#include "support/report_tool.hpp"
#include "support/store_sql.hpp"

namespace corrmp {
namespace {

using testing::TempDir;

using Outcome = testing::ToolOutcome;

std::string read_file(const std::string& path) { return testing::read(path); }

Outcome run(const TempDir& dir, const std::string& args) {
  return testing::run_experiment_tool(dir, args);
}

// Every registered demonstration source, as a message lists them: the tasks' experts, which
// come and go with the task folders, then curve_family and trajectory_files.
std::string registered_sources() {
  return fmt::format("{}", fmt::join(builtin_registries().demonstrations.names(), ", "));
}

TEST(RunExperiment, TheListedDemonstrationSourcesAreTheBuiltInOnesInRegistrationOrder) {
  const std::string sources = registered_sources();
  EXPECT_NE(sources.find("corridor_expert, rope_expert"), std::string::npos) << sources;
  EXPECT_EQ(sources.substr(sources.size() - 30), "curve_family, trajectory_files") << sources;
}

const std::string kGood =
    "experiment: {name: tiny}\nseed: 3\ndemonstrations: {type: curve_family, train: 4, "
    "validation: 2, time_steps: 10}\npolicy:\n  type: segmented_cnmp\n  network: {width: 8}\n"
    "  training: {updates: 200, validate_every: 50}\n";

TEST(RunExperiment, MalformedConfigsGiveOneLineExitTwoAndNoDatabaseWrites) {
  TempDir dir;
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"experiment: {name: a}\ndemonstrations: {type: curve_family, trian: 4}\n",
       "bad.yaml:2:38: demonstrations.trian: unknown key (did you mean 'train'?)"},
      {"seed: 1\n", "bad.yaml:1:1: experiment: missing required key"},
      {"experiment: {name: a}\nseed: -1\n",
       "bad.yaml:2:7: seed: expected a non-negative integer, got '-1'"},
      {"experiment: {name: a}\ndemonstrations: {type: curve_family, train: 0}\n",
       "bad.yaml:2:45: demonstrations.train: value 0 is out of range: must be in [1, 1000000]"},
      {"experiment: {name: a}\ndemonstrations: {type: curve_famly}\n",
       "bad.yaml:2:24: demonstrations.type: unknown demonstration source 'curve_famly' (did you "
       "mean 'curve_family'?); valid: " +
           registered_sources()},
      {"experiment: {name: 'a/b'}\n", "bad.yaml:1:20: experiment.name: 'a/b' is not a valid name"},
      {"experiment: {name: a\n", "bad.yaml:2:1: YAML syntax error"},
  };
  for (const auto& [yaml, expected] : cases) {
    const std::string path = dir.write("bad.yaml", yaml);
    const Outcome outcome = run(dir, path);
    EXPECT_EQ(outcome.exit_code, 2) << yaml;
    EXPECT_NE(outcome.err.find(expected), std::string::npos)
        << "expected: " << expected << "\ngot: " << outcome.err;
    EXPECT_EQ(std::count(outcome.err.begin(), outcome.err.end(), '\n'), 1) << outcome.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("r.sqlite"))) << yaml;
  }
  const Outcome override_error =
      run(dir, dir.write("good.yaml", kGood) + " demonstrations.trains=3");
  EXPECT_EQ(override_error.exit_code, 2);
  const Outcome nested_error = run(dir, dir.file("good.yaml") + " policy.training.updatez=3");
  EXPECT_EQ(nested_error.exit_code, 2);
  EXPECT_NE(nested_error.err.find("policy.training.updatez: unknown key (did you mean 'updates'?)"),
            std::string::npos)
      << nested_error.err;
  EXPECT_NE(override_error.err.find("command-line override 'demonstrations.trains=3': "
                                    "demonstrations.trains: unknown key (did you mean 'train'?)"),
            std::string::npos)
      << override_error.err;
  EXPECT_EQ(run(dir, "--no-such-flag").exit_code, 2);
  EXPECT_EQ(run(dir, dir.file("missing.yaml")).exit_code, 2);
  EXPECT_FALSE(std::filesystem::exists(dir.file("r.sqlite")));
}

// A numeric option given a value that is not a number: one line naming the option and the
// value, exit 2, nothing written.
TEST(RunExperiment, ANonNumberForANumericOptionNamesTheOptionAndTheValue) {
  TempDir dir;
  const std::string config = dir.write("good.yaml", kGood);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--threads abc", "run_experiment: --threads: expected an integer, got 'abc' (see --help)\n"},
      {"--threads 1.5", "run_experiment: --threads: expected an integer, got '1.5' (see --help)\n"},
      {"-j 2x", "run_experiment: --jobs: expected an integer, got '2x' (see --help)\n"},
      {"--threads 99999999999999999999",
       "run_experiment: --threads: '99999999999999999999' is out of range (see --help)\n"},
  };
  for (const auto& [args, expected] : cases) {
    const Outcome outcome = run(dir, config + " " + args);
    EXPECT_EQ(outcome.exit_code, 2) << args;
    EXPECT_EQ(outcome.err, expected) << args;
  }
  EXPECT_FALSE(std::filesystem::exists(dir.file("r.sqlite")));
}

// What one component asks of another is checked at load: exit 2 with the
// file, line and key path of the offending value, before any run is recorded.
TEST(RunExperiment, MismatchedComponentsAreConfigErrors) {
  TempDir dir;
  const std::string corridor = std::string(PROJECT_DIR) + "/configs/corridor_pc.yaml";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {corridor + " policy.segments.1.name=corr",
       "policy.segments[1].name: segment 'corr' is not in the demonstrations of "
       "'corridor_expert' (they hold: pre, cor, post, full)"},
      {corridor + " 'context.segments=[{segment: cor, state: [corridor_x]}]'",
       "corridor_pc.yaml:17:14: policy.segments[2].name: segment 'post' is conditioned on a "
       "context, but the context extractor 'perfect' gives none for it (it gives: cor)"},
      {corridor + " 'context.segments=[{segment: postt, state: [object_x]}]'",
       "context.segments[0].segment: segment 'postt' is not in the demonstrations"},
      {std::string(PROJECT_DIR) + "/configs/corridor_ae.yaml 'context.segments=[cor, postt]'",
       "context.segments[1]: segment 'postt' is not in the demonstrations of 'corridor_expert'"},
      {std::string(PROJECT_DIR) +
           "/configs/corridor_mono.yaml 'policy.matched_segments=[pre, cor, pst]'",
       "policy.matched_segments[2]: segment 'pst' is not in the demonstrations"},
      {dir.write("no_expert.yaml",
                 "experiment: {name: a}\nenvironment: {type: corridor_push}\n"
                 "demonstrations: {type: curve_family}\npolicy: {type: segmented_cnmp}\n"),
       "no_expert.yaml:3:24: demonstrations.type: 'curve_family' cannot demonstrate evaluation "
       "scenarios"},
      {dir.write("no_context.yaml",
                 "experiment: {name: a}\nenvironment: {type: rope_knot}\n"
                 "demonstrations: {type: rope_expert}\npolicy:\n  type: segmented_cnmp\n"
                 "  segments: [{name: cor}]\n"),
       "no_context.yaml:6:21: policy.segments[0].name: segment 'cor' is conditioned on a "
       "context, but there is no context section"},
      {std::string(PROJECT_DIR) + "/configs/rope_color.yaml context.segmentation.cluster=all",
       "context.segmentation.cluster: 'all' is not allowed: must be one of largest"},
      {std::string(PROJECT_DIR) +
           "/configs/rope_color.yaml 'context.gripper_state=[gripper_mid_x]'",
       "context.gripper_state: expected a list of 3 items, got 1"},
      {std::string(PROJECT_DIR) + "/configs/rope_color.yaml environment.rope.nodes=1",
       "environment.rope.nodes"},
      {dir.write("wrong_expert.yaml",
                 "experiment: {name: a}\nenvironment: {type: corridor_push}\n"
                 "demonstrations: {type: rope_expert}\npolicy:\n  type: segmented_cnmp\n"
                 "  segments: [{name: pre, use_context: false}]\n"),
       "wrong_expert.yaml:3:24: demonstrations.type: 'rope_expert' demonstrates in a 'rope_knot' "
       "environment, not in 'corridor_push'"},
      {std::string(PROJECT_DIR) + "/configs/rope_color.yaml demonstrations.images=false",
       "demonstrations.images: the context extractor 'color_segmentation' reads camera images, "
       "but the demonstrations of 'rope_expert' record none: set images: true"},
      {corridor + " 'context.segments=[{segment: cor, state: [corridor_z]}, {segment: post, "
                  "state: [object_x]}]'",
       "context.segments[0].state[0]: 'corridor_z' is not a state value of 'corridor_push' "
       "(it observes: corridor_x, corridor_y, gripper_x"},
      {std::string(PROJECT_DIR) + "/configs/corridor_ae.yaml context.plot_state=corridor_q",
       "context.plot_state: 'corridor_q' is not a state value of 'corridor_push'"},
      {corridor + " 'environment.gripper.palm_size=[]'",
       "environment.gripper.palm_size: expected a list of 3 items, got 0"},
      {std::string(PROJECT_DIR) + "/configs/corridor_ae.yaml 'environment.camera.eye=[1, 2]'",
       "environment.camera.eye: expected a list of 3 items, got 2"},
  };
  for (const auto& [args, expected] : cases) {
    const Outcome outcome = run(dir, args);
    EXPECT_EQ(outcome.exit_code, 2) << args << "\n" << outcome.err;
    EXPECT_NE(outcome.err.find(expected), std::string::npos)
        << "expected: " << expected << "\ngot: " << outcome.err;
    EXPECT_EQ(std::count(outcome.err.begin(), outcome.err.end(), '\n'), 1) << outcome.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("r.sqlite"))) << args;
  }
}

// Every shipped experiment config loads (includes, components, cross-component
// checks); fragments meant to be included name no experiment and are skipped.
TEST(RunExperiment, EveryShippedConfigLoads) {
  TempDir dir;
  int loaded = 0;
  for (const auto& entry :
       std::filesystem::recursive_directory_iterator(std::string(PROJECT_DIR) + "/configs")) {
    if (entry.path().extension() != ".yaml") continue;
    if (read_file(entry.path().string()).find("experiment:") == std::string::npos) continue;
    const Outcome outcome = run(dir, entry.path().string() + " --print-config");
    EXPECT_EQ(outcome.exit_code, 0) << entry.path() << "\n" << outcome.err;
    // The paper's full protocol wins over what the configs it extends set.
    if (entry.path().parent_path().filename() == "paper") {
      EXPECT_NE(outcome.out.find("updates: 10000000"), std::string::npos) << entry.path();
    }
    ++loaded;
  }
  EXPECT_GE(loaded, 15);
  EXPECT_FALSE(std::filesystem::exists(dir.file("r.sqlite")));
}

TEST(RunExperiment, PrintConfigShowsEveryResolvedValue) {
  TempDir dir;
  const Outcome outcome = run(dir, dir.write("good.yaml", kGood) + " seed=11 --print-config");
  EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_NE(outcome.out.find("seed: 11"), std::string::npos) << outcome.out;
  EXPECT_NE(outcome.out.find("context_max: 1.0"), std::string::npos) << outcome.out;
  EXPECT_NE(outcome.out.find("trials: 25"), std::string::npos) << outcome.out;
  EXPECT_FALSE(std::filesystem::exists(dir.file("r.sqlite")));
}

TEST(RunExperiment, ListShowsRegistriesWithDescriptionsAndParameters) {
  TempDir dir;
  const Outcome outcome = run(dir, "--list");
  EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_NE(outcome.out.find("curve_family"), std::string::npos) << outcome.out;
  EXPECT_NE(outcome.out.find("time_steps"), std::string::npos) << outcome.out;
  EXPECT_NE(outcome.out.find("segmented_cnmp"), std::string::npos) << outcome.out;
  EXPECT_NE(outcome.out.find("training.updates"), std::string::npos) << outcome.out;
  EXPECT_NE(outcome.out.find("\npolicy (policies):\n"), std::string::npos) << outcome.out;
  EXPECT_NE(outcome.out.find("\ncontext (context extractors):\n"), std::string::npos)
      << outcome.out;
}

TEST(RunExperiment, ARunIsRecordedWithItsDirectoryAndIsDeterministic) {
  TempDir dir;
  const std::string config = dir.write("good.yaml", kGood);
  const Outcome first = run(dir, config);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const Outcome second = run(dir, config);
  ASSERT_EQ(second.exit_code, 0) << second.err;

  ResultStore store(dir.file("r.sqlite"));
  EXPECT_EQ(testing::query_int(store, "SELECT COUNT(*) FROM runs WHERE status = 'completed'"), 2);
  EXPECT_EQ(testing::query_text(store,
                                "SELECT value FROM metrics WHERE run_id = 1 AND name = "
                                "'demonstrations_train'"),
            "4.0");
  EXPECT_EQ(
      testing::query_int(store,
                         "SELECT COUNT(*) FROM (SELECT name, value FROM metrics WHERE run_id = 1 "
                         "EXCEPT SELECT name, value FROM metrics WHERE run_id = 2)"),
      0);
  EXPECT_EQ(testing::query_text(store, "SELECT config_hash FROM runs WHERE id = 1"),
            testing::query_text(store, "SELECT config_hash FROM runs WHERE id = 2"));
  const std::string run_dir = testing::query_text(store, "SELECT out_dir FROM runs WHERE id = 1");
  EXPECT_EQ(run_dir, dir.file("runs/tiny/1"));
  EXPECT_NE(read_file(run_dir + "/config.resolved.yaml").find("time_steps: 10"), std::string::npos);
  const std::string run_json = read_file(run_dir + "/run.json");
  EXPECT_NE(run_json.find("\"status\": \"completed\""), std::string::npos) << run_json;
  EXPECT_NE(run_json.find("\"git_commit\""), std::string::npos) << run_json;
  EXPECT_NE(run_json.find("\"finished_at\": \"20"), std::string::npos) << run_json;
  EXPECT_NE(read_file(run_dir + "/log.txt").find("collected 4 training"), std::string::npos);
  // The policy stage: a model file, predictions and measured errors.
  EXPECT_TRUE(std::filesystem::exists(run_dir + "/models/full.cnmp"));
  EXPECT_NE(
      read_file(run_dir + "/predictions/full.csv").find("demonstration,step,x0,y0,mean0,std0"),
      std::string::npos);
  const std::string error_mean = testing::query_text(
      store, "SELECT value FROM metrics WHERE run_id = 1 AND name = 'full_error_mean'");
  ASSERT_FALSE(error_mean.empty());
  EXPECT_GT(std::stod(error_mean), 0.0);
  EXPECT_LE(std::stod(error_mean),
            std::stod(testing::query_text(store,
                                          "SELECT value FROM metrics WHERE run_id = 1 AND name = "
                                          "'full_error_max'")));
}

TEST(RunExperiment, ATinyCorridorRunRecordsTrialsAndThePapersMetrics) {
  TempDir dir;
  // corridor_pc twice: the second run reuses the cached demonstrations and must
  // reproduce the first exactly.
  for (const std::string policy : {"corridor_pc", "corridor_mono", "corridor_pc"}) {
    const Outcome outcome =
        run(dir, std::string(PROJECT_DIR) + "/configs/" + policy +
                     ".yaml demonstrations.train=8 demonstrations.validation=4 "
                     "policy.training.updates=300 policy.training.validate_every=100 "
                     "policy.network.width=16 evaluation.trials=3");
    ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
    EXPECT_NE(outcome.out.find("Table I (" + policy + ")"), std::string::npos) << outcome.out;
    EXPECT_NE(outcome.out.find("cor-MP"), std::string::npos) << outcome.out;
  }
  ResultStore store(dir.file("r.sqlite"));
  for (int run_id : {1, 2}) {
    const std::string where = " WHERE run_id = " + std::to_string(run_id);
    EXPECT_EQ(testing::query_int(store, "SELECT COUNT(*) FROM trials" + where), 3);
    EXPECT_EQ(testing::query_int(
                  store, "SELECT COUNT(*) FROM trials" + where +
                             " AND expected_action IN ('push', 'pull', 'none') AND chosen_action "
                             "IN ('push', 'pull', 'none') AND scenario LIKE "
                             "'%corridor_offset%' AND (success = 1 OR failure <> '')"),
              3);
    auto metric = [&](const std::string& name) {
      const std::string text = testing::query_text(
          store, "SELECT value FROM metrics" + where + " AND name = '" + name + "'");
      EXPECT_FALSE(text.empty()) << name;
      return text.empty() ? -1.0 : std::stod(text);
    };
    const double success = metric("task_success_rate");
    EXPECT_GE(success, 0.0);
    EXPECT_LE(success, 1.0);
    EXPECT_DOUBLE_EQ(success * 3, static_cast<double>(testing::query_int(
                                      store, "SELECT SUM(success) FROM trials" + where)));
    EXPECT_GE(metric("decision_match_rate"), 0.0);
    EXPECT_GT(metric("cor_mp_error_mean_cm"), 0.0);
    EXPECT_LE(metric("cor_mp_error_mean_cm"), metric("cor_mp_error_max_cm"));
    EXPECT_GT(metric("post_mp_error_mean_cm"), 0.0);
    EXPECT_LE(metric("post_mp_error_mean_cm"), metric("post_mp_error_max_cm"));
  }
  EXPECT_EQ(
      testing::query_int(store,
                         "SELECT COUNT(*) FROM (SELECT trial, scenario, expected_action, "
                         "chosen_action, success, failure FROM trials WHERE run_id = 1 EXCEPT "
                         "SELECT trial, scenario, expected_action, chosen_action, success, "
                         "failure FROM trials WHERE run_id = 3)"),
      0);
  EXPECT_EQ(
      testing::query_int(store,
                         "SELECT COUNT(*) FROM (SELECT name, value FROM metrics WHERE run_id = "
                         "1 EXCEPT SELECT name, value FROM metrics WHERE run_id = 3)"),
      0);
  EXPECT_NE(
      read_file(testing::query_text(store, "SELECT out_dir FROM runs WHERE id = 3") + "/log.txt")
          .find("reusing cached demonstrations"),
      std::string::npos);
}

TEST(RunExperiment, ATinyAutoencoderRunWritesItsFiguresAndGivesTheSameResultsOnOneOrTwoThreads) {
  TempDir dir;
  const std::string args =
      std::string(PROJECT_DIR) +
      "/configs/corridor_ae.yaml demonstrations.train=10 demonstrations.validation=5 "
      "policy.training.updates=200 policy.training.validate_every=100 policy.network.width=16 "
      "evaluation.trials=2 context.network.image_size=16 context.network.epochs=2 "
      "context.network.filters=[4,4,8,8,8] context.network.latent_size=3";
  // Two threads: the pre-MP's network trains beside the autoencoder.
  const Outcome first = run(dir, args + " --threads 2");
  ASSERT_EQ(first.exit_code, 0) << first.err;
  ResultStore store(dir.file("r.sqlite"));
  const std::string run_dir = testing::query_text(store, "SELECT out_dir FROM runs WHERE id = 1");
  for (const char* file : {"autoencoder.cmpm", "autoencoder_reconstructions.png",
                           "autoencoder_latents.png", "tables.txt"}) {
    EXPECT_TRUE(std::filesystem::exists(run_dir + "/" + file)) << file;
  }
  const std::string mse = testing::query_text(
      store, "SELECT value FROM metrics WHERE run_id = 1 AND name = 'autoencoder_test_mse'");
  ASSERT_FALSE(mse.empty());
  EXPECT_GT(std::stod(mse), 0.0);
  EXPECT_LT(std::stod(mse), 0.5);
  EXPECT_EQ(testing::query_int(store, "SELECT COUNT(*) FROM trials WHERE run_id = 1"), 2);
  // A second run reuses the cached autoencoder and reproduces the first.
  const Outcome second = run(dir, args);
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_NE(
      read_file(testing::query_text(store, "SELECT out_dir FROM runs WHERE id = 2") + "/log.txt")
          .find("reusing the trained autoencoder"),
      std::string::npos);
  EXPECT_EQ(
      testing::query_int(store,
                         "SELECT COUNT(*) FROM (SELECT name, value FROM metrics WHERE run_id = "
                         "1 EXCEPT SELECT name, value FROM metrics WHERE run_id = 2)"),
      0);
  // One thread, everything trained afresh one after another: the same results.
  const Outcome third = run(dir, args + " --threads 1 --no-cache");
  ASSERT_EQ(third.exit_code, 0) << third.err;
  EXPECT_EQ(
      testing::query_int(store,
                         "SELECT COUNT(*) FROM (SELECT name, value FROM metrics WHERE run_id = "
                         "1 EXCEPT SELECT name, value FROM metrics WHERE run_id = 3)"),
      0);
  EXPECT_GT(testing::query_int(store, "SELECT COUNT(*) FROM metrics WHERE run_id = 3"), 10);
}

// A cache file that cannot be read is reported and collected again;
// --no-cache collects afresh. Both give the same results as the first run.
TEST(RunExperiment, AnUnreadableCacheIsCollectedAgain) {
  TempDir dir;
  const std::string args = std::string(PROJECT_DIR) +
                           "/configs/corridor_pc.yaml demonstrations.train=4 "
                           "demonstrations.validation=2 policy.training.updates=100 "
                           "policy.training.validate_every=50 policy.network.width=8 "
                           "evaluation.trials=1";
  ASSERT_EQ(run(dir, args).exit_code, 0);
  std::vector<std::filesystem::path> caches;
  for (const auto& entry : std::filesystem::directory_iterator(dir.file("runs/cache"))) {
    if (entry.path().extension() == ".bin") caches.push_back(entry.path());  // not its .lock
  }
  ASSERT_EQ(caches.size(), 1u);
  std::ofstream(caches[0], std::ios::binary | std::ios::trunc) << "CMPD broken";
  const Outcome second = run(dir, args);
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_NE(second.err.find("collecting the demonstrations again"), std::string::npos)
      << second.err;
  const Outcome third = run(dir, args + " --no-cache");
  ASSERT_EQ(third.exit_code, 0) << third.err;
  ResultStore store(dir.file("r.sqlite"));
  EXPECT_EQ(
      read_file(testing::query_text(store, "SELECT out_dir FROM runs WHERE id = 3") + "/log.txt")
          .find("reusing cached demonstrations"),
      std::string::npos);
  for (int run_id : {2, 3}) {
    EXPECT_EQ(
        testing::query_int(store,
                           "SELECT COUNT(*) FROM (SELECT name, value FROM metrics WHERE "
                           "run_id = 1 EXCEPT SELECT name, value FROM metrics WHERE run_id = " +
                               std::to_string(run_id) + ")"),
        0);
  }
}

// The rope task end to end at a tiny size: the colour-segmented context,
// the trial rows with their contexts, true offsets and outcomes, the figures.
TEST(RunExperiment, ATinyRopeRunRecordsKnotOutcomesAndContexts) {
  TempDir dir;
  const Outcome outcome =
      run(dir, std::string(PROJECT_DIR) +
                   "/configs/rope_color.yaml demonstrations.train=3 demonstrations.validation=1 "
                   "policy.training.updates=200 policy.training.validate_every=100 "
                   "policy.network.width=16 evaluation.trials=2");
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_NE(outcome.out.find("Table I (rope_color)"), std::string::npos) << outcome.out;
  EXPECT_NE(outcome.out.find("knot"), std::string::npos) << outcome.out;
  ResultStore store(dir.file("r.sqlite"));
  EXPECT_EQ(
      testing::query_int(store,
                         "SELECT COUNT(*) FROM trials WHERE run_id = 1 AND details LIKE "
                         "'%\"contexts\":{\"cor\":[%' AND details LIKE '%critical_end_dx%' "
                         "AND scenario LIKE '%grasp_offset%' AND (success = 1 OR failure <> '')"),
      2);
  for (const char* name :
       {"task_success_rate", "knot_rate", "enclosed_rate", "demonstrations_context_error_median_mm",
        "context_found_rate", "demonstrations_context_found_rate", "cor_mp_error_mean_cm",
        "failures_missed_enclose"}) {
    EXPECT_FALSE(testing::query_text(store,
                                     "SELECT value FROM metrics WHERE run_id = 1 AND "
                                     "name = '" +
                                         std::string(name) + "'")
                     .empty())
        << name;
  }
  const std::string run_dir = testing::query_text(store, "SELECT out_dir FROM runs WHERE id = 1");
  for (const char* file : {"knotting.png", "segmentation_0.png", "trajectories.png",
                           "trajectories.csv", "tables.txt", "models/cor.cnmp"}) {
    EXPECT_TRUE(std::filesystem::exists(run_dir + "/" + file)) << file;
  }
}

}  // namespace
}  // namespace corrmp
