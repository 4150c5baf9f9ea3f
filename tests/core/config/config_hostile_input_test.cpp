// Tests of config input that is broken or hostile: several documents, paths
// that are not regular files, text that is not UTF-8, unbounded input (alias
// bombs, huge files, deep nesting), include cycles, duplicate keys and
// out-of-range list indexes. Each must end as one ConfigError line naming
// where, never a crash, a hang or another exception.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <string>

#include "core/config/config_loader.hpp"
#include "test_files.hpp"

namespace corrmp {
namespace {

using testing::config_error_of;
using testing::TempDir;

// The ConfigError of loading `text` as a config file, or "" for none.
std::string error_loading(const TempDir& dir, const std::string& text,
                          const std::vector<std::string>& overrides = {}) {
  const auto path = dir.write("exp.yaml", text);
  return config_error_of([&] { load_config(path, overrides); });
}

// "<dir>/exp.yaml" followed by `rest`.
std::string at(const TempDir& dir, const std::string& rest) { return dir.file("exp.yaml") + rest; }

std::string repeat(const std::string& text, int times) {
  std::string out;
  for (int i = 0; i < times; ++i) out += text;
  return out;
}

// An alias bomb: each level a list of nine aliases to the level below, so
// `levels` levels expand to 9^levels scalars.
std::string alias_bomb(int levels) {
  std::string text = "l0: &l0 [x, x, x, x, x, x, x, x, x]\n";
  for (int level = 1; level < levels; ++level) {
    const std::string below = "*l" + std::to_string(level - 1);
    text += "l" + std::to_string(level) + ": &l" + std::to_string(level) + " [";
    for (int i = 0; i < 9; ++i) text += (i > 0 ? ", " : "") + below;
    text += "]\n";
  }
  return text;
}

TEST(ConfigHostileInput, ASecondDocumentIsAnErrorNamingItsLine) {
  TempDir dir;
  EXPECT_EQ(error_loading(dir, "a: 1\nb: 2\n---\nc: 3\n"),
            at(dir, ":3:1: a second YAML document: a config file holds exactly one"));
  // Without `---` (after an end marker `...`), the second document's first line.
  EXPECT_EQ(error_loading(dir, "a: 1\n...\nc: 3\n"),
            at(dir, ":3:1: a second YAML document: a config file holds exactly one"));
  // A lone `---` first line starts the only document.
  EXPECT_EQ(error_loading(dir, "---\na: 1\n"), "");
}

TEST(ConfigHostileInput, IncludesThatAreNotRegularFilesAreRefused) {
  TempDir dir;
  dir.write("common/cnmp.yaml", "a: 1\n");
  EXPECT_EQ(error_loading(dir, "seed: 1\ninclude: [common]\n"),
            at(dir, ":2:11: include: included file '" + dir.file("common") +
                        "' is a directory, not a config file"));
  EXPECT_EQ(error_loading(dir, "include: /dev/zero\n"),
            at(dir,
               ":1:10: include: included file '/dev/zero' is not a regular file (a device, "
               "FIFO or socket?)"));
  ASSERT_EQ(::mkfifo(dir.file("fifo").c_str(), 0600), 0);
  EXPECT_EQ(error_loading(dir, "include: [fifo]\n"),
            at(dir, ":1:11: include: included file '" + dir.file("fifo") +
                        "' is not a regular file (a device, FIFO or socket?)"));
  EXPECT_EQ(
      error_loading(dir, "include: [nope.yaml]\n"),
      at(dir, ":1:11: include: included file '" + dir.file("nope.yaml") + "' does not exist"));
}

TEST(ConfigHostileInput, AConfigPathThatIsADirectorySaysSo) {
  TempDir dir;
  dir.write("configs/x.yaml", "a: 1\n");
  EXPECT_EQ(config_error_of([&] { load_config(dir.file("configs"), {}); }),
            dir.file("configs") + ": is a directory, not a config file");
  EXPECT_EQ(config_error_of([&] { load_config(dir.file("none.yaml"), {}); }),
            dir.file("none.yaml") + ": does not exist");
}

TEST(ConfigHostileInput, InvalidUtf8NamesTheFirstBadByte) {
  TempDir dir;
  EXPECT_EQ(error_loading(dir, "a: 1\nb: x\xff y\n"),
            at(dir, ":2:5: invalid UTF-8 (byte 0xff): config text must be UTF-8"));
  // An overlong encoding of '/' and a UTF-16 surrogate are not UTF-8 either.
  EXPECT_EQ(error_loading(dir, "a: \xc0\xaf\n"),
            at(dir, ":1:4: invalid UTF-8 (byte 0xc0): config text must be UTF-8"));
  EXPECT_EQ(error_loading(dir, "a: \xed\xa0\x80\n"),
            at(dir, ":1:4: invalid UTF-8 (byte 0xed): config text must be UTF-8"));
  // Valid multi-byte UTF-8 is kept as it is.
  const auto path = dir.write("ok.yaml", "name: caf\xc3\xa9 \xe2\x9c\x93\n");
  EXPECT_EQ(load_config(path, {}).find("name")->text(), "caf\xc3\xa9 \xe2\x9c\x93");
}

TEST(ConfigHostileInput, NulBytesAndControlCharactersAreNamed) {
  TempDir dir;
  EXPECT_EQ(error_loading(dir, std::string("a: 1\nb: x\0y\n", 12)),
            at(dir, ":2:5: NUL byte: config text cannot contain one"));
  EXPECT_EQ(error_loading(dir, std::string("a: \"x\0\"\n", 8)),
            at(dir, ":1:6: NUL byte: config text cannot contain one"));
  EXPECT_EQ(error_loading(dir, "a: x\x07y\n"),
            at(dir, ":1:5: control character U+0007 is not allowed in YAML"));
}

TEST(ConfigHostileInput, OverridesAreCheckedLikeFiles) {
  TempDir dir;
  EXPECT_EQ(error_loading(dir, "seed: 1\n", {"seed=\xff"}),
            "command-line override 'seed=\\xff': column 6: invalid UTF-8 (byte 0xff): config "
            "text must be UTF-8");
  // A line break in an override does not break the one-line message.
  const std::string error = error_loading(dir, "seed: 1\n", {"seed=[1\n"});
  EXPECT_EQ(error.rfind("command-line override 'seed=[1\\n':1:1: ", 0), 0u) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos);
  // A second document in an override.
  EXPECT_EQ(error_loading(dir, "seed: 1\n", {"seed=1\n---\n2"}),
            "command-line override 'seed=1\\n---\\n2':2:1: a second YAML document: a config file "
            "holds exactly one");
}

TEST(ConfigHostileInput, AnAliasBombStopsAtTheValueLimit) {
  TempDir dir;
  // 9^9 = 387 million scalars once expanded; the limit is reached at level 6.
  const std::string error = error_loading(dir, alias_bomb(9));
  EXPECT_EQ(error, at(dir,
                      ":6:10: l5[0]: the config holds more than 100000 values (counting every "
                      "alias expansion, include and override)"));
  // A few levels are fine.
  EXPECT_EQ(error_loading(dir, alias_bomb(4)), "");
}

TEST(ConfigHostileInput, TheValueLimitCountsIncludesAndOverrides) {
  TempDir dir;
  std::string list = "[0";
  for (int i = 1; i < 60000; ++i) list += ",0";
  list += "]";
  dir.write("big.yaml", "a: " + list + "\n");
  dir.write("big2.yaml", "a: " + list + "\n");
  // 7 values here, 60003 in big.yaml: big2.yaml reaches the limit.
  EXPECT_EQ(error_loading(dir, "include: [big.yaml, big2.yaml]\nb: 0\n"),
            dir.file("big2.yaml") +
                ":1:79979: a[39987]: the config holds more than 100000 values (counting every "
                "alias expansion, include and override)");
  EXPECT_NE(error_loading(dir, "include: [big.yaml]\n", {"b=" + list})
                .find("the config holds more than 100000 values"),
            std::string::npos);
}

TEST(ConfigHostileInput, FilesLargerThanTheLimitAreRefused) {
  TempDir dir;
  // A 10 MB single line.
  const std::string huge = "a: " + std::string(10 << 20, 'x') + "\n";
  EXPECT_EQ(error_loading(dir, huge),
            at(dir, ": is larger than 1 MiB, the limit for a config file"));
  dir.write("big.yaml", "a: " + std::string((1 << 20) + 1, 'x') + "\n");
  EXPECT_EQ(error_loading(dir, "include: big.yaml\n"),
            at(dir, ":1:10: include: included file '" + dir.file("big.yaml") +
                        "' is larger than 1 MiB, the limit for a config file"));
  // A large scalar within the limit is read.
  const auto path = dir.write("ok.yaml", "a: " + std::string(900000, 'y') + "\n");
  EXPECT_EQ(load_config(path, {}).find("a")->text().size(), 900000u);
}

TEST(ConfigHostileInput, DeepNestingIsAnErrorNamingTheLine) {
  TempDir dir;
  // Flow style, far deeper than yaml-cpp's own guard ("bad file").
  EXPECT_EQ(
      error_loading(dir, "a: 1\nb: " + std::string(5000, '[') + std::string(5000, ']')),
      at(dir, ":2:67: b" + repeat("[0]", 63) + ": lists and maps nested more than 64 levels deep"));
  // Block style: one level per line.
  std::string block;
  for (int level = 0; level < 70; ++level) block += std::string(level, ' ') + "k:\n";
  const std::string error = error_loading(dir, block);
  EXPECT_NE(error.find(at(dir, ":65:65: k.k.k.")), std::string::npos) << error;
  EXPECT_NE(error.find(": lists and maps nested more than 64 levels deep"), std::string::npos);
  // 64 levels are fine.
  EXPECT_EQ(error_loading(dir, "a: " + std::string(63, '[') + std::string(63, ']') + "\n"), "");
  // An override's value counts from where its keys put it.
  EXPECT_NE(error_loading(dir, "a: 1\n", {"x.y=" + std::string(63, '[') + std::string(63, ']')})
                .find("nested more than 64 levels deep"),
            std::string::npos);
}

TEST(ConfigHostileInput, IncludeCyclesNameTheLineAndTheChain) {
  TempDir dir;
  dir.write("a.yaml", "seed: 1\ninclude: b.yaml\n");
  dir.write("b.yaml", "include: [c.yaml]\n");
  dir.write("c.yaml", "x: 1\ninclude: [a.yaml]\n");
  EXPECT_EQ(config_error_of([&] { load_config(dir.file("a.yaml"), {}); }),
            dir.file("c.yaml") + ":2:11: include: include cycle: " + dir.file("a.yaml") + " -> " +
                dir.file("b.yaml") + " -> " + dir.file("c.yaml") + " -> " + dir.file("a.yaml"));
  dir.write("self.yaml", "include: self.yaml\n");
  EXPECT_EQ(config_error_of([&] { load_config(dir.file("self.yaml"), {}); }),
            dir.file("self.yaml") + ":1:10: include: include cycle: " + dir.file("self.yaml") +
                " -> " + dir.file("self.yaml"));
}

TEST(ConfigHostileInput, DuplicateKeysNameTheFullKeyPath) {
  TempDir dir;
  EXPECT_EQ(error_loading(dir, "policy:\n  training:\n    updates: 1\n    updates: 2\n"),
            at(dir, ":4:5: policy.training.updates: duplicate key"));
  EXPECT_EQ(error_loading(dir, "segments:\n  - {name: a}\n  - {name: b, name: c}\n"),
            at(dir, ":3:15: segments[1].name: duplicate key"));
}

TEST(ConfigHostileInput, OverrideListIndexesOutOfRangeAreConfigErrors) {
  TempDir dir;
  const std::string text = "policy:\n  segments: [{name: a}, {name: b}]\n";
  EXPECT_EQ(error_loading(dir, text, {"policy.segments.99999999999999999999999.name=x"}),
            "command-line override 'policy.segments.99999999999999999999999.name=x': "
            "policy.segments.99999999999999999999999: list index 99999999999999999999999 is out "
            "of range: the list has 2 elements");
  EXPECT_EQ(error_loading(dir, text, {"policy.segments.first.name=x"}),
            "command-line override 'policy.segments.first.name=x': policy.segments.first: "
            "'first' is not a list index: the list has 2 elements");
  EXPECT_EQ(error_loading(dir, text, {"policy.segments.1.name=x"}), "");
  EXPECT_EQ(error_loading(dir, text, {"policy..x=1"}),
            "command-line override 'policy..x=1': policy..x: empty key in path");
}

TEST(ConfigHostileInput, OtherHostileYamlEndsAsAConfigErrorWithALocation) {
  TempDir dir;
  // A tab used for indentation.
  EXPECT_EQ(error_loading(dir, "a:\n\tb: 1\n"),
            at(dir, ":2:3: YAML syntax error: illegal map value"));
  // Merge keys are not supported (yaml-cpp would keep "<<" as an ordinary key).
  EXPECT_EQ(error_loading(dir, "base: &b {x: 1}\nd:\n  <<: *b\n  y: 2\n"),
            at(dir,
               ":3:3: d.<<: YAML merge keys (<<) are not supported: write the keys out, or "
               "put shared keys in a file named by include:"));
  // Keys that are not scalars.
  EXPECT_EQ(error_loading(dir, "? [a, b]\n: 1\n"),
            at(dir, ":1:3: map keys must be scalars, not lists"));
  EXPECT_EQ(error_loading(dir, "a: {? {b: 1} : 2}\n"),
            at(dir, ":1:7: a: map keys must be scalars, not maps"));
  EXPECT_EQ(error_loading(dir, "a: {: 2}\n"), at(dir, ":1:5: a: empty map key"));
  // An alias inside the list it refers to would be an endless tree.
  EXPECT_EQ(error_loading(dir, "a: &a [x, *a]\n"),
            at(dir, ":1:11: a[1]: this alias refers to a list or map that contains it"));
  // A byte order mark at the start is allowed; UTF-16 is not.
  const auto bom = dir.write("bom.yaml",
                             "\xef\xbb\xbf"
                             "a: 1\n");
  EXPECT_EQ(load_config(bom, {}).find("a")->text(), "1");
  EXPECT_EQ(error_loading(dir, std::string("\xff\xfe"
                                           "a\0:\0 \0001\0\n\0",
                                           12)),
            at(dir, ":1:1: the text is UTF-16 or UTF-32: config text must be UTF-8"));
  EXPECT_EQ(error_loading(dir, "a: 1\nb: \xef\xbb\xbf\n"),
            at(dir, ":2:4: byte order mark (U+FEFF) after the start of the text"));
  // Characters written as escapes are checked too: a NUL would cut a file name short.
  EXPECT_EQ(error_loading(dir, "a: \"x\\0y\"\n"),
            at(dir,
               ":1:4: a: a character written as an escape is not allowed: NUL byte: config "
               "text cannot contain one"));
  EXPECT_EQ(error_loading(dir, "include: \"big.yaml\\0\"\n"),
            at(dir,
               ":1:10: include: a character written as an escape is not allowed: NUL byte: "
               "config text cannot contain one"));
  EXPECT_EQ(error_loading(dir, "a: \"\\x07\"\n"),
            at(dir,
               ":1:4: a: a character written as an escape is not allowed: control character "
               "U+0007 is not allowed in YAML"));
  // An include name with a line break stays on one line in the message.
  EXPECT_EQ(error_loading(dir, "include: \"x\\ny\"\n"),
            at(dir, ":1:10: include: included file '" + dir.file("x\\ny") + "' does not exist"));
}

}  // namespace
}  // namespace corrmp
