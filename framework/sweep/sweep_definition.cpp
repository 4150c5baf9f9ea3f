// Sweeps from the command line and sweep files (sweep_definition.hpp).
#include "sweep/sweep_definition.hpp"

#include <fmt/format.h>

#include <ctime>
#include <filesystem>
#include <random>

#include "core/config/config_loader.hpp"
#include "core/config/config_reader.hpp"
#include "sweep/slurm_launcher.hpp"
#include "sweep/sweep_axes.hpp"
#include "sweep/sweep_names.hpp"

namespace corrmp {

namespace fs = std::filesystem;

namespace {

// The `slurm:` section of a sweep file.
struct SlurmSection {
  SlurmResources resources;
  template <class Fields>
  void describe(Fields& f) {
    f("cpus_per_task", resources.cpus_per_task, "CPUs of each array task (--cpus-per-task)",
      in_range(1, 1024));
    f("time", resources.time, "time limit of each task (--time), e.g. 01:00:00");
    f("memory", resources.memory, "memory of each task (--mem), e.g. 4G");
    f("partition", resources.partition, "partition (--partition); empty: the cluster's default");
  }
};

// The `sweep:` section; axes and zip are read by hand (their keys are config paths).
struct SweepSection {
  std::string name;
  std::vector<std::string> configs;
  std::vector<std::string> overrides;
  template <class Fields>
  void describe(Fields& f) {
    f("name", name, "the sweep's name", required());
    f("configs", configs, "experiment configs (relative to this file), each crossed with the axes",
      required());
    f("overrides", overrides, "key.path=value overrides applied to every job");
  }
};

// Resources an #SBATCH line cannot hold are refused where the file sets them, whether the
// sweep then runs here or on Slurm.
void check_slurm_values(const ConfigNode& section, const SlurmResources& resources) {
  const std::pair<const char*, const std::string*> values[] = {{"time", &resources.time},
                                                               {"memory", &resources.memory},
                                                               {"partition", &resources.partition}};
  for (const auto& [key, value] : values) {
    const ConfigNode* node = section.find(key);
    if (node == nullptr) continue;
    if (const std::string problem = slurm_value_problem(*value); !problem.empty()) {
      throw ConfigError(node->where(), std::string("sweep.slurm.") + key, problem);
    }
  }
}

// One YAML value as the text of an override's value: a plain scalar as written, anything
// else (a quoted string, a list, a map) as flow YAML that reads back as the same value.
std::string override_value(const ConfigNode& value) {
  if (value.is_scalar() && !value.quoted()) return value.text();
  std::string text = value.to_yaml_string(true);
  while (!text.empty() && text.back() == '\n') text.pop_back();
  return text;
}

// An axis of a sweep file: a list is its values, one per item, taken as they are; a scalar is
// read as on the command line (a,b,c, range(), choice()).
std::vector<std::string> axis_values(const ConfigNode& value, const std::string& path) {
  if (value.is_scalar()) return parse_axis_values(value.text(), value.where(), path);
  if (value.is_sequence()) {
    std::vector<std::string> values;
    for (const auto& item : value.items()) {
      if (item.is_null() || (item.is_scalar() && !item.quoted() && item.text().empty())) {
        throw ConfigError(item.where(), path, "empty value");
      }
      values.push_back(override_value(item));
    }
    if (values.empty()) throw ConfigError(value.where(), path, "the axis has no values");
    return values;
  }
  throw ConfigError(value.where(), path, "expected values: a list, a,b,c, range() or choice()");
}

std::vector<SweepAxis> read_axes(const ConfigNode& map, const std::string& path) {
  if (!map.is_map()) throw ConfigError(map.where(), path, "expected a map of key.path: values");
  std::vector<SweepAxis> axes;
  for (const auto& entry : map.entries()) {
    const std::string axis_path = path + "." + entry.key;
    SweepAxis axis;
    axis.key = entry.key;
    axis.where = entry.value.where();
    axis.values = axis_values(entry.value, axis_path);
    axes.push_back(std::move(axis));
  }
  return axes;
}

// A fixed override that an axis would replace, wholly (the same key, or one under the axis's
// key) is refused: its value would be dropped without a word. One that the axes refine
// (`policy.network={...}` fixed, `policy.network.width` swept) keeps its other values.
void check_no_axis_replaces(const std::string& assignment, const SourceLocation& where,
                            const std::string& path, const std::vector<AxisGroup>& groups) {
  const auto equals = assignment.find('=');
  if (equals == std::string::npos) return;  // the config loader names what is wrong
  std::string key = assignment.substr(0, equals);
  key.erase(0, key.find_first_not_of(" \t"));
  key.erase(key.find_last_not_of(" \t") + 1);
  for (const auto& group : groups) {
    for (const auto& axis : group) {
      if (key != axis.key && key.rfind(axis.key + ".", 0) != 0) continue;
      throw ConfigError(where, path.empty() ? key : path + ": " + key,
                        fmt::format("the sweep also varies {} ({}), whose values would replace "
                                    "this one: drop one of them",
                                    axis.key, axis.where.str()));
    }
  }
}

}  // namespace

bool is_sweep_file(const std::string& path) {
  const ConfigNode root = ConfigNode::load_file(path);
  return root.is_map() && root.find("sweep") != nullptr;
}

std::string new_sweep_id(const std::string& name) {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%dT%H%M%S", &utc);
  std::random_device random;
  return fmt::format("{}-{}-{:04x}", name, stamp, random() & 0xffffu);
}

Sweep define_sweep(const std::string& config_path, const std::vector<std::string>& assignments) {
  Sweep sweep;
  // Absolute: jobs may run from another directory (--resume, Slurm).
  std::vector<std::string> configs{fs::absolute(config_path).lexically_normal().string()};
  std::vector<std::string> fixed;
  std::vector<AxisGroup> groups;
  if (is_sweep_file(config_path)) {
    ConfigNode root = load_config_file(config_path);
    for (const auto& entry : root.entries()) {
      if (entry.key != "sweep") {
        throw ConfigError(entry.value.where(), entry.key,
                          "a sweep file holds only a `sweep:` section");
      }
    }
    ConfigNode& section = *root.find("sweep");
    ConfigReader reader(section, "sweep");
    SweepSection read;
    read.describe(reader);
    reader.declare("axes");
    reader.declare("zip");
    SlurmSection slurm;
    if (ConfigNode* node = section.find("slurm")) {
      ConfigReader::read(*node, "sweep.slurm", slurm);
      check_slurm_values(*node, slurm.resources);
    }
    reader.declare("slurm");
    reader.finish();
    const fs::path base = fs::path(config_path).parent_path();
    configs.clear();
    for (const auto& config : read.configs) {
      configs.push_back(fs::absolute(base / config).lexically_normal().string());
    }
    if (configs.empty()) {
      throw ConfigError(section.find("configs")->where(), "sweep.configs", "no config to run");
    }
    fixed = read.overrides;
    if (const ConfigNode* overrides = section.find("overrides")) {
      std::size_t i = 0;
      for (const auto& item : overrides->items()) {
        const std::string& text = read.overrides.at(i++);
        sweep.file_places.overrides.push_back(
            {text.substr(0, text.find('=')), item.where(), "sweep.overrides"});
      }
    }
    if (const std::string problem = sweep_name_problem(read.name); !problem.empty()) {
      throw ConfigError(section.find("name")->where(), "sweep.name", problem);
    }
    sweep.name = read.name;
    sweep.slurm = slurm.resources;
    if (const ConfigNode* axes = section.find("axes")) {
      for (auto& axis : read_axes(*axes, "sweep.axes")) {
        sweep.file_places.axes.push_back({axis.key, axis.where, "sweep.axes." + axis.key});
        groups.push_back({std::move(axis)});
        check_job_count(configs.size(), groups);
      }
    }
    if (const ConfigNode* zip = section.find("zip")) {
      AxisGroup group = read_axes(*zip, "sweep.zip");
      for (const auto& axis : group)
        sweep.file_places.axes.push_back({axis.key, axis.where, "sweep.zip." + axis.key});
      if (!group.empty()) groups.push_back(std::move(group));
      check_job_count(configs.size(), groups);
    }
  } else {
    sweep.name = fs::path(config_path).stem().string();
    if (const std::string problem = sweep_name_problem(sweep.name); !problem.empty()) {
      throw ConfigError(SourceLocation{config_path, 0, 0}, "",
                        "the file's name names the sweep, but " + problem +
                            ": rename the file, or run it from a sweep file with a name");
    }
  }
  const std::size_t file_fixed = fixed.size();
  for (const auto& assignment : assignments) {
    if (is_sweep_assignment(assignment)) {
      groups.push_back({parse_axis_assignment(assignment)});
      check_job_count(configs.size(), groups);
    } else {
      check_fixed_assignment(assignment);
      fixed.push_back(assignment);
    }
  }
  for (std::size_t i = 0; i < fixed.size(); ++i) {
    if (i < file_fixed) {
      const SweepKeyOrigin& origin = sweep.file_places.overrides.at(i);
      check_no_axis_replaces(fixed[i], origin.where, origin.path, groups);
    } else {
      check_no_axis_replaces(fixed[i], override_location(fixed[i]), "", groups);
    }
  }
  sweep.jobs = expand_jobs(configs, fixed, groups);
  sweep.id = new_sweep_id(sweep.name);
  return sweep;
}

}  // namespace corrmp
