// Tests of experiment/provenance.hpp: the git state a run records is the one the binary was built
// from, and a changed source tree is reported.
#include "experiment/provenance.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace corrmp {
namespace {

bool is_commit_hash(const std::string& text) {
  return text.size() == 40 && text.find_first_not_of("0123456789abcdef") == std::string::npos;
}

TEST(Provenance, TheBuildStateNamesACommitOfThisSourceTree) {
  const GitState built = build_git_state();
  const GitState now = source_git_state();
  if (now.commit == "unknown") GTEST_SKIP() << "the source tree is not a git checkout";
  ASSERT_TRUE(is_commit_hash(built.commit)) << built.commit;
  // The binary was built from HEAD or from a commit before it (a commit made since the build).
  const std::string ancestry = fmt::format("git -C '{}' merge-base --is-ancestor {} {}",
                                           CORRMP_SOURCE_DIR, built.commit, now.commit);
  EXPECT_EQ(std::system(ancestry.c_str()), 0) << ancestry;
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
