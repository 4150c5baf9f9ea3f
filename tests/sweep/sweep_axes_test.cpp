// Sweep axes, their cross product, sweep files and the manifest
// (framework/sweep/sweep_axes.hpp, sweep_definition.hpp, sweep_manifest.hpp).
#include <gtest/gtest.h>

#include "config/test_files.hpp"
#include "sweep/sweep_axes.hpp"
#include "sweep/sweep_definition.hpp"
#include "sweep/sweep_manifest.hpp"

namespace corrmp {
namespace {

using testing::TempDir;

std::vector<std::string> values(const std::string& text) {
  return parse_axis_values(text, SourceLocation{"test", 0, 0}, "key");
}

std::string error_of(const std::string& text) {
  try {
    values(text);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(SweepAxes, ReadsListsRangesAndChoices) {
  EXPECT_EQ(values("a,b,c"), (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_EQ(values("range(3)"), (std::vector<std::string>{"0", "1", "2"}));
  EXPECT_EQ(values("range(2, 8, 3)"), (std::vector<std::string>{"2", "5"}));
  EXPECT_EQ(values("range(3,0,-1)"), (std::vector<std::string>{"3", "2", "1"}));
  EXPECT_EQ(values("choice(x, [1, 2])"), (std::vector<std::string>{"x", "[1, 2]"}));
  EXPECT_EQ(values("[1,2],[3,4]"), (std::vector<std::string>{"[1,2]", "[3,4]"}));
  EXPECT_EQ(values("7"), (std::vector<std::string>{"7"}));
}

TEST(SweepAxes, RefusesEmptyAndMalformedAxes) {
  EXPECT_NE(error_of("range(5, 0)").find("is empty"), std::string::npos);
  EXPECT_NE(error_of("range(0, 5, 0)").find("step must not be 0"), std::string::npos);
  EXPECT_NE(error_of("range(a)").find("not an integer"), std::string::npos);
  EXPECT_NE(error_of("range(1,2,3,4)").find("takes"), std::string::npos);
  EXPECT_NE(error_of("range(0, 1000000000)").find("more than"), std::string::npos);
  EXPECT_NE(error_of("choice()").find("at least one"), std::string::npos);
  EXPECT_NE(error_of("a,,b").find("empty value"), std::string::npos);
  EXPECT_NE(error_of("").find("empty value"), std::string::npos);
}

// Values are counted and made without stepping past the ends of the 64-bit integers.
TEST(SweepAxes, RangesAtTheEdgesOfTheIntegersNeverOverflow) {
  EXPECT_EQ(values("range(9223372036854775805, 9223372036854775807)"),
            (std::vector<std::string>{"9223372036854775805", "9223372036854775806"}));
  EXPECT_EQ(values("range(-9223372036854775808, -9223372036854775806)"),
            (std::vector<std::string>{"-9223372036854775808", "-9223372036854775807"}));
  EXPECT_EQ(values("range(9000000000000000000, -9000000000000000000, -6000000000000000000)"),
            (std::vector<std::string>{"9000000000000000000", "3000000000000000000",
                                      "-3000000000000000000"}));
  EXPECT_NE(error_of("range(9223372036854775800, 9223372036854775807, 5)")
                .find("beyond the 64-bit integers"),
            std::string::npos);
  EXPECT_NE(error_of("range(-9223372036854775800, -9223372036854775808, -5)")
                .find("beyond the 64-bit integers"),
            std::string::npos);
  EXPECT_NE(error_of("range(-9223372036854775808, 9223372036854775807)").find("more than"),
            std::string::npos);
  EXPECT_NE(error_of("range(9223372036854775807, -9223372036854775808, -1)").find("more than"),
            std::string::npos);
  EXPECT_NE(error_of("range(0, 9223372036854775808)").find("not an integer"), std::string::npos);
}

TEST(SweepAxes, AnUnmatchedQuoteIsAnError) {
  EXPECT_NE(error_of("it's,b").find("unmatched ' in \"it's,b\""), std::string::npos);
  EXPECT_NE(error_of("\"a,b").find("unmatched \""), std::string::npos);
  EXPECT_EQ(values("\"it's\",b"), (std::vector<std::string>{"\"it's\"", "b"}));
  EXPECT_EQ(values("'it''s',b"), (std::vector<std::string>{"'it''s'", "b"}));
  EXPECT_EQ(values(R"("a\"b",c)"), (std::vector<std::string>{R"("a\"b")", "c"}));
}

TEST(SweepAxes, TellsSweepingAssignmentsFromPlainOnes) {
  EXPECT_TRUE(is_sweep_assignment("seed=0,1"));
  EXPECT_TRUE(is_sweep_assignment("seed=range(0,5)"));
  EXPECT_TRUE(is_sweep_assignment("x=choice(a)"));
  EXPECT_FALSE(is_sweep_assignment("seed=3"));
  EXPECT_FALSE(is_sweep_assignment("environment.camera.eye=[0.1, 0.2, 0.3]"));
  EXPECT_FALSE(is_sweep_assignment("experiment.name='a,b'"));
}

TEST(SweepAxes, CrossesConfigsAndAxesTheLastVaryingFastest) {
  const SweepAxis seed{"seed", {"0", "1"}, {}};
  const SweepAxis lr{"lr", {"a", "b", "c"}, {}};
  const auto jobs = expand_jobs({"one.yaml", "two.yaml"}, {"fixed=1"}, {{seed}, {lr}});
  ASSERT_EQ(jobs.size(), 12u);
  EXPECT_EQ(jobs[0].overrides, (std::vector<std::string>{"fixed=1", "seed=0", "lr=a"}));
  EXPECT_EQ(jobs[1].overrides, (std::vector<std::string>{"fixed=1", "seed=0", "lr=b"}));
  EXPECT_EQ(jobs[3].overrides, (std::vector<std::string>{"fixed=1", "seed=1", "lr=a"}));
  EXPECT_EQ(jobs[6].config_path, "two.yaml");
  EXPECT_EQ(jobs[11].index, 11);
  EXPECT_EQ(jobs[11].axes,
            (std::vector<std::pair<std::string, std::string>>{{"seed", "1"}, {"lr", "c"}}));
  EXPECT_EQ(expand_jobs({"one.yaml"}, {}, {}).size(), 1u);
}

TEST(SweepAxes, ZippedAxesAdvanceTogetherAndMustMatchInLength) {
  const SweepAxis seed{"seed", {"0", "1"}, {}};
  const SweepAxis evaluation{"evaluation.seed", {"100", "101"}, {}};
  const auto jobs = expand_jobs({"c.yaml"}, {}, {{seed, evaluation}});
  ASSERT_EQ(jobs.size(), 2u);
  EXPECT_EQ(jobs[1].overrides, (std::vector<std::string>{"seed=1", "evaluation.seed=101"}));
  const SweepAxis short_axis{"x", {"1"}, {}};
  EXPECT_THROW(expand_jobs({"c.yaml"}, {}, {{seed, short_axis}}), ConfigError);
  EXPECT_THROW(expand_jobs({"c.yaml"}, {}, {{seed}, {seed}}), ConfigError);
}

TEST(SweepDefinition, ReadsASweepFileWithCommandLineAxesAfterItsOwn) {
  TempDir dir;
  dir.write("base.yaml", "experiment: {name: base}\n");
  const std::string file = dir.write("sweeps/s.yaml", R"(
sweep:
  name: small
  configs: [../base.yaml]
  overrides: [evaluation.trials=2]
  axes:
    policy.training.updates: [100, 200]
  zip:
    seed: range(0, 2)
    evaluation.seed: range(100, 102)
  slurm: {cpus_per_task: 4, time: "00:10:00"}
)");
  EXPECT_TRUE(is_sweep_file(file));
  EXPECT_FALSE(is_sweep_file(dir.file("base.yaml")));
  const Sweep sweep = define_sweep(file, {"x=1", "y=a,b"});
  EXPECT_EQ(sweep.name, "small");
  EXPECT_EQ(sweep.id.rfind("small-", 0), 0u);
  EXPECT_EQ(sweep.slurm.cpus_per_task, 4);
  EXPECT_EQ(sweep.slurm.time, "00:10:00");
  EXPECT_EQ(sweep.slurm.memory, "4G");
  ASSERT_EQ(sweep.jobs.size(), 8u);
  EXPECT_EQ(sweep.jobs[0].config_path, (dir.path() / "base.yaml").string());
  EXPECT_EQ(sweep.jobs[7].overrides,
            (std::vector<std::string>{"evaluation.trials=2", "x=1", "policy.training.updates=200",
                                      "seed=1", "evaluation.seed=101", "y=b"}));
}

TEST(SweepDefinition, RefusesMalformedSweepFiles) {
  TempDir dir;
  const auto message = [&](const std::string& text) {
    try {
      define_sweep(dir.write("s.yaml", text), {});
    } catch (const ConfigError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message("sweep: {name: s, configs: [a.yaml], axis: {}}\n").find("sweep.axis"),
            std::string::npos);
  EXPECT_NE(message("sweep: {name: s}\n").find("sweep.configs: missing"), std::string::npos);
  EXPECT_NE(message("sweep: {name: s, configs: []}\n").find("no config"), std::string::npos);
  EXPECT_NE(message("sweep: {name: ../x, configs: [a.yaml]}\n").find("sweep.name"),
            std::string::npos);
  EXPECT_NE(
      message("sweep: {name: s, configs: [a.yaml], axes: {seed: []}}\n").find("sweep.axes.seed"),
      std::string::npos);
  EXPECT_NE(
      message("sweep: {name: s, configs: [a.yaml], slurm: {cpus: 2}}\n").find("sweep.slurm.cpus"),
      std::string::npos);
  EXPECT_NE(message("sweep: {name: s, configs: [a.yaml]}\nseed: 1\n").find("only a `sweep:`"),
            std::string::npos);
}

TEST(SweepManifest, RoundTripsEveryField) {
  Sweep sweep;
  sweep.id = "s-1";
  sweep.name = "s";
  sweep.slurm = {8, "02:00:00", "16G", "gpu"};
  sweep.jobs = expand_jobs(
      {"/a b/c.yaml"}, {"name='x: y'"},
      {{SweepAxis{"seed", {"0", "1"}, {}}}, {SweepAxis{"eye", {"[1, 2, 3]", "\"q\""}, {}}}});
  sweep.config_hashes = {{"/a b/c.yaml", "0123456789abcdef"}};
  const Sweep back = parse_manifest(manifest_yaml(sweep), "test");
  EXPECT_EQ(back.id, sweep.id);
  EXPECT_EQ(back.config_hashes, sweep.config_hashes);
  EXPECT_EQ(back.slurm.partition, "gpu");
  EXPECT_EQ(back.slurm.cpus_per_task, 8);
  ASSERT_EQ(back.jobs.size(), 4u);
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(back.jobs[i].overrides, sweep.jobs[i].overrides);
    EXPECT_EQ(back.jobs[i].axes, sweep.jobs[i].axes);
    EXPECT_EQ(back.jobs[i].config_path, "/a b/c.yaml");
  }
  EXPECT_EQ(axes_json(back.jobs[3]), R"({"seed":"1","eye":"\"q\""})");
  EXPECT_THROW(parse_manifest("jobs: 3", "bad"), std::runtime_error);
  sweep.id = "../s-1";
  EXPECT_EQ(testing::config_error_of([&] { parse_manifest(manifest_yaml(sweep), "m.yaml"); }),
            "m.yaml: id: '../s-1' is not a valid sweep id (up to 128 letters, digits, '_', '-', "
            "'.', not starting with '.')");
}

}  // namespace
}  // namespace corrmp
