// End-to-end tests of train_cnmp and predict_cnmp on CSV demonstrations.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cnmp/csv_reader.hpp"
#include "config/test_files.hpp"
#include "support/sanitized_build.hpp"

namespace corrmp {
namespace {

using testing::TempDir;

int run(const std::string& command, std::string* err = nullptr, const TempDir* dir = nullptr) {
  std::string full = command;
  if (dir != nullptr) full += " 2>" + dir->file("err.txt");
  const int status = std::system(full.c_str());
  if (err != nullptr && dir != nullptr) {
    std::ifstream in(dir->file("err.txt"));
    std::stringstream buffer;
    buffer << in.rdbuf();
    *err = buffer.str();
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Straight lines from (0, 0) to (c, 2c) over time, with context c.
void write_demos(const TempDir& dir) {
  for (int d = 0; d < 12; ++d) {
    const double c = 0.1 + 0.08 * d;
    std::string csv = "time,px,py,goal\n";
    for (int t = 0; t < 20; ++t) {
      const double s = t / 19.0;
      csv += fmt::format("{},{},{},{}\n", 0.5 * t, c * s, 2 * c * s, c);
    }
    dir.write(fmt::format("demos/{:02}.csv", d), csv);
  }
}

TEST(CnmpTools, TrainOnCsvFilesThenPredictFromAStartPointAndContext) {
  TempDir dir;
  write_demos(dir);
  const std::string model = dir.file("line.cnmp");
  ASSERT_EQ(run(fmt::format("{} --data {} --time time --y px,py --context goal --updates 4000 "
                            "--batch 8 --max-targets 5 --lr 1e-3 --width 32 --out {} --quiet",
                            TRAIN_CNMP_BIN, dir.file("demos"), model)),
            0);
  const std::string csv = dir.file("p.csv");
  ASSERT_EQ(run(fmt::format("{} --model {} --obs 0,0,0 --context 0.5 --steps 11 --out {}",
                            PREDICT_CNMP_BIN, model, csv)),
            0);
  const RawTrajectory p = read_csv_trajectory(csv);
  ASSERT_EQ(p.columns, (std::vector<std::string>{"x0", "mean0", "mean1", "std0", "std1"}));
  ASSERT_EQ(p.values.rows(), 11);
  // An unseen context (0.5): the line ends near (0.5, 1.0).
  EXPECT_NEAR(p.values(10, 1), 0.5, 0.05);
  EXPECT_NEAR(p.values(10, 2), 1.0, 0.1);
  EXPECT_NEAR(p.values(5, 1), 0.25, 0.05);
  EXPECT_TRUE((p.values.rightCols(2).array() > 0).all());
}

// A model trained with a task parameter (train_cnmp --x goal) is queried with its value
// (--x-values), the same at every query time; the CSV has a column for it after time.
TEST(CnmpTools, AModelWithTaskParametersIsQueriedWithTheirValues) {
  TempDir dir;
  write_demos(dir);
  const std::string model = dir.file("task.cnmp");
  ASSERT_EQ(run(fmt::format("{} --data {} --time time --x goal --y px,py --updates 50 --width 8 "
                            "--out {} --quiet",
                            TRAIN_CNMP_BIN, dir.file("demos"), model)),
            0);
  const std::string csv = dir.file("p.csv");
  ASSERT_EQ(run(fmt::format("{} --model {} --obs 0,0.5,0,0 --x-values 0.5 --steps 6 --out {}",
                            PREDICT_CNMP_BIN, model, csv)),
            0);
  const RawTrajectory p = read_csv_trajectory(csv);
  ASSERT_EQ(p.columns, (std::vector<std::string>{"x0", "x1", "mean0", "mean1", "std0", "std1"}));
  ASSERT_EQ(p.values.rows(), 6);
  for (int t = 0; t < 6; ++t) {
    EXPECT_DOUBLE_EQ(p.values(t, 0), t / 5.0);
    EXPECT_EQ(p.values(t, 1), 0.5);
  }
  EXPECT_TRUE(p.values.allFinite());
  EXPECT_TRUE((p.values.rightCols(2).array() > 0).all());

  // Missing or too many values, or values for a model without task parameters: one line, exit 2.
  std::string err;
  for (const char* args : {"", "--x-values 0.5,1"}) {
    EXPECT_EQ(run(fmt::format("{} --model {} --obs 0,0.5,0,0 {}", PREDICT_CNMP_BIN, model, args),
                  &err, &dir),
              2)
        << args;
    EXPECT_NE(err.find("--x-values: this model needs 1 values, one per task parameter"),
              std::string::npos)
        << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  }
  ASSERT_EQ(run(fmt::format("{} --data {} --time time --y px,py --updates 10 --width 4 --out {} "
                            "--quiet",
                            TRAIN_CNMP_BIN, dir.file("demos"), dir.file("time_only.cnmp"))),
            0);
  EXPECT_EQ(run(fmt::format("{} --model {} --obs 0,0,0 --x-values 0.5", PREDICT_CNMP_BIN,
                            dir.file("time_only.cnmp")),
                &err, &dir),
            2);
  EXPECT_NE(err.find("--x-values: this model has no task parameters"), std::string::npos) << err;
}

// Training sees time in [0, 1] only: query times beyond it are predicted, with one warning line
// naming the range queried; queries inside it warn of nothing.
TEST(CnmpTools, QueryTimesOutsideZeroToOneGiveOneWarningLine) {
  TempDir dir;
  write_demos(dir);
  const std::string model = dir.file("m.cnmp");
  ASSERT_EQ(run(fmt::format("{} --data {} --time time --y px,py --context goal --updates 10 "
                            "--width 4 --out {} --quiet",
                            TRAIN_CNMP_BIN, dir.file("demos"), model)),
            0);
  const std::string csv = dir.file("p.csv");
  std::string err;
  EXPECT_EQ(run(fmt::format("{} --model {} --obs 0,0,0 --context 0.5 --query -0.5,0,1.5 --out {}",
                            PREDICT_CNMP_BIN, model, csv),
                &err, &dir),
            0);
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  EXPECT_NE(err.find("warning: query times span [-0.5, 1.5], beyond the normalised time range "
                     "[0, 1]"),
            std::string::npos)
      << err;
  EXPECT_EQ(read_csv_trajectory(csv).values.rows(), 3);
  for (const char* times : {"--query 0,0.5,1", "--steps 5"}) {
    EXPECT_EQ(run(fmt::format("{} --model {} --obs 0,0,0 --context 0.5 {} --out {}",
                              PREDICT_CNMP_BIN, model, times, csv),
                  &err, &dir),
              0);
    EXPECT_EQ(err, "") << times;
  }
  EXPECT_EQ(run(fmt::format("{} --model {} --obs 0,0,0 --context 0.5 --query 0.5,1.25 --out {}",
                            PREDICT_CNMP_BIN, model, csv),
                &err, &dir),
            0);
  EXPECT_NE(err.find("query times span [0.5, 1.25]"), std::string::npos) << err;
}

// A numeric option given a value that is not a number (or not a whole one, or a negative seed):
// one line naming the option and the value, exit 2. Integers are decimal: 010 is ten.
TEST(CnmpTools, ANonNumberForANumericOptionNamesTheOptionAndTheValue) {
  TempDir dir;
  write_demos(dir);
  const std::string train = fmt::format("{} --data {} --time time --y px,py --out {} --quiet",
                                        TRAIN_CNMP_BIN, dir.file("demos"), dir.file("m.cnmp"));
  const std::vector<std::pair<std::string, std::string>> train_cases = {
      {"--updates abc", "--updates: expected an integer, got 'abc'"},
      {"--batch 1.5", "--batch: expected an integer, got '1.5'"},
      {"--width x", "--width: expected an integer, got 'x'"},
      {"--seed abc", "--seed: expected a non-negative integer, got 'abc'"},
      {"--seed -1", "--seed: expected a non-negative integer, got '-1'"},
      {"--lr fast", "--lr: expected a number, got 'fast'"},
      {"--validation-fraction abc", "--validation-fraction: expected a number, got 'abc'"},
  };
  std::string err;
  for (const auto& [args, expected] : train_cases) {
    EXPECT_EQ(run(train + " " + args, &err, &dir), 2) << args;
    EXPECT_EQ(err, "train_cnmp: " + expected + " (see --help)\n") << args;
    EXPECT_FALSE(std::filesystem::exists(dir.file("m.cnmp"))) << args;
  }
  ASSERT_EQ(run(train + " --updates 10 --width 4"), 0);
  const std::string predict = fmt::format("{} --model {} --obs 0,0,0 --out {}", PREDICT_CNMP_BIN,
                                          dir.file("m.cnmp"), dir.file("p.csv"));
  EXPECT_EQ(run(predict + " --steps abc", &err, &dir), 2);
  EXPECT_EQ(err, "predict_cnmp: --steps: expected an integer, got 'abc' (see --help)\n");
  ASSERT_EQ(run(predict + " --steps 010"), 0);
  EXPECT_EQ(read_csv_trajectory(dir.file("p.csv")).values.rows(), 10);
}

TEST(CnmpTools, BadInputGivesAClearErrorAndNonZeroExit) {
  TempDir dir;
  write_demos(dir);
  std::string err;
  EXPECT_EQ(run(fmt::format("{} --data {} --y nope --out {}", TRAIN_CNMP_BIN, dir.file("demos"),
                            dir.file("m.cnmp")),
                &err, &dir),
            2);
  EXPECT_NE(err.find("no column 'nope'"), std::string::npos) << err;
  // Bad data and unusable model files are bad input too: exit 2, one line naming the file.
  dir.write("bad/d.csv", "time,px\n0,1\n1,x\n");
  EXPECT_EQ(run(fmt::format("{} --data {} --y px --out {}", TRAIN_CNMP_BIN, dir.file("bad"),
                            dir.file("m.cnmp")),
                &err, &dir),
            2);
  EXPECT_NE(err.find("d.csv:3:"), std::string::npos) << err;
  dir.write("garbage.cnmp", "not a model");
  std::filesystem::create_directories(dir.file("directory.cnmp"));
  for (const char* model : {"none.cnmp", "garbage.cnmp", "directory.cnmp"}) {
    EXPECT_EQ(
        run(fmt::format("{} --model {} --obs 0,0", PREDICT_CNMP_BIN, dir.file(model)), &err, &dir),
        2)
        << model;
    EXPECT_NE(err.find(model), std::string::npos) << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  }
  EXPECT_EQ(run(fmt::format("{} --data {}", TRAIN_CNMP_BIN, dir.file("demos")), &err, &dir), 2);
  ASSERT_EQ(run(fmt::format("{} --data {} --time time --y px,py --context goal --updates 10 "
                            "--width 4 --out {} --quiet",
                            TRAIN_CNMP_BIN, dir.file("demos"), dir.file("m.cnmp"))),
            0);
  EXPECT_EQ(
      run(fmt::format("{} --model {} --obs 0,0 --context 1", PREDICT_CNMP_BIN, dir.file("m.cnmp")),
          &err, &dir),
      2);
  EXPECT_NE(err.find("needs 1 x and 2 y values"), std::string::npos) << err;
  EXPECT_EQ(run(fmt::format("{} --model {} --obs 0,0,0 --context a", PREDICT_CNMP_BIN,
                            dir.file("m.cnmp")),
                &err, &dir),
            2);
  // NaN and infinity are refused, not propagated into the prediction.
  for (const char* args : {"--obs 0,nan,0 --context 1", "--obs 0,inf,0 --context 1",
                           "--obs 0,0,0 --context nan", "--obs 0,0,0 --context 1 --query nan"}) {
    EXPECT_EQ(run(fmt::format("{} --model {} {}", PREDICT_CNMP_BIN, dir.file("m.cnmp"), args), &err,
                  &dir),
              2)
        << args;
    EXPECT_NE(err.find("is not a finite number"), std::string::npos) << args << ": " << err;
  }
}

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

using testing::kSanitized;

// An output that is one of the inputs (the same file by any spelling or link) is refused before
// any work, exit 2, and the input is left as it was.
TEST(CnmpTools, AnOutputThatIsAnInputIsRefusedBeforeAnyWork) {
  TempDir dir;
  write_demos(dir);
  const std::string first = dir.file("demos/00.csv"), second = dir.file("demos/01.csv");
  const std::string demo = bytes_of(first);
  std::filesystem::create_symlink(first, dir.file("link.csv"));
  std::string err;
  for (const auto& [data, out] : std::vector<std::pair<std::string, std::string>>{
           {first + " " + second, first},
           {first + " " + second, dir.file("demos/../demos/./00.csv")},
           {dir.file("demos"), dir.file("link.csv")}}) {
    EXPECT_EQ(run(fmt::format("{} --data {} --time time --y px,py --updates 10 --width 4 --out {} "
                              "--quiet",
                              TRAIN_CNMP_BIN, data, out),
                  &err, &dir),
              2)
        << out;
    EXPECT_EQ(err.rfind("train_cnmp: --out " + out + ": is the demonstration file ", 0), 0u) << err;
    EXPECT_NE(err.find("write the model to another file\n"), std::string::npos) << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    EXPECT_TRUE(bytes_of(first) == demo) << out << ": the demonstration was overwritten";
  }
  const std::string model = dir.file("m.cnmp");
  ASSERT_EQ(run(fmt::format("{} --data {} --time time --y px,py --updates 10 --width 4 --out {} "
                            "--quiet",
                            TRAIN_CNMP_BIN, dir.file("demos"), model)),
            0);
  const std::string trained = bytes_of(model);
  for (const std::string& out : {model, dir.file("./m.cnmp")}) {
    EXPECT_EQ(run(fmt::format("{} --model {} --obs 0,0,0 --steps 5 --out {}", PREDICT_CNMP_BIN,
                              model, out),
                  &err, &dir),
              2)
        << out;
    EXPECT_EQ(err, "predict_cnmp: --out " + out + ": is the model file (--model " + model +
                       "): write the predictions to another file\n");
    EXPECT_TRUE(bytes_of(model) == trained) << out << ": the model was overwritten";
  }
}

// Sizes whose training cannot fit in memory are refused before training, naming the option
// (the estimate run_experiment makes at load), instead of ending in std::bad_alloc.
TEST(CnmpTools, SizesThatCannotFitInMemoryAreRefusedNamingTheOption) {
  TempDir dir;
  write_demos(dir);
  // One update and its validation: without the estimate, the failure would come at once.
  const std::string train =
      fmt::format("{} --data {} --time time --y px,py --updates 1 --validate-every 1 --out {}",
                  TRAIN_CNMP_BIN, dir.file("demos"), dir.file("m.cnmp"));
  std::string err;
  EXPECT_EQ(run(train + " --batch 2000000000", &err, &dir), 2);
  EXPECT_EQ(err.rfind("train_cnmp: --batch: the declared sizes need about ", 0), 0u) << err;
  EXPECT_NE(err.find("for the training batches (batch_size 2000000000"), std::string::npos) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  if (kSanitized) GTEST_SKIP() << "a sanitizer's shadow memory cannot run under ulimit -v";
  // The widest, deepest network: about 500 million parameters, more than 2 GiB allow (a limit
  // below any machine's memory, so the message names the limit).
  EXPECT_EQ(
      run("ulimit -v 2097152; " + train + " --width 4096 --encoder-layers 16 --decoder-layers 16",
          &err, &dir),
      2);
  EXPECT_EQ(err.rfind("train_cnmp: --width: the declared sizes need about ", 0), 0u) << err;
  EXPECT_NE(err.find("width 4096, 16 encoder and 16 decoder layers"), std::string::npos) << err;
  EXPECT_NE(err.find("this process may use 2.0 GiB (ulimit)"), std::string::npos) << err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("m.cnmp")));
}

// A column named twice, or given two roles (the time column as an output), is refused in one
// line before the data is read.
TEST(CnmpTools, AColumnNamedTwiceOrGivenTwoRolesIsRefused) {
  TempDir dir;
  write_demos(dir);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--time time --y px,px", "--y: column 'px' is named twice"},
      {"--time time --y time",
       "--y: column 'time' is also named by --time; each column has one "
       "role"},
      {"--time time --y px --context px",
       "--context: column 'px' is also named by --y; each "
       "column has one role"},
      {"--time time --x goal --y goal",
       "--y: column 'goal' is also named by --x; each column has "
       "one role"},
  };
  std::string err;
  for (const auto& [args, expected] : cases) {
    EXPECT_EQ(run(fmt::format("{} --data {} {} --updates 10 --width 4 --out {} --quiet",
                              TRAIN_CNMP_BIN, dir.file("demos"), args, dir.file("m.cnmp")),
                  &err, &dir),
              2)
        << args;
    EXPECT_EQ(err, "train_cnmp: " + expected + "\n") << args;
    EXPECT_FALSE(std::filesystem::exists(dir.file("m.cnmp"))) << args;
  }
}

}  // namespace
}  // namespace corrmp
