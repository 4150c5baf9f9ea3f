// A sweep's manifest as YAML (sweep_manifest.hpp).
#include "sweep/sweep_manifest.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/atomic_file.hpp"
#include "core/config/config_error.hpp"
#include "core/json_writer.hpp"
#include "sweep/sweep_names.hpp"

namespace corrmp {

std::string manifest_yaml(const Sweep& sweep) {
  YAML::Emitter out;
  out << YAML::BeginMap << YAML::Key << "id" << YAML::Value << sweep.id << YAML::Key << "name"
      << YAML::Value << sweep.name;
  out << YAML::Key << "slurm" << YAML::Value << YAML::Flow << YAML::BeginMap << YAML::Key
      << "cpus_per_task" << YAML::Value << sweep.slurm.cpus_per_task << YAML::Key << "time"
      << YAML::Value << sweep.slurm.time << YAML::Key << "memory" << YAML::Value
      << sweep.slurm.memory << YAML::Key << "partition" << YAML::Value << sweep.slurm.partition
      << YAML::EndMap;
  if (!sweep.config_hashes.empty()) {
    out << YAML::Key << "config_hashes" << YAML::Value << YAML::BeginSeq;
    for (const auto& [path, hash] : sweep.config_hashes) {
      out << YAML::Flow << YAML::BeginSeq << YAML::DoubleQuoted << path << YAML::DoubleQuoted
          << hash << YAML::EndSeq;
    }
    out << YAML::EndSeq;
  }
  out << YAML::Key << "jobs" << YAML::Value << YAML::BeginSeq;
  for (const auto& job : sweep.jobs) {
    out << YAML::BeginMap << YAML::Key << "index" << YAML::Value << job.index << YAML::Key
        << "config" << YAML::Value << job.config_path << YAML::Key << "overrides" << YAML::Value
        << YAML::BeginSeq;
    for (const auto& o : job.overrides) out << YAML::DoubleQuoted << o;
    out << YAML::EndSeq << YAML::Key << "axes" << YAML::Value << YAML::BeginSeq;
    for (const auto& [key, value] : job.axes) {
      out << YAML::Flow << YAML::BeginSeq << YAML::DoubleQuoted << key << YAML::DoubleQuoted
          << value << YAML::EndSeq;
    }
    out << YAML::EndSeq << YAML::EndMap;
  }
  out << YAML::EndSeq << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

Sweep parse_manifest(const std::string& text, const std::string& origin) {
  Sweep sweep;
  try {
    const YAML::Node root = YAML::Load(text);
    sweep.id = root["id"].as<std::string>();
    sweep.name = root["name"].as<std::string>();
    const YAML::Node slurm = root["slurm"];
    sweep.slurm.cpus_per_task = slurm["cpus_per_task"].as<int>();
    sweep.slurm.time = slurm["time"].as<std::string>();
    sweep.slurm.memory = slurm["memory"].as<std::string>();
    sweep.slurm.partition = slurm["partition"].as<std::string>();
    for (const auto& pair : root["config_hashes"]) {
      sweep.config_hashes.emplace_back(pair[0].as<std::string>(), pair[1].as<std::string>());
    }
    for (const auto& node : root["jobs"]) {
      SweepJob job;
      job.index = node["index"].as<int>();
      job.config_path = node["config"].as<std::string>();
      job.overrides = node["overrides"].as<std::vector<std::string>>();
      for (const auto& axis : node["axes"]) {
        job.axes.emplace_back(axis[0].as<std::string>(), axis[1].as<std::string>());
      }
      if (job.index != static_cast<int>(sweep.jobs.size())) {
        throw std::runtime_error("jobs out of order");
      }
      sweep.jobs.push_back(std::move(job));
    }
  } catch (const std::exception& e) {
    throw std::runtime_error(fmt::format("{}: not a sweep manifest: {}", origin, e.what()));
  }
  // The id names folders and files: one from a manifest written elsewhere (a merged shard, a
  // file given to --sweep-job) is checked like any input.
  if (const std::string problem = sweep_id_problem(sweep.id); !problem.empty()) {
    throw ConfigError(fmt::format("{}: id: {}", origin, problem));
  }
  return sweep;
}

void write_manifest(const std::string& path, const Sweep& sweep) {
  write_file_atomically(path, manifest_yaml(sweep));
}

Sweep read_manifest(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) {
    throw std::runtime_error(fmt::format("{}: no such sweep manifest", path));
  }
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return parse_manifest(text.str(), path);
}

std::string axes_json(const SweepJob& job) {
  JsonObject axes;
  for (const auto& [key, value] : job.axes) axes.add(key, value);
  return axes.str();
}

}  // namespace corrmp
