// Tests of the JSON writer.
#include "core/json_writer.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace corrmp {

TEST(JsonObject, WritesEscapedCompactObjects) {
  JsonObject inner;
  inner.add("ok", true);
  JsonObject object;
  object.add("name", "a \"b\"\n").add("n", 3).add("x", 0.25).add("v", std::vector<double>{1, 2.5});
  object.add("inner", inner).add("bad", std::nan("")).add_null("none");
  EXPECT_EQ(
      object.str(),
      R"({"name":"a \"b\"\n","n":3,"x":0.25,"v":[1,2.5],"inner":{"ok":true},"bad":null,"none":null})");
}

TEST(JsonObject, IndentedFormPutsOneKeyPerLine) {
  JsonObject object;
  object.add("a", 1).add("b", "x");
  EXPECT_EQ(object.str(2), "{\n  \"a\": 1,\n  \"b\": \"x\"\n}");
  EXPECT_EQ(JsonObject().str(), "{}");
}

}  // namespace corrmp
