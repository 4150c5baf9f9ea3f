// Tests of scripts/reproduce_paper's help (docs/usage.md, "Reproducing the paper"): it is the
// script's header comment, whole and nothing after it. The reproduction itself installs, builds and
// runs for minutes; the sweep and report it calls are tested in tests/sweep and tests/report.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <memory>
#include <string>

namespace {

std::string output_of(const std::string& command) {
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  std::array<char, 256> buffer{};
  std::string text;
  while (pipe && fgets(buffer.data(), buffer.size(), pipe.get()) != nullptr) text += buffer.data();
  return text;
}

TEST(ReproducePaper, HelpIsTheWholeHeaderCommentAndNothingElse) {
  const std::string help =
      output_of(std::string("bash ") + PROJECT_DIR + "/scripts/reproduce_paper --help 2>&1");
  EXPECT_EQ(help.rfind("scripts/reproduce_paper [--quick | --full] [-j N] [--out DIR]", 0), 0u)
      << help;
  EXPECT_NE(help.find("--out DIR writes the database, runs and report into DIR"), std::string::npos)
      << help;
  EXPECT_NE(help.find("prints how to resume (--resume SWEEP_ID).\n"), std::string::npos) << help;
  EXPECT_EQ(help.find("set -euo"), std::string::npos) << help;
  EXPECT_EQ(help.find('#'), std::string::npos) << help;
}

}  // namespace
