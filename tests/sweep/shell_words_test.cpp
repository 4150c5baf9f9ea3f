// Tests of sweep/shell_words.hpp: plain words stay as they are, others are quoted so that
// bash reads back exactly the text (checked by running bash).
#include "sweep/shell_words.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace corrmp {
namespace {

// What bash makes of `word` as one argument of printf %s.
std::string read_back_by_bash(const std::string& word) {
  const std::string command = "bash -c " + shell_quoted("printf %s " + word);
  FILE* pipe = ::popen(command.c_str(), "r");
  std::string out;
  char buffer[256];
  size_t got = 0;
  while ((got = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) out.append(buffer, got);
  ::pclose(pipe);
  return out;
}

TEST(ShellWords, PlainWordsStayAndOthersAreQuoted) {
  EXPECT_EQ(shell_word("/tmp/results/r.sqlite"), "/tmp/results/r.sqlite");
  EXPECT_EQ(shell_word("a,b=c:d+e-f@g%h"), "a,b=c:d+e-f@g%h");
  EXPECT_EQ(shell_word("my results/r.sqlite"), "'my results/r.sqlite'");
  EXPECT_EQ(shell_word("it's"), "'it'\\''s'");
  EXPECT_EQ(shell_word(""), "''");
}

TEST(ShellWords, BashReadsBackTheText) {
  for (const std::string text : {"plain/path.sqlite", "with space", "it's", "$HOME", "a;b|c&d",
                                 "*?[x]", "back\\slash", "\"quoted\"", "tab\there"}) {
    EXPECT_EQ(read_back_by_bash(shell_word(text)), text) << text;
  }
}

}  // namespace
}  // namespace corrmp
