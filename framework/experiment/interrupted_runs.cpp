// Marking runs whose process ended without finishing them (interrupted_runs.hpp).
#include "experiment/interrupted_runs.hpp"

#include <spdlog/spdlog.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/atomic_file.hpp"
#include "core/json_writer.hpp"

namespace corrmp {

namespace {

// Replaces the one occurrence of `from` in `text`; false if it is not there exactly once.
bool replace_once(std::string& text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  if (at == std::string::npos || text.find(from, at + 1) != std::string::npos) return false;
  text.replace(at, from.size(), to);
  return true;
}

}  // namespace

bool mark_run_json_interrupted(const std::string& path, const std::string& finished_at,
                               const std::string& failure) {
  std::ifstream in(path);
  if (!in) return false;
  std::stringstream read;
  read << in.rdbuf();
  std::string text = read.str();
  // The two members as the pipeline's JsonObject writes them at an indent of 2.
  std::string members = JsonObject().add("finished_at", finished_at).add("failure", failure).str(2);
  members = members.substr(2, members.rfind('\n') - 2);  // without the braces' lines
  const auto status_line = [](RunStatus status) {
    return "\n  \"status\": \"" + to_string(status) + "\",";
  };
  if (!replace_once(text, status_line(RunStatus::running), status_line(RunStatus::interrupted)) ||
      !replace_once(text, "\n  \"finished_at\": null,", "\n" + members + ","))
    return false;
  write_file_atomically(path, text);
  return true;
}

namespace {

// Writes what the database now says of `marked` into their folders' run.json.
void mark_run_jsons(const std::vector<ResultStore::InterruptedRun>& marked) {
  for (const auto& run : marked) {
    if (run.out_dir.empty()) continue;
    const std::string path = (std::filesystem::path(run.out_dir) / "run.json").string();
    try {
      if (!mark_run_json_interrupted(path, run.finished_at, run.failure))
        spdlog::debug("run {}: {} not updated (missing or edited)", run.id, path);
    } catch (const std::exception& e) {  // the database is right; the folder is a copy
      spdlog::warn("run {}: cannot mark {} interrupted: {}", run.id, path, e.what());
    }
  }
}

}  // namespace

int mark_interrupted_runs(ResultStore& store) {
  const auto marked = store.mark_interrupted_runs();
  mark_run_jsons(marked);
  return static_cast<int>(marked.size());
}

int mark_job_runs_interrupted(ResultStore& store, const std::string& sweep_id, int job_index) {
  const auto marked = store.mark_job_runs_interrupted(sweep_id, job_index);
  mark_run_jsons(marked);
  return static_cast<int>(marked.size());
}

}  // namespace corrmp
