// Test helpers for killing a tool mid-run: start it as a child with its output discarded,
// and wait until its database shows what the test waits for.
#pragma once

#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "store/result_store.hpp"
#include "support/store_sql.hpp"

namespace corrmp::testing {

// Starts `argv` (argv[0] is the executable) with stdout and stderr sent to /dev/null.
inline pid_t spawn_quietly(const std::vector<std::string>& argv) {
  const pid_t child = fork();
  if (child == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, STDOUT_FILENO);
    ::dup2(null, STDERR_FILENO);
    std::vector<char*> args;
    for (const auto& arg : argv) args.push_back(const_cast<char*>(arg.c_str()));
    args.push_back(nullptr);
    execv(args[0], args.data());
    _exit(127);
  }
  return child;
}

// Polls the integer `query` on the database at `db` until it is positive or `seconds` pass;
// returns its last value (0 when the database never appeared).
inline int64_t wait_until_positive(const std::string& db, const std::string& query,
                                   int seconds = 60) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
  int64_t value = 0;
  while (value <= 0 && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    if (!std::filesystem::exists(db)) continue;
    try {
      ResultStore store(db);
      value = testing::query_int(store, query);
    } catch (const StoreError&) {
    }
  }
  return value;
}

}  // namespace corrmp::testing
