// Tests of scripts/bench_ab (docs/performance.md, "Measuring"): its errors, and the table it
// prints, on stand-in benchmark executables whose numbers are fixed (no timing is asserted)
// and on the real ones' output format.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "script_run.hpp"

namespace {

namespace fs = std::filesystem;

using Result = corrmp::testing::ScriptResult;

Result bench_ab(const std::string& arguments) {
  return corrmp::testing::run_script("bench_ab", arguments);
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
  EXPECT_NE(nothing.err.find("matches 'NoSuchBenchmark'"), std::string::npos) << nothing.err;
  EXPECT_TRUE(nothing.out.empty()) << nothing.out;
}

// A stand-in for a Google Benchmark executable: prints `csv_rows` under the CSV header,
// whatever its arguments.
std::string fake_benchmark(const fs::path& dir, const std::string& name,
                           const std::string& csv_rows) {
  const fs::path path = dir / name;
  std::ofstream(path) << "#!/bin/sh\ncat <<'EOF'\nname,iterations,real_time,cpu_time,time_unit,"
                         "bytes_per_second,items_per_second,label,error_occurred,error_message\n"
                      << csv_rows << "EOF\n";
  fs::permissions(path, fs::perms::owner_all);
  return path.string();
}

TEST(BenchAb, TabulatesMediansAndPairedRatiosOfBothKindsOfRate) {
  const fs::path dir = fs::temp_directory_path() / ("bench_ab_fake_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  // BM_timed: 2 ms then 1 ms per iteration (500 and 1000 per second); BM_counted: 500 then 400
  // items per second whatever its time; BM_new only in NEW; BM_broken failed in both.
  const std::string old_binary = fake_benchmark(dir, "old",
                                                "\"BM_timed\",10,2,2,ms,,,,,\n"
                                                "\"BM_counted\",10,7,7,us,,500,,,\n"
                                                "\"BM_broken\",0,0,0,ns,,,,true,\"boom\"\n");
  const std::string new_binary = fake_benchmark(dir, "new",
                                                "\"BM_timed\",10,1,1,ms,,,,,\n"
                                                "\"BM_counted\",10,3,3,us,,400,,,\n"
                                                "\"BM_new\",10,1,1,ms,,,,,\n"
                                                "\"BM_broken\",0,0,0,ns,,,,true,\"boom\"\n");
  const Result r = bench_ab(old_binary + " " + new_binary + " BM 3");
  fs::remove_all(dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::smatch m;
  ASSERT_TRUE(find_row(r.out, "BM_timed", m)) << r.out;
  EXPECT_EQ(m[2], "500.0");
  EXPECT_EQ(m[3], "1000.0");
  EXPECT_EQ(m[4], "2.0000");
  EXPECT_EQ(m[5], "3");
  EXPECT_EQ(m[6], "3");
  ASSERT_TRUE(find_row(r.out, "BM_counted", m)) << r.out;
  EXPECT_EQ(m[2], "500.0");
  EXPECT_EQ(m[3], "400.0");
  EXPECT_EQ(m[4], "0.8000");
  EXPECT_EQ(m[5], "0");
  EXPECT_EQ(r.out.find("BM_new"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("BM_broken"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("in one build only, left out: BM_new"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("BM_broken reported an error or no time; left out"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("pair 3 of 3 done"), std::string::npos) << r.err;
}

// The real benchmark executables' CSV is what the script reads (no check of their speed).
TEST(BenchAb, ReadsTheBenchmarkExecutablesOutput) {
  const Result r = bench_ab(std::string(BENCH_CNMP_BIN) + " " + BENCH_CNMP_BIN +
                            " BM_predict_200_points 1 0.01");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::smatch m;
  ASSERT_TRUE(find_row(r.out, "BM_predict_200_points", m)) << r.out;
  EXPECT_GT(std::stod(m[2]), 0.0);
  EXPECT_EQ(m[6], "1");
  const Result counted = bench_ab(std::string(BENCH_AUTOENCODER_BIN) + " " + BENCH_AUTOENCODER_BIN +
                                  " 'BM_train_step/16/1/' 1 0.01");
  ASSERT_EQ(counted.exit_code, 0) << counted.err;
  EXPECT_TRUE(find_row(counted.out, "BM_train_step/16/1/real_time", m)) << counted.out;
}

}  // namespace
