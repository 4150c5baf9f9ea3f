// Tests of opening a result database that is not a healthy one: a 0-byte file
// becomes a new database with a one-line notice; garbage bytes, a truncated
// database or a directory are refused with the path, before anything is
// written; every error of a statement names the database file.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "config/test_files.hpp"
#include "log_capture.hpp"
#include "store/result_store.hpp"
#include "support/store_sql.hpp"

namespace corrmp {
namespace {

using ::testing::StartsWith;
using ::testing::ThrowsMessage;

namespace fs = std::filesystem;
using testing::TempDir;

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

std::string store_error_of(const std::string& path) {
  try {
    ResultStore store(path);
  } catch (const StoreError& e) {
    return e.what();
  }
  return "";
}

// A real database with a few runs, closed (so checkpointed into one file).
void write_real_database(const std::string& path) {
  ResultStore store(path);
  for (int i = 0; i < 20; ++i) {
    RunRecord run;
    run.experiment = "e";
    run.config = std::string(2000, 'c');
    run.config_hash = "h";
    const int64_t id = store.begin_run(run);
    store.complete_run(id, {TrialRecord{0, std::string(1000, 's'), "a", "a", true, "", ""}},
                       {{"m", 1.0}});
  }
}

TEST(DamagedDatabase, AZeroByteFileBecomesANewDatabaseWithOneNotice) {
  TempDir dir;
  const std::string path = dir.write("touched.sqlite", "");
  testing::LogCapture log;
  {
    ResultStore store(path);
    EXPECT_EQ(testing::query_int(store, "PRAGMA user_version"), ResultStore::kSchemaVersion);
    RunRecord run;
    run.experiment = "e";
    EXPECT_GT(store.begin_run(run), 0);
  }
  EXPECT_EQ(log.warnings(),
            "[warning] " + path + ": empty file (0 bytes); using it as a new result database\n");
  { ResultStore again(path); }  // no longer empty: no second notice
  const std::string text = log.text();
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;
}

// A database another process has just created in WAL mode still has a 0-byte
// main file (its schema is in the -wal file): that is no empty file.
TEST(DamagedDatabase, ANewDatabaseOrOneStillInItsWalGetsNoNotice) {
  TempDir dir;
  const std::string path = dir.file("new.sqlite");
  testing::LogCapture log;
  ResultStore first(path);
  ResultStore second(path);
  EXPECT_EQ(log.text(), "");
}

TEST(DamagedDatabase, GarbageBytesAreRefusedNamingTheFileAndLeftAlone) {
  TempDir dir;
  std::string garbage;
  for (int i = 0; i < 2000; ++i) garbage += "not a database ";
  const std::string path = dir.write("garbage.sqlite", garbage);
  EXPECT_EQ(store_error_of(path), path +
                                      ": not a usable result database (not an SQLite database); "
                                      "move it aside or choose another database file");
  EXPECT_EQ(bytes_of(path), garbage);
}

TEST(DamagedDatabase, ATruncatedDatabaseIsRefusedNamingTheFileAndLeftAlone) {
  TempDir dir;
  const std::string path = dir.file("r.sqlite");
  write_real_database(path);
  ASSERT_GT(fs::file_size(path), 3 * 4096u);
  fs::resize_file(path, 2 * 4096);
  const std::string truncated = bytes_of(path);
  EXPECT_EQ(store_error_of(path), path +
                                      ": not a usable result database (the file is damaged or "
                                      "truncated); move it aside or choose another database file");
  EXPECT_EQ(bytes_of(path), truncated);
}

TEST(DamagedDatabase, ADirectoryIsRefusedNamingIt) {
  TempDir dir;
  fs::create_directories(dir.file("results.sqlite"));
  EXPECT_EQ(store_error_of(dir.file("results.sqlite")),
            dir.file("results.sqlite") + ": is a directory, not a database");
}

TEST(DamagedDatabase, EveryStatementErrorNamesTheDatabase) {
  TempDir dir;
  const std::string path = dir.file("r.sqlite");
  ResultStore store(path);
  EXPECT_THAT([&] { testing::query_text(store, "SELECT nothing FROM nowhere"); },
              ThrowsMessage<StoreError>(StartsWith(fs::canonical(path).string() + ": ")));
}

}  // namespace
}  // namespace corrmp
