// Tests of where a component's parameter error points: the value's node under its section,
// its stated location or the section's when it is a default, and file-name checks.
#include "core/parameter_error.hpp"

#include <gtest/gtest.h>

#include "config/test_files.hpp"
#include "core/config/config_loader.hpp"

namespace corrmp {
namespace {

using testing::TempDir;

ConfigNode load(const std::string& text, const std::vector<std::string>& overrides = {}) {
  static TempDir dir;
  return load_config(dir.write("c.yaml", text), overrides);
}

TEST(ParameterError, NodeAtFollowsMapsAndSequences) {
  const ConfigNode root = load("a:\n  b:\n    - {c: 1}\n    - {c: 2}\n");
  EXPECT_EQ(node_at(root, "a.b[1].c").where().line, 4);
  EXPECT_EQ(node_at(root, "a.b[0]").where().line, 3);
}

TEST(ParameterError, NodeAtStopsAtTheDeepestNodeOnTheWay) {
  const ConfigNode root = load("a:\n  b: {c: 1}\n");
  EXPECT_EQ(&node_at(root, "a.b.missing.deeper"), &node_at(root, "a.b"));
  EXPECT_EQ(&node_at(root, "a.b[7]"), &node_at(root, "a.b"));
  EXPECT_EQ(&node_at(root, "a[x]"), &node_at(root, "a"));
}

TEST(ParameterError, StatedLocationIsTheOverrideOrTheFileLine) {
  const ConfigNode root = load("a:\n  b: 1\n  c: 2\n", {"a.c=3"});
  const SourceLocation otherwise{"elsewhere", 9, 9};
  EXPECT_EQ(stated_location(root, "a.b", otherwise).line, 2);
  EXPECT_NE(stated_location(root, "a.c", otherwise).file.find("a.c=3"), std::string::npos);
}

TEST(ParameterError, StatedLocationOfADefaultIsTheFallback) {
  ConfigNode root = load("a: {b: 1}\n");
  root.find("a")->set("d", ConfigNode::scalar("4", SourceLocation{"<default>", 0, 0}),
                      SourceLocation{"<default>", 0, 0});
  const SourceLocation otherwise{"section.yaml", 7, 1};
  EXPECT_EQ(stated_location(root, "a.d", otherwise).file, "section.yaml");
  EXPECT_EQ(stated_location(root, "a.d", otherwise).line, 7);
}

TEST(ParameterError, SafeFileNamesStayInTheirDirectory) {
  EXPECT_TRUE(is_safe_file_name("cor_mp-2.v1"));
  for (const std::string bad : {"", ".", "..", ".hidden", "../x", "a/b", "a\\b", "a b", "é"})
    EXPECT_FALSE(is_safe_file_name(bad)) << bad;
  EXPECT_THROW(check_file_name("segments[0].name", "../x"), ParameterError);
  try {
    check_file_name("segments[0].name", "../x");
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.key(), "segments[0].name");
  }
}

}  // namespace
}  // namespace corrmp
