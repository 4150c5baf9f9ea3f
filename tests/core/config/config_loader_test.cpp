// Tests of config includes (deep merge of maps, replacement of scalars and
// lists) and command-line overrides.
#include "core/config/config_loader.hpp"

#include <gtest/gtest.h>

#include "core/config/config_reader.hpp"
#include "test_files.hpp"

namespace corrmp {
namespace {

using testing::config_error_of;
using testing::TempDir;

std::string text_at(const ConfigNode& root, const std::string& a, const std::string& b) {
  return root.find(a)->find(b)->text();
}

TEST(ConfigInclude, DeepMergesMapsAndReplacesScalarsAndLists) {
  TempDir dir;
  dir.write("common/cnmp.yaml",
            "policy:\n  lr: 0.0001\n  width: 128\n  strides: [2, 1, 2]\nseed: 1\n");
  const auto path = dir.write("exp.yaml",
                              "include: [common/cnmp.yaml]\npolicy:\n  width: 64\n"
                              "  strides: [1]\nseed: 5\n");
  const ConfigNode root = load_config_file(path);
  EXPECT_EQ(root.find("include"), nullptr);
  EXPECT_EQ(text_at(root, "policy", "lr"), "0.0001");
  EXPECT_EQ(text_at(root, "policy", "width"), "64");
  ASSERT_EQ(root.find("policy")->find("strides")->items().size(), 1u);
  EXPECT_EQ(root.find("seed")->text(), "5");
  // Locations still point at the file each value came from.
  EXPECT_EQ(root.find("policy")->find("lr")->where().file, dir.file("common/cnmp.yaml"));
  EXPECT_EQ(root.find("policy")->find("width")->where().line, 3);
}

TEST(ConfigInclude, LaterIncludesOverrideEarlierOnesAndNestedIncludesWork) {
  TempDir dir;
  dir.write("base.yaml", "a: {x: 1, y: 1}\n");
  dir.write("mid.yaml", "include: base.yaml\na: {y: 2}\n");
  dir.write("other.yaml", "a: {z: 3}\n");
  const auto path = dir.write("top.yaml", "include: [mid.yaml, other.yaml]\n");
  const ConfigNode root = load_config_file(path);
  EXPECT_EQ(text_at(root, "a", "x"), "1");
  EXPECT_EQ(text_at(root, "a", "y"), "2");
  EXPECT_EQ(text_at(root, "a", "z"), "3");
}

TEST(ConfigInclude, MissingFileAndCyclesAreErrors) {
  TempDir dir;
  const auto missing = dir.write("m.yaml", "include: [nope.yaml]\n");
  EXPECT_NE(config_error_of([&] {
              load_config_file(missing);
            }).find("m.yaml:1:11: include: included file"),
            std::string::npos);
  dir.write("a.yaml", "include: b.yaml\n");
  const auto b = dir.write("b.yaml", "include: a.yaml\n");
  EXPECT_NE(config_error_of([&] { load_config_file(b); }).find("include cycle"), std::string::npos);
}

TEST(ConfigOverride, ReplacesScalarsAndListsAndAddsKeys) {
  TempDir dir;
  const auto path = dir.write("exp.yaml",
                              "policy:\n  width: 128\n  strides: [2]\nseed: 1\n"
                              "segments:\n  - {name: pre}\n  - {name: cor}\n");
  const ConfigNode root =
      load_config(path, {"policy.width=64", "policy.strides=[1, 2, 3]", "seed=9", "policy.lr=0.5",
                         "segments.1.name=post", "evaluation.trials=3"});
  EXPECT_EQ(text_at(root, "policy", "width"), "64");
  EXPECT_EQ(root.find("policy")->find("strides")->items().size(), 3u);
  EXPECT_EQ(root.find("seed")->text(), "9");
  EXPECT_EQ(text_at(root, "policy", "lr"), "0.5");
  EXPECT_EQ(root.find("segments")->items().back().find("name")->text(), "post");
  EXPECT_EQ(text_at(root, "evaluation", "trials"), "3");
  EXPECT_EQ(root.find("policy")->find("width")->where().file,
            "command-line override 'policy.width=64'");
}

TEST(ConfigOverride, MalformedOverridesAreErrors) {
  TempDir dir;
  const auto path = dir.write("exp.yaml", "policy: {width: 1}\nsegments: [a]\n");
  EXPECT_EQ(config_error_of([&] { load_config(path, {"policy.width"}); }),
            "command-line override 'policy.width': expected key.path=value");
  EXPECT_EQ(config_error_of([&] { load_config(path, {"policy.width.x=1"}); }),
            "command-line override 'policy.width.x=1': policy.width.x: cannot override inside a "
            "scalar");
  EXPECT_EQ(config_error_of([&] { load_config(path, {"segments.4=b"}); }),
            "command-line override 'segments.4=b': segments.4: list index 4 is out of range: the "
            "list has 1 element");
}

struct Small {
  int width = 1;
  template <class F>
  void describe(F& f) {
    f("width", width, "width");
  }
};
struct Top {
  Small policy;
  template <class F>
  void describe(F& f) {
    f("policy", policy, "policy");
  }
};

TEST(ConfigOverride, OverridingAKeyThatDoesNotExistIsAnErrorNamingTheOverride) {
  TempDir dir;
  const auto path = dir.write("exp.yaml", "policy: {width: 1}\n");
  ConfigNode root = load_config(path, {"policy.widht=3"});
  Top top;
  EXPECT_EQ(config_error_of([&] { ConfigReader::read(root, "", top); }),
            "command-line override 'policy.widht=3': policy.widht: unknown key (did you mean "
            "'width'?)");
  ConfigNode root2 = load_config(path, {"polcy.width=3"});
  EXPECT_EQ(config_error_of([&] { ConfigReader::read(root2, "", top); }),
            "command-line override 'polcy.width=3': polcy: unknown key (did you mean 'policy'?)");
}

}  // namespace
}  // namespace corrmp
