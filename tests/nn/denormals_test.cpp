// Tests of nn/denormals.hpp: subnormal results are flushed inside the scope only.
#include "nn/denormals.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace corrmp::nn {
namespace {

float halve(volatile float x) { return x * 0.5f; }

TEST(ScopedFlushDenormals, FlushesSubnormalResultsOnlyInsideTheScope) {
  const float smallest_normal = std::numeric_limits<float>::min();
  EXPECT_GT(halve(smallest_normal), 0.0f);  // a subnormal result by default
#if defined(__SSE__) || defined(__x86_64__)
  {
    const ScopedFlushDenormals scope;
    EXPECT_EQ(halve(smallest_normal), 0.0f);
  }
#endif
  EXPECT_GT(halve(smallest_normal), 0.0f);
}

}  // namespace
}  // namespace corrmp::nn
