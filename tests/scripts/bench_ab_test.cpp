// Tests of scripts/bench_ab (docs/performance.md, "Measuring"): its errors, and the table it
// prints for benchmarks that count items and for ones that only time iterations.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

struct Result {
  int exit_code = -1;
  std::string out, err;
};

std::string read_file(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Runs scripts/bench_ab with `arguments` (already shell-quoted).
Result bench_ab(const std::string& arguments) {
  const fs::path dir = fs::temp_directory_path() / ("bench_ab_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string command = std::string("bash ") + PROJECT_DIR + "/scripts/bench_ab " +
                              arguments + " >" + (dir / "out").string() + " 2>" +
                              (dir / "err").string();
  const int status = std::system(command.c_str());
  Result result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = read_file(dir / "out");
  result.err = read_file(dir / "err");
  fs::remove_all(dir);
  return result;
}

// Finds the table's row for `name`: old and new medians (match 2 and 3), their ratio (4), the
// pairs new won (5) of all (6).
bool find_row(const std::string& out, const std::string& name, std::smatch& match) {
  const std::regex line("(^|\n)" + name + R"( +([0-9.]+) +([0-9.]+) +([0-9.]+) +(\d+)/(\d+)\n)");
  return std::regex_search(out, match, line);
}

TEST(BenchAb, WrongArgumentsExitWithTwoAndSayWhy) {
  const Result none = bench_ab("");
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_NE(none.err.find("usage: scripts/bench_ab"), std::string::npos) << none.err;

  const Result missing = bench_ab(std::string("/no/such/binary ") + BENCH_CNMP_BIN + " x");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("'/no/such/binary' is not an executable file"), std::string::npos)
      << missing.err;

  const Result pairs = bench_ab(std::string(BENCH_CNMP_BIN) + " " + BENCH_CNMP_BIN + " x 0");
  EXPECT_EQ(pairs.exit_code, 2);
  EXPECT_NE(pairs.err.find("PAIRS '0' is not a positive integer"), std::string::npos) << pairs.err;

  const Result nothing =
      bench_ab(std::string(BENCH_CNMP_BIN) + " " + BENCH_CNMP_BIN + " NoSuchBenchmark 1 0.01");
  EXPECT_EQ(nothing.exit_code, 2);
  EXPECT_NE(nothing.err.find("no benchmark matches 'NoSuchBenchmark'"), std::string::npos)
      << nothing.err;
  EXPECT_TRUE(nothing.out.empty()) << nothing.out;
}

TEST(BenchAb, TimedBenchmarksGiveRatesFromTheirRealTime) {
  const Result r = bench_ab(std::string(BENCH_CNMP_BIN) + " " + BENCH_CNMP_BIN +
                            " BM_predict_200_points 2 0.01");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("pair 2 of 2 done"), std::string::npos) << r.err;
  std::smatch m;
  ASSERT_TRUE(find_row(r.out, "BM_predict_200_points", m)) << r.out;
  // Predictions take tens to hundreds of microseconds: thousands per second.
  EXPECT_GT(std::stod(m[2]), 100.0);
  EXPECT_GT(std::stod(m[3]), 100.0);
  EXPECT_GT(std::stod(m[4]), 0.2);  // one binary against itself: a ratio near 1
  EXPECT_LT(std::stod(m[4]), 5.0);
  EXPECT_EQ(m[6], "2");
}

TEST(BenchAb, CountedBenchmarksGiveTheirItemsPerSecond) {
  const Result r = bench_ab(std::string(BENCH_AUTOENCODER_BIN) + " " + BENCH_AUTOENCODER_BIN +
                            " 'BM_train_step/16/1/' 1 0.01");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::smatch m;
  ASSERT_TRUE(find_row(r.out, "BM_train_step/16/1/real_time", m)) << r.out;
  // Images per second (hundreds on one core, 150 and more in every build measured), not steps
  // per second, 16 times fewer.
  EXPECT_GT(std::stod(m[2]), 50.0);
  EXPECT_LT(std::stod(m[2]), 1e5);
  EXPECT_EQ(m[6], "1");
}

}  // namespace
