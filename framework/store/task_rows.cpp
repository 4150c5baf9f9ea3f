// Task declarations in the run_tasks table (task_rows.hpp).
#include "store/task_rows.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "store/statement.hpp"

namespace corrmp {

namespace {

std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (const unsigned char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c < 0x20) {
      out += fmt::format("\\u{:04x}", c);
    } else {
      out += static_cast<char>(c);
    }
  }
  return out + "\"";
}

std::string json_array(const std::vector<std::string>& items) {
  std::vector<std::string> quoted;
  for (const auto& item : items) quoted.push_back(json_string(item));
  return fmt::format("[{}]", fmt::join(quoted, ","));
}

std::string json_array(const std::vector<int>& items) {
  return fmt::format("[{}]", fmt::join(items, ","));
}

// The elements of a JSON array, as text, in order (SQLite's json_each).
std::vector<std::string> array_items(sqlite3* db, const std::string& json) {
  std::vector<std::string> items;
  if (json.empty()) return items;
  Statement each(db, "SELECT value FROM json_each(?) ORDER BY key");
  each.bind(1, json);
  while (each.step()) items.push_back(each.column_text(0));
  return items;
}

std::vector<int> int_items(sqlite3* db, const std::string& json) {
  std::vector<int> items;
  for (const auto& item : array_items(db, json)) items.push_back(std::stoi(item));
  return items;
}

}  // namespace

const std::vector<std::string> kTaskColumns = {
    "trajectory_columns", "error_unit",       "error_scale",     "error_segments",
    "error_columns",      "decision_segment", "decision_labels", "relative_columns",
    "plot_horizontal",    "plot_vertical",    "outcome_metrics", "failure_categories"};

void insert_task(sqlite3* db, int64_t run_id, const TaskDeclaration& task) {
  std::vector<std::string> places(kTaskColumns.size() + 1, "?");
  Statement insert(db, fmt::format("INSERT INTO run_tasks (run_id, {}) VALUES ({})",
                                   fmt::join(kTaskColumns, ", "), fmt::join(places, ", ")));
  insert.bind(1, run_id)
      .bind(2, json_array(task.trajectory_columns))
      .bind(3, task.error_unit)
      .bind(4, task.error_scale)
      .bind(5, json_array(task.error_segments))
      .bind(6, json_array(task.error_columns))
      .bind(7, task.decision_segment)
      .bind(8, json_array(task.decision_labels))
      .bind(9, json_array(task.relative_columns))
      .bind(10, int64_t{task.plot_horizontal})
      .bind(11, int64_t{task.plot_vertical})
      .bind(12, json_array(task.outcome_metrics))
      .bind(13, json_array(task.failure_categories))
      .run();
}

std::optional<TaskDeclaration> read_task(sqlite3* db, int64_t run_id) {
  Statement select(
      db, fmt::format("SELECT {} FROM run_tasks WHERE run_id = ?", fmt::join(kTaskColumns, ", ")));
  select.bind(1, run_id);
  if (!select.step()) return std::nullopt;
  TaskDeclaration task;
  task.trajectory_columns = array_items(db, select.column_text(0));
  task.error_unit = select.column_text(1);
  task.error_scale = select.column_double(2);
  task.error_segments = array_items(db, select.column_text(3));
  task.error_columns = int_items(db, select.column_text(4));
  task.decision_segment = select.column_text(5);
  task.decision_labels = array_items(db, select.column_text(6));
  task.relative_columns = int_items(db, select.column_text(7));
  task.plot_horizontal = static_cast<int>(select.column_int(8));
  task.plot_vertical = static_cast<int>(select.column_int(9));
  task.outcome_metrics = array_items(db, select.column_text(10));
  task.failure_categories = array_items(db, select.column_text(11));
  return task;
}

}  // namespace corrmp
