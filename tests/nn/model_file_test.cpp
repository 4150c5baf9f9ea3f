// Tests of nn/model_file.hpp: exact round trips (hyperparameters, special float values, Mlp
// parameters) and one clear error naming the file for every kind of damaged input.
#include "nn/model_file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>

#include "nn/mlp.hpp"

namespace corrmp::nn {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::ThrowsMessage;

std::string temp_path(const std::string& name) {
  return ::testing::TempDir() + "corrmp_nn_" + name + ".cmpm";
}

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

ModelFile sample_model() {
  ModelFile m;
  m.hyper["type"] = "cnmp";
  m.set_hyper_int("width", 128);
  m.set_hyper_double("min_std", 0.01);
  m.tensors.push_back({"encoder.layers.0.weight",
                       {2, 3},
                       {1.5f, -2.0f, 0.0f, -0.0f, 3e-39f, std::numeric_limits<float>::infinity()}});
  m.tensors.push_back({"scalar", {}, {42.0f}});
  m.tensors.push_back({"empty", {0, 4}, {}});
  return m;
}

// Expects ModelFile::read(path) to throw a runtime_error whose message names the file and
// contains `fragment`.
void expect_read_error(const std::string& path, const std::string& fragment) {
  EXPECT_THAT([&] { ModelFile::read(path); },
              ThrowsMessage<std::runtime_error>(
                  AllOf(HasSubstr(path), HasSubstr(fragment), Not(HasSubstr("\n")))));
}

TEST(ModelFile, RoundTripPreservesHyperparametersAndTensorsBitExactly) {
  const std::string path = temp_path("round_trip");
  const ModelFile written = sample_model();
  written.write(path);
  const ModelFile read = ModelFile::read(path);
  EXPECT_EQ(read.hyper, written.hyper);
  ASSERT_EQ(read.tensors.size(), written.tensors.size());
  for (std::size_t k = 0; k < read.tensors.size(); ++k) {
    const NamedTensor& a = written.tensors[k];
    const NamedTensor& b = read.tensors[k];
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.shape, b.shape);
    ASSERT_EQ(a.data.size(), b.data.size());
    for (std::size_t i = 0; i < a.data.size(); ++i)
      EXPECT_EQ(std::memcmp(&a.data[i], &b.data[i], sizeof(float)), 0) << a.name << "[" << i << "]";
  }
  EXPECT_EQ(read.hyper_int("width"), 128);
  EXPECT_EQ(read.hyper_double("min_std"), 0.01);
  EXPECT_EQ(read.source, path);
  std::remove(path.c_str());
}

TEST(ModelFile, HeaderIsLittleEndianMagicAndVersion) {
  const std::string path = temp_path("header");
  sample_model().write(path);
  const std::string bytes = read_bytes(path);
  ASSERT_GE(bytes.size(), 16u);
  EXPECT_EQ(bytes.substr(0, 4), "CMPM");
  EXPECT_EQ(bytes.substr(4, 4), std::string("\x01\x00\x00\x00", 4));
  std::uint64_t body = 0;
  for (int i = 0; i < 8; ++i)
    body |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes[8 + i])) << (8 * i);
  EXPECT_EQ(body + 24, bytes.size());
  std::remove(path.c_str());
}

TEST(ModelFile, MlpParametersRoundTripIntoAFreshNetwork) {
  const std::string path = temp_path("mlp");
  Rng a(80), b(81);
  Mlp<float> trained({3, 16, 16, 2}, a), fresh({3, 16, 16, 2}, b);
  ModelFile out;
  out.set_hyper_int("input", 3);
  out.add_parameters(trained.parameters("decoder."));
  out.write(path);
  ModelFile::read(path).load_parameters(fresh.parameters("decoder."));
  for (Index i = 0; i < trained.num_layers(); ++i) {
    EXPECT_EQ(trained.layer(i).weight(), fresh.layer(i).weight());
    EXPECT_EQ(trained.layer(i).bias(), fresh.layer(i).bias());
  }
  const Mat<float> x = Mat<float>::Random(4, 3);
  EXPECT_EQ(Mat<float>(trained.forward(x)), Mat<float>(fresh.forward(x)));
  std::remove(path.c_str());
}

TEST(ModelFile, TruncatedFileThrowsNamingTheFile) {
  const std::string path = temp_path("truncated");
  sample_model().write(path);
  const std::string bytes = read_bytes(path);
  for (std::size_t keep : {std::size_t{0}, std::size_t{3}, std::size_t{10}, std::size_t{23},
                           bytes.size() / 2, bytes.size() - 1}) {
    write_bytes(path, bytes.substr(0, keep));
    expect_read_error(path, "truncated");
  }
  std::remove(path.c_str());
}

TEST(ModelFile, CorruptByteThrowsChecksumMismatch) {
  const std::string path = temp_path("corrupt");
  sample_model().write(path);
  std::string bytes = read_bytes(path);
  bytes[bytes.size() / 2] ^= 0x10;
  write_bytes(path, bytes);
  expect_read_error(path, "checksum mismatch");
  std::remove(path.c_str());
}

TEST(ModelFile, WrongMagicThrows) {
  const std::string path = temp_path("magic");
  sample_model().write(path);
  std::string bytes = read_bytes(path);
  bytes[0] = 'X';
  write_bytes(path, bytes);
  expect_read_error(path, "wrong magic");
  write_bytes(path, "PK\x03\x04 definitely a zip archive");
  expect_read_error(path, "wrong magic");
  std::remove(path.c_str());
}

TEST(ModelFile, NewerVersionThrows) {
  const std::string path = temp_path("version");
  sample_model().write(path);
  std::string bytes = read_bytes(path);
  bytes[4] = 2;
  write_bytes(path, bytes);
  expect_read_error(path, "format version 2 is not supported");
  std::remove(path.c_str());
}

TEST(ModelFile, TrailingBytesThrow) {
  const std::string path = temp_path("trailing");
  sample_model().write(path);
  write_bytes(path, read_bytes(path) + "extra");
  expect_read_error(path, "trailing bytes");
  std::remove(path.c_str());
}

TEST(ModelFile, MissingFileThrows) {
  expect_read_error(temp_path("does_not_exist"), "cannot open");
}

TEST(ModelFile, ShapeMismatchThrowsNamingFileTensorAndShapes) {
  const std::string path = temp_path("shape");
  Rng rng(82);
  Mlp<float> small({3, 8, 2}, rng), wide({3, 9, 2}, rng);
  ModelFile out;
  out.add_parameters(small.parameters());
  out.write(path);
  const ModelFile in = ModelFile::read(path);
  const Mat<float> before = wide.layer(0).weight();
  EXPECT_THAT(
      [&] { in.load_parameters(wide.parameters()); },
      ThrowsMessage<std::runtime_error>(AllOf(
          HasSubstr(path), HasSubstr("'layers.0.weight' has shape [8, 3], expected [9, 3]"))));
  EXPECT_EQ(wide.layer(0).weight(), before) << "a failed load must not modify parameters";
  EXPECT_THROW(in.tensor("no.such.tensor", {1}), std::runtime_error);
  std::remove(path.c_str());
}

TEST(ModelFile, HyperparameterAccessorsCheckTypes) {
  ModelFile m = sample_model();
  EXPECT_EQ(m.hyper_string("type"), "cnmp");
  EXPECT_THROW(m.hyper_int("type"), std::runtime_error);
  EXPECT_THROW(m.hyper_int("min_std"), std::runtime_error);
  EXPECT_THROW(m.hyper_string("missing"), std::runtime_error);
  m.set_hyper_double("lr", 1e-4);
  EXPECT_EQ(m.hyper_double("lr"), 1e-4);
}

TEST(ModelFile, WriteRejectsInconsistentTensors) {
  const std::string path = temp_path("invalid");
  ModelFile m;
  m.tensors.push_back({"w", {2, 2}, {1.0f, 2.0f, 3.0f}});
  EXPECT_THROW(m.write(path), std::runtime_error);
  m.tensors[0].data.push_back(4.0f);
  m.tensors.push_back(m.tensors[0]);
  EXPECT_THROW(m.write(path), std::runtime_error);
  std::remove(path.c_str());
}

}  // namespace
}  // namespace corrmp::nn
