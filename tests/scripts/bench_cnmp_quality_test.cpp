// Tests of scripts/bench_cnmp_quality (docs/performance.md, "Quality"): its errors, and the
// per-seed table and t-interval it prints, on short trainings of the real train_cnmp (no
// validation error is asserted beyond being a number the summary agrees with).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "script_run.hpp"

namespace {

namespace fs = std::filesystem;

using Result = corrmp::testing::ScriptResult;

Result bench_quality(const std::string& arguments) {
  return corrmp::testing::run_script("bench_cnmp_quality", arguments);
}

// A short run: few updates on a small family.
const std::string kQuick =
    std::string("--train-cnmp ") + TRAIN_CNMP_BIN + " --updates 300 --demos 10 --steps 20 ";

TEST(BenchCnmpQuality, WrongArgumentsExitWithTwoAndSayWhy) {
  const Result seeds = bench_quality("--seeds 0");
  EXPECT_EQ(seeds.exit_code, 2);
  EXPECT_NE(seeds.err.find("--seeds '0' is not a positive integer"), std::string::npos)
      << seeds.err;

  const Result missing = bench_quality("--train-cnmp /no/such/train_cnmp");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("'/no/such/train_cnmp' is not an executable file"), std::string::npos)
      << missing.err;

  const Result unknown = bench_quality("--nonsense 3");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("usage: scripts/bench_cnmp_quality"), std::string::npos)
      << unknown.err;

  const Result existing = bench_quality("--write-family " + std::string(PROJECT_DIR) + "/scripts");
  EXPECT_EQ(existing.exit_code, 2);
  EXPECT_NE(existing.err.find("already exists"), std::string::npos) << existing.err;

  const Result few = bench_quality(kQuick + "--demos 4");
  EXPECT_EQ(few.exit_code, 2);
  EXPECT_NE(few.err.find("--demos 4 is too few"), std::string::npos) << few.err;
  EXPECT_TRUE(few.out.empty()) << few.out;
}

// The rows "seed error seconds" of seeds 2, 3, 4, and the summary line: its mean and half-width
// are those of the printed errors (Student t with 2 degrees of freedom: 4.303).
TEST(BenchCnmpQuality, PrintsEachSeedAndTheMeanWithItsTInterval) {
  const Result r = bench_quality(kQuick + "--seeds 3 --first-seed 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::vector<double> errors;
  const std::regex row(R"((^|\n)(\d+) +([0-9.eE+-]+) +[0-9.]+(?=\n))");
  for (std::sregex_iterator it(r.out.begin(), r.out.end(), row), end; it != end; ++it) {
    EXPECT_EQ(std::stoi((*it)[2]), 2 + static_cast<int>(errors.size())) << r.out;
    errors.push_back(std::stod((*it)[3]));
  }
  ASSERT_EQ(errors.size(), 3u) << r.out;
  double mean = 0.0, squares = 0.0;
  for (double e : errors) mean += e / 3.0;
  for (double e : errors) squares += (e - mean) * (e - mean);
  const double half = 4.303 * std::sqrt(squares / 2.0) / std::sqrt(3.0);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(
      r.out, m, std::regex(R"(mean error: +([0-9.]+) \+- ([0-9.]+) \(95% interval .* n 3\))")))
      << r.out;
  EXPECT_NEAR(std::stod(m[1]), mean, 1e-5);
  EXPECT_NEAR(std::stod(m[2]), half, 1e-5);
  EXPECT_GT(mean, 0.0);
}

// Against itself as the baseline, every seed's difference is 0: the same seed gives the same
// split, weights and draws.
TEST(BenchCnmpQuality, ABaselineBuildPairsBySeed) {
  const Result r = bench_quality(kQuick + "--seeds 2 --baseline " + TRAIN_CNMP_BIN);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("difference:      0.00000 +- 0.00000"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("baseline:"), std::string::npos) << r.out;
}

}  // namespace
