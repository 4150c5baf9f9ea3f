// Store-internal: a run's task declaration as its row of the run_tasks table, lists as JSON
// arrays.
#pragma once

#include <sqlite3.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "store/records.hpp"

namespace corrmp {

// The run_tasks columns after run_id, in the order insert_task writes them.
extern const std::vector<std::string> kTaskColumns;

void insert_task(sqlite3* db, int64_t run_id, const TaskDeclaration& task);
// The run's task declaration; nothing for a run without one (no environment, or recorded
// before runs stored them).
std::optional<TaskDeclaration> read_task(sqlite3* db, int64_t run_id);

}  // namespace corrmp
