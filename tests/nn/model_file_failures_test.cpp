// Tests of nn/model_file.hpp against a hostile file system: a write that fails
// part way leaves the previous model intact and no temporary file, stale
// temporary names do not get in the way, and reading a directory, a device or
// a missing folder gives one line naming the path and what is wrong.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

#include "core/file_size_limit.hpp"
#include "nn/model_file.hpp"

namespace corrmp::nn {
namespace {

namespace fs = std::filesystem;

// A fresh folder of its own for each test, removed afterwards.
class ModelFileFailures : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(::testing::TempDir()) /
           ("corrmp_model_file_failures_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string file(const std::string& name) const { return (dir_ / name).string(); }
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& entry : fs::directory_iterator(dir_)) {
      out.push_back(entry.path().filename().string());
    }
    std::sort(out.begin(), out.end());
    return out;
  }

  fs::path dir_;
};

ModelFile model_of_size(std::size_t values) {
  ModelFile m;
  m.hyper["type"] = "test";
  m.tensors.push_back({"w", {static_cast<std::int64_t>(values)}, std::vector<float>(values, 0.5f)});
  return m;
}

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// The message of the runtime_error `body` throws.
template <class Body>
std::string error_of(Body body) {
  try {
    body();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST_F(ModelFileFailures, AFailedWriteKeepsThePreviousModelAndLeavesNoTemporaryFile) {
  const std::string path = file("model.cmpm");
  model_of_size(4).write(path);
  const std::string good = bytes_of(path);
  std::string message;
  {
    corrmp::testing::FileSizeLimit limit(4096);  // a disk that fills up mid-write
    message = error_of([&] { model_of_size(100000).write(path); });
  }
  EXPECT_EQ(message, "model file '" + path + "': cannot write: File too large");
  EXPECT_EQ(bytes_of(path), good);
  EXPECT_EQ(ModelFile::read(path).tensors[0].data.size(), 4u);
  EXPECT_EQ(names(), std::vector<std::string>{"model.cmpm"});
}

TEST_F(ModelFileFailures, AFailedWriteOfANewModelLeavesNoFileAtAll) {
  const std::string path = file("new.cmpm");
  {
    corrmp::testing::FileSizeLimit limit(4096);
    EXPECT_NE(error_of([&] { model_of_size(100000).write(path); }).find(path), std::string::npos);
  }
  EXPECT_TRUE(names().empty());
}

// The old writer used "<path>.tmp" for every process: a leftover there (here
// even a directory) made every later write fail.
TEST_F(ModelFileFailures, ALeftoverTemporaryNameDoesNotBlockWriting) {
  const std::string path = file("model.cmpm");
  fs::create_directories(path + ".tmp");
  model_of_size(3).write(path);
  EXPECT_EQ(ModelFile::read(path).tensors[0].data.size(), 3u);
}

TEST_F(ModelFileFailures, WritingIntoAMissingFolderOrOntoADirectoryNamesThePath) {
  const std::string missing = file("no/such/folder/m.cmpm");
  EXPECT_EQ(error_of([&] { model_of_size(2).write(missing); }),
            "model file '" + missing + "': cannot write: its folder does not exist");
  const std::string folder = file("m.cmpm");
  fs::create_directories(folder);
  EXPECT_EQ(error_of([&] { model_of_size(2).write(folder); }),
            "model file '" + folder + "': is a directory");
  EXPECT_EQ(names(), std::vector<std::string>{"m.cmpm"});
}

TEST_F(ModelFileFailures, ReadingADirectoryOrADeviceNamesThePathAndWhatItIs) {
  const std::string folder = file("autoencoder.cmpm");
  fs::create_directories(folder);
  EXPECT_EQ(error_of([&] { ModelFile::read(folder); }),
            "model file '" + folder + "': is a directory");
  EXPECT_EQ(error_of([&] { ModelFile::read("/dev/null"); }),
            "model file '/dev/null': is not a regular file (a character device)");
}

}  // namespace
}  // namespace corrmp::nn
