// Tests of the component registry: strict parameters, unknown and duplicate names.
#include "core/registry.hpp"

#include <gtest/gtest.h>

#include "config/test_files.hpp"
#include "core/config/config_loader.hpp"

namespace corrmp {
namespace {

using testing::config_error_of;
using testing::TempDir;

struct Shape {
  virtual ~Shape() = default;
  virtual double size() const = 0;
};

struct SquareParams {
  double side = 1.0;
  template <class F>
  void describe(F& f) {
    f("side", side, "side length (m)", positive());
  }
};

struct Square : Shape {
  explicit Square(double side) : side_(side) {}
  double size() const override { return side_ * side_; }
  double side_;
};

Registry<Shape> shapes() {
  Registry<Shape> registry("shape");
  registry.add<SquareParams>("square", "a square", [](const SquareParams& p, const SeedTree&) {
    return new Square(p.side);
  });
  registry.add<SquareParams>(
      "big_square", "a square twice as wide",
      [](const SquareParams& p, const SeedTree&) { return std::make_unique<Square>(2 * p.side); });
  return registry;
}

struct Top {
  ComponentSpec shape;
  template <class F>
  void describe(F& f) {
    f("shape", shape, "the shape", required());
  }
};

std::unique_ptr<Shape> build(ConfigNode& root) {
  Top top;
  ConfigReader::read(root, "", top);
  return shapes().create(top.shape, SeedTree{0});
}

TEST(Registry, BuildsTheNamedComponentFromItsParameters) {
  TempDir dir;
  ConfigNode root = load_config(dir.write("c.yaml", "shape: {type: big_square, side: 3}\n"), {});
  EXPECT_DOUBLE_EQ(build(root)->size(), 36.0);
  ConfigNode defaults = load_config(dir.write("d.yaml", "shape: {type: square}\n"), {});
  EXPECT_DOUBLE_EQ(build(defaults)->size(), 1.0);
  EXPECT_EQ(defaults.find("shape")->find("side")->text(), "1.0");
}

TEST(Registry, UnknownNameListsTheValidNames) {
  TempDir dir;
  const auto path = dir.write("c.yaml", "shape:\n  type: sqare\n");
  ConfigNode root = load_config(path, {});
  EXPECT_EQ(config_error_of([&] { build(root); }),
            path +
                ":2:9: shape.type: unknown shape 'sqare' (did you mean 'square'?); valid: "
                "square, big_square");
}

TEST(Registry, ComponentParametersAreStrict) {
  TempDir dir;
  const auto path = dir.write("c.yaml", "shape:\n  type: square\n  sid: 2\n");
  ConfigNode root = load_config(path, {});
  EXPECT_EQ(config_error_of([&] { build(root); }),
            path + ":3:3: shape.sid: unknown key (did you mean 'side'?)");
  const auto negative = dir.write("n.yaml", "shape: {type: square, side: -1}\n");
  ConfigNode root2 = load_config(negative, {});
  EXPECT_EQ(config_error_of([&] { build(root2); }),
            negative + ":1:29: shape.side: value -1 is out of range: must be > 0");
  const auto no_type = dir.write("t.yaml", "shape: {side: 1}\n");
  ConfigNode root3 = load_config(no_type, {});
  EXPECT_EQ(config_error_of([&] { build(root3); }),
            no_type + ":1:8: shape.type: missing required key");
}

TEST(Registry, DuplicateNamesAreRejectedAtRegistration) {
  Registry<Shape> registry = shapes();
  EXPECT_THROW(registry.add<SquareParams>(
                   "square", "again",
                   [](const SquareParams& p, const SeedTree&) { return new Square(p.side); }),
               std::logic_error);
}

TEST(Registry, EntriesDocumentTheirParameters) {
  const Registry<Shape> registry = shapes();
  ASSERT_EQ(registry.names(), (std::vector<std::string>{"square", "big_square"}));
  const auto& params = registry.find("square")->parameters;
  ASSERT_EQ(params.size(), 1u);
  EXPECT_EQ(params[0].key, "side");
  EXPECT_EQ(params[0].type, "float");
  EXPECT_EQ(params[0].default_value, "1.0");
  EXPECT_EQ(params[0].rule, "must be > 0");
}

}  // namespace
}  // namespace corrmp
