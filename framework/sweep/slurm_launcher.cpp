// The job-array script of a sweep and its submission with sbatch. docs/slurm.md.
#include "sweep/slurm_launcher.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "sweep/run_command.hpp"
#include "sweep/shell_words.hpp"

namespace corrmp {
namespace {

// A file name pattern on an #SBATCH line: sbatch reads a double-quoted argument with
// \" and \\ escapes, then Slurm expands %-patterns (a literal % is %%) and expands
// none of them when the name holds a backslash, so a backslash is refused.
std::string sbatch_file_pattern(const std::string& dir, const std::string& name) {
  if (dir.find_first_of("\\\n\r") != std::string::npos) {
    throw std::invalid_argument("the Slurm log directory '" + dir +
                                "' holds a backslash or a line break, which an #SBATCH "
                                "line cannot take");
  }
  std::string quoted = "\"";
  for (const char c : dir + "/") {
    if (c == '"') {
      quoted += "\\\"";
    } else if (c == '%') {
      quoted += "%%";
    } else {
      quoted += c;
    }
  }
  return quoted + name + "\"";
}

// A resource value written as is on an #SBATCH line.
const std::string& checked_resource(const std::string& value, const std::string& key) {
  if (const std::string problem = slurm_value_problem(value); !problem.empty()) {
    throw std::invalid_argument("slurm." + key + ": " + problem);
  }
  return value;
}

// The job name: the sweep's name with anything but letters, digits and ._+- as '_'.
std::string job_name(const std::string& name) {
  std::string safe = name.empty() ? "sweep" : name;
  for (char& c : safe) {
    if (!std::isalnum(static_cast<unsigned char>(c)) &&
        std::string("._+-").find(c) == std::string::npos) {
      c = '_';
    }
  }
  return safe;
}

// The tasks run in sbatch's working directory on another node: every path absolute.
std::string absolute(const std::string& path) {
  return std::filesystem::absolute(path).lexically_normal().string();
}

std::vector<int> selected_indices(const Sweep& sweep, const SlurmArraySelection& selection) {
  const int count = static_cast<int>(sweep.jobs.size());
  if (count == 0) throw std::invalid_argument("sweep '" + sweep.name + "' has no jobs");
  if (selection.indices.empty()) {
    std::vector<int> all(count);
    for (int i = 0; i < count; ++i) all[i] = i;
    return all;
  }
  for (const int index : selection.indices) {
    if (index < 0 || index >= count) {
      throw std::invalid_argument("job index " + std::to_string(index) + " is not in sweep '" +
                                  sweep.name + "' (jobs 0-" + std::to_string(count - 1) + ")");
    }
  }
  return selection.indices;
}

}  // namespace

std::string slurm_value_problem(const std::string& value) {
  const bool plain = std::all_of(value.begin(), value.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) ||
           std::string(":-_.,+").find(c) != std::string::npos;
  });
  if (plain) return "";
  return "'" + value + "' is not a Slurm value (letters, digits and :-_.,+ only)";
}

std::string slurm_array_spec(std::vector<int> indices, int max_concurrent) {
  if (indices.empty()) throw std::invalid_argument("a Slurm array needs at least one index");
  if (max_concurrent < 0) throw std::invalid_argument("a negative limit of running tasks");
  std::sort(indices.begin(), indices.end());
  indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
  std::string spec;
  for (size_t start = 0; start < indices.size();) {
    size_t end = start;
    while (end + 1 < indices.size() && indices[end + 1] == indices[end] + 1) ++end;
    if (!spec.empty()) spec += ',';
    spec += std::to_string(indices[start]);
    if (end > start) spec += '-' + std::to_string(indices[end]);
    start = end + 1;
  }
  if (max_concurrent > 0) spec += '%' + std::to_string(max_concurrent);
  return spec;
}

std::string slurm_array_script(const Sweep& sweep, const SlurmPaths& paths,
                               const SlurmArraySelection& selection) {
  const std::vector<int> indices = selected_indices(sweep, selection);
  const SlurmResources& resources = sweep.slurm;
  if (resources.cpus_per_task < 1) {
    throw std::invalid_argument("slurm.cpus_per_task: " + std::to_string(resources.cpus_per_task) +
                                " is not a positive number of CPUs");
  }

  std::ostringstream script;
  script << "#!/bin/bash\n";
  script << "#SBATCH --job-name=" << job_name(sweep.name) << "\n";
  script << "#SBATCH --array=" << slurm_array_spec(indices, selection.max_concurrent) << "\n";
  script << "#SBATCH --cpus-per-task=" << resources.cpus_per_task << "\n";
  if (!resources.time.empty()) {
    script << "#SBATCH --time=" << checked_resource(resources.time, "time") << "\n";
  }
  if (!resources.memory.empty()) {
    script << "#SBATCH --mem=" << checked_resource(resources.memory, "memory") << "\n";
  }
  if (!resources.partition.empty()) {
    script << "#SBATCH --partition=" << checked_resource(resources.partition, "partition") << "\n";
  }
  const std::string log_dir = absolute(paths.log_dir);
  script << "#SBATCH --output=" << sbatch_file_pattern(log_dir, "job-%a.out") << "\n";
  script << "#SBATCH --error=" << sbatch_file_pattern(log_dir, "job-%a.err") << "\n";
  script << "\n";
  script << "# Sweep " << job_name(sweep.id) << ": " << sweep.jobs.size()
         << " jobs; task i runs job i of the manifest into its own shard database.\n";
  script << "# Written by run_experiment (docs/slurm.md).\n";
  script << "set -euo pipefail\n";
  script << "exec " << shell_quoted(absolute(paths.run_experiment)) << " --sweep-job "
         << shell_quoted(absolute(paths.manifest)) << " \"$SLURM_ARRAY_TASK_ID\" --db "
         << shell_quoted(absolute(paths.shard_dir)) << "\"/job-$SLURM_ARRAY_TASK_ID.sqlite\" --out "
         << shell_quoted(absolute(paths.out_dir))
         << " --threads \"${SLURM_CPUS_PER_TASK:-1}\" --quiet\n";
  return script.str();
}

SlurmSubmission submit_slurm(const std::string& script_path, bool wait) {
  std::vector<std::string> argv = {"sbatch", "--parsable"};
  if (wait) argv.push_back("--wait");
  argv.push_back(script_path);

  CommandResult result;
  try {
    result = run_command(argv);
  } catch (const CommandNotFound&) {
    throw std::runtime_error(
        "sbatch not found: is Slurm installed? use --emit slurm DIR to only write the files");
  }

  // --parsable prints "<job id>" or "<job id>;<cluster>" as soon as the job is queued;
  // with --wait, sbatch then exits with the job's status.
  std::string job_id = result.out.substr(0, result.out.find_first_of(";\n"));
  const bool numeric = !job_id.empty() && std::all_of(job_id.begin(), job_id.end(), [](char c) {
    return std::isdigit(static_cast<unsigned char>(c));
  });
  if (!numeric) {
    std::string why = result.err.empty() ? result.out : result.err;
    while (!why.empty() && (why.back() == '\n' || why.back() == ' ')) why.pop_back();
    throw std::runtime_error("sbatch could not submit " + script_path + " (exit " +
                             std::to_string(result.exit_code) +
                             "): " + (why.empty() ? "no message" : why));
  }
  SlurmSubmission submission;
  submission.job_id = job_id;
  if (wait) submission.exit_code = result.exit_code;
  return submission;
}

}  // namespace corrmp
