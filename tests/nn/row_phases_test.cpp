// Tests of nn/row_phases.hpp against the definitions written out: rows whose float width is a
// multiple of 16 (the SSE path where the build has it) and other widths and double (the scalar
// loops), phases and columns further apart than a row's tiles, and the entries between them left
// alone.
#include "nn/row_phases.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

namespace corrmp::nn {
namespace {

template <class S>
std::vector<S> random_row(Index width, unsigned seed) {
  std::vector<S> row(static_cast<size_t>(width));
  unsigned state = seed * 2654435761u + 7u;
  for (S& value : row) {
    state = state * 1664525u + 1013904223u;
    value = static_cast<S>((state >> 8) % 1999u + 1u) / S(1000) - S(1);  // nonzero, in (-1, 1)
  }
  return row;
}

template <class S>
class RowPhases : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(RowPhases, Scalars);

const Index kWidths[] = {1, 3, 5, 12, 13, 16, 32, 48, 64};
constexpr Index kGap = 3;  // extra entries between phases or columns

TYPED_TEST(RowPhases, SplitRowAndMergeRowFollowTheirDefinitions) {
  using S = TypeParam;
  const S sentinel = std::numeric_limits<S>::quiet_NaN();
  for (const Index width : kWidths) {
    const Index count = (width + 3) / 4, stride = count + kGap;
    const std::vector<S> row = random_row<S>(width, static_cast<unsigned>(width));
    std::vector<S> phases(static_cast<size_t>(4 * stride), sentinel);
    split_row(row.data(), width, count, phases.data(), stride);
    for (int p = 0; p < 4; ++p)
      for (Index m = 0; m < stride; ++m) {
        const S value = phases[static_cast<size_t>(p * stride + m)];
        if (m >= count) {
          EXPECT_TRUE(value != value) << "gap written, width " << width;
        } else {
          const Index w = 4 * m + p;
          EXPECT_EQ(value, w < width ? row[static_cast<size_t>(w)] : S(0)) << width << " " << w;
        }
      }
    std::vector<S> merged(static_cast<size_t>(width), sentinel);
    merge_row(phases.data(), stride, width, count, merged.data());
    EXPECT_EQ(merged, row) << "width " << width;

    split_row<S>(nullptr, width, count, phases.data(), stride);
    for (int p = 0; p < 4; ++p)
      for (Index m = 0; m < count; ++m) EXPECT_EQ(phases[static_cast<size_t>(p * stride + m)], 0);
  }
}

TYPED_TEST(RowPhases, PatchColumnsOverlapByTwoPixels) {
  using S = TypeParam;
  const S sentinel = std::numeric_limits<S>::quiet_NaN();
  for (const Index width : kWidths) {
    const Index count = (width + 3) / 4, stride = count + kGap;
    const std::vector<S> row = random_row<S>(width, static_cast<unsigned>(width) + 100u);
    std::vector<S> columns(static_cast<size_t>(6 * stride), sentinel);
    split_patch_columns(row.data(), width, count, columns.data(), stride);
    const auto column = [&](int q, Index m) {
      return columns[static_cast<size_t>(q * stride + m)];
    };
    for (int q = 0; q < 6; ++q)
      for (Index m = 0; m < stride; ++m) {
        if (m >= count) {
          EXPECT_TRUE(column(q, m) != column(q, m)) << "gap written, width " << width;
        } else {
          const Index w = 4 * m + q - 1;  // the row padded by one zero on the left
          EXPECT_EQ(column(q, m), w >= 0 && w < width ? row[static_cast<size_t>(w)] : S(0))
              << width << " q " << q << " m " << m;
        }
      }

    // Merging adds, for each pixel, the (one or two) column entries that hold it.
    const std::vector<S> gradients = random_row<S>(6 * stride, static_cast<unsigned>(width) + 200u);
    std::vector<S> merged(static_cast<size_t>(width), sentinel);
    merge_patch_columns(gradients.data(), stride, width, count, merged.data());
    for (Index w = 0; w < width; ++w) {
      S expected(0);
      int terms = 0;
      for (int q = 0; q < 6; ++q)
        for (Index m = 0; m < count; ++m)
          if (4 * m + q - 1 == w) {
            expected += gradients[static_cast<size_t>(q * stride + m)];
            ++terms;
          }
      EXPECT_EQ(merged[static_cast<size_t>(w)], expected) << "width " << width << " pixel " << w;
      EXPECT_EQ(terms, (w + 1) % 4 < 2 && w >= 3 && (w + 1) / 4 < count ? 2 : 1)
          << "width " << width << " pixel " << w;
    }
  }
}

}  // namespace
}  // namespace corrmp::nn
