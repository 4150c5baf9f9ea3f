// Tests that a damaged cache is never fatal: the demonstration cache and the
// autoencoder model cache, truncated, with a flipped byte or replaced by a
// directory, are reported once (a warning naming the file) and recomputed,
// giving the same result as before; a cache that cannot be written is a
// warning too; a run told not to reuse the cache (--no-cache) trains again and
// replaces the cached model.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "config/test_files.hpp"
#include "context/autoencoder_context.hpp"
#include "core/seeds.hpp"
#include "experiment/demonstration_cache.hpp"
#include "log_capture.hpp"
#include "nn/model_file.hpp"

namespace corrmp {
namespace {

namespace fs = std::filesystem;
using testing::LogCapture;
using testing::TempDir;

enum class Damage { kTruncate, kFlipByte, kDirectory, kEmpty };

const char* name_of(Damage damage) {
  switch (damage) {
    case Damage::kTruncate:
      return "truncated";
    case Damage::kFlipByte:
      return "flipped byte";
    case Damage::kDirectory:
      return "directory";
    case Damage::kEmpty:
      return "empty";
  }
  return "";
}

void damage(const std::string& path, Damage kind) {
  const auto size = fs::file_size(path);
  switch (kind) {
    case Damage::kTruncate:
      fs::resize_file(path, size / 2);
      break;
    case Damage::kFlipByte: {
      std::fstream file(path, std::ios::in | std::ios::out | std::ios::binary);
      file.seekg(static_cast<std::streamoff>(size / 2));
      const char byte = static_cast<char>(file.get());
      file.seekp(static_cast<std::streamoff>(size / 2));
      file.put(static_cast<char>(byte ^ 0x10));
      break;
    }
    case Damage::kDirectory:
      fs::remove(path);
      fs::create_directories(path + "/inside");
      break;
    case Damage::kEmpty:
      fs::resize_file(path, 0);
      break;
  }
}

// ---- the demonstration cache -------------------------------------------------------------

Demonstration a_demonstration(double value) {
  SegmentTrajectory s;
  s.segment = "cor";
  s.x = Eigen::MatrixXd::Constant(5, 1, value);
  s.y = Eigen::MatrixXd::Constant(5, 2, 2 * value);
  s.start.rgb = cv::Mat(4, 6, CV_8UC3, cv::Scalar(10, 200, 30));
  return Demonstration{"{}", {s}, "push"};
}

std::string load_error_of(const std::string& path) {
  try {
    load_demonstrations(path);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(DamagedCaches, EachDamagedDemonstrationCacheIsOneLineNamingTheFileAndWhatIsWrong) {
  TempDir dir;
  DemonstrationSplit demos;
  demos.train = {a_demonstration(1.0), a_demonstration(2.0)};
  const std::string path = dir.file("cache/demonstrations-0.bin");
  const std::vector<std::pair<Damage, std::string>> cases = {
      {Damage::kTruncate, "checksum mismatch (truncated or damaged)"},
      {Damage::kFlipByte, "checksum mismatch (truncated or damaged)"},
      {Damage::kDirectory, "is a directory"},
      {Damage::kEmpty, "empty file"},
  };
  for (const auto& [kind, problem] : cases) {
    fs::remove_all(path);
    ASSERT_TRUE(save_demonstrations(path, demos));
    damage(path, kind);
    EXPECT_EQ(load_error_of(path), "demonstration cache '" + path + "': " + problem)
        << name_of(kind);
  }
  fs::remove_all(path);
  fs::create_symlink("/dev/null", path);
  EXPECT_EQ(load_error_of(path),
            "demonstration cache '" + path + "': is not a regular file (a character device)");
}

TEST(DamagedCaches, ADemonstrationCacheThatCannotBeWrittenIsAWarningNotAFailure) {
  TempDir dir;
  DemonstrationSplit demos;
  demos.train = {a_demonstration(1.0)};
  const std::string path = dir.file("demonstrations-0.bin");
  fs::create_directories(path);
  LogCapture log;
  EXPECT_FALSE(save_demonstrations(path, demos));
  EXPECT_EQ(log.warnings(),
            "[warning] demonstration cache '" + path + "' not written: is a directory\n");
  EXPECT_TRUE(fs::is_directory(path));  // a folder of the researcher's is not removed
  EXPECT_EQ(fs::directory_iterator(dir.path())->path().filename(), "demonstrations-0.bin");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()), 1);
  fs::remove(path);
  EXPECT_TRUE(save_demonstrations(path, demos));
  EXPECT_EQ(load_demonstrations(path)->train.size(), 1u);
}

// ---- the autoencoder model cache ---------------------------------------------------------

AutoencoderContextParams tiny_autoencoder() {
  AutoencoderContextParams params;
  params.segments = {"cor"};
  params.network.image_size = 8;
  params.network.filters = {2, 2, 2, 2, 2};
  params.network.latent_size = 2;
  params.network.epochs = 1;
  params.network.batch_size = 4;
  params.network.threads = 1;
  params.network.test_fraction = 0.25;
  return params;
}

std::vector<Demonstration> demonstrations_with_images() {
  std::vector<Demonstration> demos;
  for (int i = 0; i < 8; ++i) {
    Demonstration demo = a_demonstration(i);
    demo.segments[0].start.rgb = cv::Mat(8, 8, CV_8UC3, cv::Scalar(30 * i, 200 - 20 * i, 90));
    demos.push_back(demo);
  }
  return demos;
}

// The one autoencoder-*.cmpm file (or directory) in `folder`.
std::string cached_model(const std::string& folder) {
  std::vector<std::string> found;
  for (const auto& entry : fs::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("autoencoder-", 0) == 0 && entry.path().extension() == ".cmpm") {
      found.push_back(entry.path().string());
    }
  }
  EXPECT_EQ(found.size(), 1u);
  return found.empty() ? "" : found[0];
}

// Fits a fresh extractor (same seed, same random stream) and returns its metrics.
std::vector<Metric> fit(const std::string& cache_folder, bool reuse = true) {
  AutoencoderContext context(tiny_autoencoder(), 7);
  Rng rng(11);
  context.fit(demonstrations_with_images(), {cache_folder, "key", reuse}, rng);
  return context.metrics();
}

TEST(DamagedCaches, ADamagedAutoencoderCacheIsReportedOnceAndTrainedAgain) {
  TempDir dir;
  const std::string folder = dir.file("cache");
  const auto first = fit(folder);
  ASSERT_FALSE(first.empty());
  const std::string path = cached_model(folder);
  const std::vector<std::pair<Damage, std::string>> cases = {
      {Damage::kTruncate, "truncated"},
      {Damage::kFlipByte, "checksum mismatch"},
      {Damage::kEmpty, "truncated: 0 bytes"},
  };
  for (const auto& [kind, problem] : cases) {
    damage(path, kind);
    LogCapture log;
    EXPECT_EQ(fit(folder), first) << name_of(kind);
    const std::string warnings = log.warnings();
    EXPECT_EQ(std::count(warnings.begin(), warnings.end(), '\n'), 1) << warnings;
    EXPECT_EQ(warnings.rfind("[warning] model file '" + path + "': " + problem, 0), 0u) << warnings;
    EXPECT_NE(warnings.find("; training the autoencoder again"), std::string::npos) << warnings;
    EXPECT_NO_THROW(nn::ModelFile::read(path)) << "the cache is written again";
  }
  {
    LogCapture log;
    EXPECT_EQ(fit(folder), first) << "an intact cache is reused";
    EXPECT_NE(log.text().find("reusing the trained autoencoder " + path), std::string::npos);
  }
}

// --no-cache: the cached model is not read (a damaged one draws no warning), the autoencoder
// is trained again and replaces it, so the next run reuses the fresh model.
TEST(DamagedCaches, WithoutReuseTheAutoencoderIsTrainedAgainAndReplacesTheCache) {
  TempDir dir;
  const std::string folder = dir.file("cache");
  const auto first = fit(folder);
  const std::string path = cached_model(folder);
  damage(path, Damage::kFlipByte);
  {
    LogCapture log;
    EXPECT_EQ(fit(folder, /*reuse=*/false), first);
    EXPECT_EQ(log.warnings(), "");
    EXPECT_EQ(log.text().find("reusing"), std::string::npos) << log.text();
    EXPECT_NE(log.text().find("training the autoencoder"), std::string::npos) << log.text();
  }
  EXPECT_NO_THROW(nn::ModelFile::read(path)) << "the fresh model replaced the damaged one";
  LogCapture log;
  EXPECT_EQ(fit(folder), first);
  EXPECT_NE(log.text().find("reusing the trained autoencoder " + path), std::string::npos);
}

TEST(DamagedCaches, ADirectoryInPlaceOfTheAutoencoderCacheIsNeverFatal) {
  TempDir dir;
  const std::string folder = dir.file("cache");
  const auto first = fit(folder);
  const std::string path = cached_model(folder);
  damage(path, Damage::kDirectory);
  for (int run = 0; run < 2; ++run) {  // not once, not ever: every run goes through
    LogCapture log;
    EXPECT_EQ(fit(folder), first);
    EXPECT_EQ(log.warnings(), "[warning] model file '" + path +
                                  "': is a directory; training the autoencoder again\n"
                                  "[warning] model file '" +
                                  path +
                                  "': is a directory; the trained autoencoder is not cached\n");
  }
  EXPECT_TRUE(fs::is_directory(path + "/inside"));
}

}  // namespace
}  // namespace corrmp
