// Tests of nn/buffer.hpp: storage grows only for larger shapes and is reused otherwise.
#include "nn/buffer.hpp"

#include <gtest/gtest.h>

namespace corrmp::nn {
namespace {

TEST(Buffer, GrowsOnlyWhenAShapeNeedsMoreElements) {
  Buffer<float> buffer;
  EXPECT_EQ(buffer.capacity(), 0);
  MatMap<float> first = buffer.resize(4, 5);
  EXPECT_EQ(buffer.capacity(), 20);
  const float* data = first.data();
  MatMap<float> smaller = buffer.resize(2, 3);
  EXPECT_EQ(smaller.rows(), 2);
  EXPECT_EQ(smaller.cols(), 3);
  EXPECT_EQ(smaller.data(), data);
  EXPECT_EQ(buffer.capacity(), 20);
  buffer.resize(5, 5);
  EXPECT_EQ(buffer.capacity(), 25);
  EXPECT_EQ(buffer.view().rows(), 5);
}

TEST(Buffer, ViewWritesThroughToStorage) {
  Buffer<double> buffer;
  buffer.resize(2, 2).setConstant(3.0);
  EXPECT_EQ(buffer.view()(1, 1), 3.0);
  buffer.view()(0, 1) = 7.0;
  const Buffer<double>& read_only = buffer;
  EXPECT_EQ(read_only.view()(0, 1), 7.0);
}

}  // namespace
}  // namespace corrmp::nn
