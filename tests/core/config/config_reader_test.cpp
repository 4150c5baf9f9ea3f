// Tests of strict typed config reading: every error kind names file:line:column
// and the dotted key path; defaults are written back into the tree.
#include "core/config/config_reader.hpp"

#include <gtest/gtest.h>

#include <map>

#include "core/config/config_loader.hpp"
#include "test_files.hpp"

namespace corrmp {
namespace {

using testing::config_error_of;
using testing::TempDir;

struct LayerParams {
  int width = 128;
  int depth = 3;
  template <class F>
  void describe(F& f) {
    f("width", width, "layer width", at_least(1));
    f("depth", depth, "layer count", in_range(1, 16));
  }
};

struct ModelParams {
  std::string name;
  double lr = 1e-4;
  bool verbose = false;
  std::vector<int> strides{2, 1, 2};
  std::string activation = "relu";
  LayerParams encoder;
  std::vector<LayerParams> heads;
  std::optional<LayerParams> extra;
  template <class F>
  void describe(F& f) {
    f("name", name, "model name", required());
    f("lr", lr, "learning rate", positive());
    f("verbose", verbose, "chatty");
    f("strides", strides, "conv strides", at_least(1));
    f("activation", activation, "nonlinearity", one_of({"relu", "tanh"}));
    f("encoder", encoder, "encoder");
    f("heads", heads, "output heads");
    f("extra", extra, "optional extra layer");
  }
};

ModelParams read_yaml(const std::string& path) {
  ConfigNode root = load_config(path, {});
  ModelParams params;
  ConfigReader::read(root, "", params);
  return params;
}

TEST(ConfigReader, ReadsTypedValuesAndWritesDefaultsBack) {
  TempDir dir;
  const auto path = dir.write("m.yaml",
                              "name: cnmp\nlr: 0.001\nstrides: [1, 2]\n"
                              "encoder: {width: 64}\nheads:\n  - {depth: 2}\n  - {width: 8}\n");
  ConfigNode root = load_config(path, {});
  ModelParams params;
  ConfigReader::read(root, "", params);
  EXPECT_EQ(params.name, "cnmp");
  EXPECT_DOUBLE_EQ(params.lr, 0.001);
  EXPECT_EQ(params.strides, (std::vector<int>{1, 2}));
  EXPECT_EQ(params.encoder.width, 64);
  EXPECT_EQ(params.encoder.depth, 3);
  ASSERT_EQ(params.heads.size(), 2u);
  EXPECT_EQ(params.heads[0].depth, 2);
  EXPECT_EQ(params.heads[1].width, 8);
  EXPECT_FALSE(params.extra.has_value());
  const std::string resolved = root.to_yaml_string();
  EXPECT_NE(resolved.find("verbose: false"), std::string::npos) << resolved;
  EXPECT_NE(resolved.find("depth: 3"), std::string::npos) << resolved;
  EXPECT_NE(resolved.find("activation: relu"), std::string::npos) << resolved;
  EXPECT_EQ(resolved.find("extra"), std::string::npos) << resolved;

  // The resolved text reads back to the same values.
  const auto again = dir.write("again.yaml", resolved);
  const ModelParams reread = read_yaml(again);
  EXPECT_EQ(reread.encoder.depth, 3);
  EXPECT_DOUBLE_EQ(reread.lr, 0.001);
}

TEST(ConfigReader, UnknownKeyNamesLocationPathAndSuggestion) {
  TempDir dir;
  const auto path = dir.write("m.yaml", "name: a\nencoder:\n  widht: 3\n");
  const std::string error = config_error_of([&] { read_yaml(path); });
  EXPECT_EQ(error, path + ":3:3: encoder.widht: unknown key (did you mean 'width'?)");
}

TEST(ConfigReader, MissingRequiredKey) {
  TempDir dir;
  const auto path = dir.write("m.yaml", "lr: 0.1\n");
  const std::string error = config_error_of([&] { read_yaml(path); });
  EXPECT_EQ(error, path + ":1:1: name: missing required key");
}

TEST(ConfigReader, WrongTypes) {
  TempDir dir;
  EXPECT_EQ(
      config_error_of([&] { read_yaml(dir.write("a.yaml", "name: a\nencoder: {width: 3.5}\n")); }),
      dir.file("a.yaml") + ":2:18: encoder.width: expected an integer, got '3.5'");
  EXPECT_EQ(config_error_of([&] { read_yaml(dir.write("b.yaml", "name: a\nlr: fast\n")); }),
            dir.file("b.yaml") + ":2:5: lr: expected a number, got 'fast'");
  EXPECT_EQ(config_error_of([&] { read_yaml(dir.write("c.yaml", "name: a\nverbose: yes\n")); }),
            dir.file("c.yaml") + ":2:10: verbose: expected true or false, got 'yes'");
  EXPECT_EQ(config_error_of([&] { read_yaml(dir.write("d.yaml", "name: a\nstrides: 2\n")); }),
            dir.file("d.yaml") + ":2:10: strides: expected a list, got a scalar");
  EXPECT_EQ(config_error_of([&] { read_yaml(dir.write("e.yaml", "name: [a]\n")); }),
            dir.file("e.yaml") + ":1:7: name: expected a string, got a list");
  EXPECT_EQ(config_error_of([&] { read_yaml(dir.write("f.yaml", "name: a\nencoder: 3\n")); }),
            dir.file("f.yaml") + ":2:10: encoder: expected a map, got a scalar");
  EXPECT_EQ(config_error_of([&] { read_yaml(dir.write("g.yaml", "name: a\nlr: '0.1'\n")); }),
            dir.file("g.yaml") + ":2:5: lr: expected a number, got '0.1'");
}

TEST(ConfigReader, OutOfRangeValues) {
  TempDir dir;
  EXPECT_EQ(
      config_error_of([&] { read_yaml(dir.write("a.yaml", "name: a\nencoder: {depth: 17}\n")); }),
      dir.file("a.yaml") + ":2:18: encoder.depth: value 17 is out of range: must be in [1, 16]");
  EXPECT_EQ(config_error_of([&] { read_yaml(dir.write("b.yaml", "name: a\nlr: 0\n")); }),
            dir.file("b.yaml") + ":2:5: lr: value 0 is out of range: must be > 0");
  EXPECT_EQ(config_error_of([&] { read_yaml(dir.write("c.yaml", "name: a\nstrides: [1, 0]\n")); }),
            dir.file("c.yaml") + ":2:14: strides[1]: value 0 is out of range: must be >= 1");
  EXPECT_EQ(
      config_error_of([&] { read_yaml(dir.write("d.yaml", "name: a\nactivation: tanhh\n")); }),
      dir.file("d.yaml") +
          ":2:13: activation: 'tanhh' is not allowed: must be one of relu, tanh (did you mean "
          "'tanh'?)");
}

TEST(ConfigReader, ErrorsInsideListsOfMapsNameTheElement) {
  TempDir dir;
  const auto path = dir.write("m.yaml", "name: a\nheads:\n  - {width: 4}\n  - {wdth: 4}\n");
  EXPECT_EQ(config_error_of([&] { read_yaml(path); }),
            path + ":4:6: heads[1].wdth: unknown key (did you mean 'width'?)");
}

struct TableParams {
  std::map<std::string, double> rates;
  std::map<std::string, std::vector<int>> counts;
  template <class F>
  void describe(F& f) {
    f("rates", rates, "a rate per label", in_range(0, 1));
    f("counts", counts, "two counts per label", size_is(2));
  }
};

// A map field takes any keys; each value is read as the field's value type under the rule.
TEST(ConfigReader, MapFieldsReadEveryKeyAndCheckEachValue) {
  TempDir dir;
  auto read = [&](const std::string& text) {
    ConfigNode root = load_config(dir.write("t.yaml", text), {});
    TableParams params;
    ConfigReader::read(root, "", params);
    return params;
  };
  const TableParams params = read("rates: {push: 0.5, none: 1}\ncounts: {a: [1, 2]}\n");
  EXPECT_EQ(params.rates, (std::map<std::string, double>{{"none", 1.0}, {"push", 0.5}}));
  EXPECT_EQ(params.counts.at("a"), (std::vector<int>{1, 2}));
  EXPECT_TRUE(read("{}").rates.empty());
  EXPECT_EQ(config_error_of([&] { read("rates: {push: 2}\n"); }),
            dir.file("t.yaml") + ":1:15: rates.push: value 2 is out of range: must be in [0, 1]");
  EXPECT_EQ(config_error_of([&] { read("counts: {a: [1]}\n"); }),
            dir.file("t.yaml") + ":1:13: counts.a: expected a list of 2 items, got 1");
  EXPECT_EQ(config_error_of([&] { read("rates: [1]\n"); }),
            dir.file("t.yaml") + ":1:8: rates: expected a map, got a list");
}

TEST(ConfigReader, YamlSyntaxErrorNamesTheLocation) {
  TempDir dir;
  const auto path = dir.write("m.yaml", "name: a\nencoder: {width: 3\n");
  const std::string error = config_error_of([&] { read_yaml(path); });
  EXPECT_EQ(error.rfind(path + ":", 0), 0u) << error;
  EXPECT_NE(error.find("YAML syntax error"), std::string::npos) << error;
}

}  // namespace
}  // namespace corrmp
