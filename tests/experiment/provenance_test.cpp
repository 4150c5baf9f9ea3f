// Tests of experiment/provenance.hpp: the git state a run records is the one the binary was built
// from, and a changed source tree is reported.
#include "experiment/provenance.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include "config/test_files.hpp"

namespace corrmp {
namespace {

bool is_commit_hash(const std::string& text) {
  return text.size() == 40 && text.find_first_not_of("0123456789abcdef") == std::string::npos;
}

TEST(Provenance, TheBuildStateNamesACommitOfThisSourceTree) {
  const GitState built = build_git_state();
  if (built.commit == "unknown") GTEST_SKIP() << "built from a tree that is not a git checkout";
  ASSERT_TRUE(is_commit_hash(built.commit)) << built.commit;
  const std::string exists =
      fmt::format("git -C '{}' cat-file -e {}^{{commit}}", CORRMP_SOURCE_DIR, built.commit);
  EXPECT_EQ(std::system(exists.c_str()), 0) << exists;
}

// cmake/build_info.cmake on a repository of its own: the commit, clean, then dirty once a
// tracked file changes; and "unknown" for a folder inside another repository's work tree.
TEST(Provenance, TheBuildScriptReadsCommitAndDirtyFlag) {
  if (std::system("git --version >/dev/null 2>&1") != 0) GTEST_SKIP() << "no git";
  const testing::TempDir dir;
  const std::string repo = dir.file("repo"), out = dir.file("state.cpp");
  const auto run = [](const std::string& command) {
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
  };
  run(
      fmt::format("mkdir -p '{0}/inner' && cd '{0}' && git init -q && echo a > f && git add f && "
                  "git -c user.email=t@t -c user.name=t commit -qm first",
                  repo));
  const auto state_of = [&](const std::string& source) {
    run(fmt::format("'{}' -DSOURCE_DIR='{}' -DOUTPUT='{}' -P '{}/cmake/build_info.cmake'",
                    CMAKE_BIN, source, out, CORRMP_SOURCE_DIR));
    std::ifstream in(out);
    std::stringstream text;
    text << in.rdbuf();
    const std::string code = text.str();
    const auto begin = code.find("return {");
    return begin == std::string::npos ? code : code.substr(begin, code.find('}', begin) - begin);
  };
  std::string head;
  {
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(
        popen(fmt::format("git -C '{}' rev-parse HEAD", repo).c_str(), "r"), pclose);
    char line[64] = {};
    ASSERT_NE(fgets(line, sizeof line, pipe.get()), nullptr);
    head = std::string(line).substr(0, 40);
  }
  EXPECT_EQ(state_of(repo), "return {\"" + head + "\", false");
  run(fmt::format("echo b >> '{}/f'", repo));
  EXPECT_EQ(state_of(repo), "return {\"" + head + "\", true");
  EXPECT_EQ(state_of(repo + "/inner"), "return {\"unknown\", false");
}

TEST(Provenance, AChangedSourceTreeIsReportedWithBothStates) {
  const std::string a(40, 'a'), b(40, 'b');
  EXPECT_EQ(source_change_warning({a, false}, {a, false}), "");
  EXPECT_EQ(source_change_warning({a, true}, {a, true}), "");

  const std::string moved = source_change_warning({a, false}, {b, false});
  EXPECT_NE(moved.find("built from aaaaaaaaaaaa,"), std::string::npos) << moved;
  EXPECT_NE(moved.find("now at bbbbbbbbbbbb;"), std::string::npos) << moved;

  const std::string edited = source_change_warning({a, false}, {a, true});
  EXPECT_NE(edited.find("now at aaaaaaaaaaaa with uncommitted changes"), std::string::npos)
      << edited;
  const std::string reverted = source_change_warning({a, true}, {a, false});
  EXPECT_NE(reverted.find("built from aaaaaaaaaaaa with uncommitted changes"), std::string::npos)
      << reverted;
}

TEST(Provenance, NoWarningWhenEitherStateIsUnknown) {
  const std::string a(40, 'a');
  EXPECT_EQ(source_change_warning({"unknown", false}, {a, true}), "");
  EXPECT_EQ(source_change_warning({a, false}, {"unknown", false}), "");
}

}  // namespace
}  // namespace corrmp
