// Sweep axes and their cross product (sweep_axes.hpp).
#include "sweep/sweep_axes.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstdlib>
#include <limits>
#include <set>

#include "core/config/config_loader.hpp"

namespace corrmp {

namespace {

constexpr int64_t kMaxAxisValues = 100000;

std::string trim(const std::string& text) {
  const auto begin = text.find_first_not_of(" \t");
  if (begin == std::string::npos) return "";
  return text.substr(begin, text.find_last_not_of(" \t") - begin + 1);
}

// The parts of a value split at commas outside brackets, parentheses and quotes, and the quote
// left open at its end (0 when none): a quote that never closes would swallow the commas after
// it, so the callers refuse it rather than guess.
struct TopLevelParts {
  std::vector<std::string> parts;
  char open_quote = 0;
};

TopLevelParts split_top_level(const std::string& text) {
  TopLevelParts split;
  std::string current;
  int depth = 0;
  char quote = 0;
  bool escaped = false;
  for (const char c : text) {
    if (quote != 0) {
      if (escaped) {
        escaped = false;
      } else if (quote == '"' && c == '\\') {
        escaped = true;  // YAML's \" inside double quotes
      } else if (c == quote) {
        quote = 0;
      }
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '[' || c == '(' || c == '{') {
      ++depth;
    } else if (c == ']' || c == ')' || c == '}') {
      --depth;
    } else if (c == ',' && depth == 0) {
      split.parts.push_back(trim(current));
      current.clear();
      continue;
    }
    current += c;
  }
  split.parts.push_back(trim(current));
  split.open_quote = quote;
  return split;
}

void check_quotes_closed(const TopLevelParts& split, const std::string& value,
                         const SourceLocation& where, const std::string& key) {
  if (split.open_quote == 0) return;
  throw ConfigError(where, key,
                    fmt::format("unmatched {} in \"{}\" (in a sweep, quotes hold a value "
                                "together: write a quote inside quotes of the other kind, "
                                "e.g. \"it's\")",
                                split.open_quote, value));
}

// The argument list of `name(...)`, or false when `text` is not such a call.
bool call_arguments(const std::string& text, const std::string& name,
                    std::vector<std::string>& arguments) {
  if (text.size() < name.size() + 2 || text.compare(0, name.size() + 1, name + "(") != 0 ||
      text.back() != ')') {
    return false;
  }
  const std::string inside = text.substr(name.size() + 1, text.size() - name.size() - 2);
  arguments = trim(inside).empty() ? std::vector<std::string>{} : split_top_level(inside).parts;
  return true;
}

int64_t parse_integer(const std::string& text, const SourceLocation& where,
                      const std::string& key) {
  errno = 0;
  char* end = nullptr;
  const long long value = std::strtoll(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || errno == ERANGE) {
    throw ConfigError(where, key, fmt::format("range(): '{}' is not an integer", text));
  }
  return value;
}

std::vector<std::string> range_values(const std::vector<std::string>& arguments,
                                      const SourceLocation& where, const std::string& key) {
  if (arguments.empty() || arguments.size() > 3) {
    throw ConfigError(where, key, "range() takes (stop), (start, stop) or (start, stop, step)");
  }
  std::vector<int64_t> n;
  for (const auto& argument : arguments) n.push_back(parse_integer(argument, where, key));
  const int64_t start = n.size() == 1 ? 0 : n[0];
  const int64_t stop = n.size() == 1 ? n[0] : n[1];
  const int64_t step = n.size() == 3 ? n[2] : 1;
  if (step == 0) throw ConfigError(where, key, "range(): the step must not be 0");
  // Counted in unsigned 64-bit arithmetic, where the distance between any two 64-bit
  // integers fits; the walk's end is computed with overflow checks.
  const bool up = step > 0;
  if (up ? stop <= start : stop >= start) {
    throw ConfigError(where, key, fmt::format("range({}, {}, {}) is empty", start, stop, step));
  }
  const uint64_t distance = up ? static_cast<uint64_t>(stop) - static_cast<uint64_t>(start)
                               : static_cast<uint64_t>(start) - static_cast<uint64_t>(stop);
  const uint64_t stride = up ? static_cast<uint64_t>(step) : 0 - static_cast<uint64_t>(step);
  const uint64_t count = distance / stride + (distance % stride != 0 ? 1 : 0);
  if (count > static_cast<uint64_t>(kMaxAxisValues)) {
    throw ConfigError(where, key, fmt::format("range(): more than {} values", kMaxAxisValues));
  }
  // The step after the last value must be a 64-bit integer too, so that the range is a walk
  // any 64-bit program can take: its distance from start is at most the room left that way.
  const uint64_t room =
      up ? static_cast<uint64_t>(std::numeric_limits<int64_t>::max()) - static_cast<uint64_t>(start)
         : static_cast<uint64_t>(start) -
               static_cast<uint64_t>(std::numeric_limits<int64_t>::min());
  uint64_t walked = 0;
  if (__builtin_mul_overflow(count, stride, &walked) || walked > room) {
    throw ConfigError(
        where, key,
        fmt::format("range({}, {}, {}) steps beyond the 64-bit integers", start, stop, step));
  }
  const auto after_last = static_cast<int64_t>(up ? static_cast<uint64_t>(start) + walked
                                                  : static_cast<uint64_t>(start) - walked);
  std::vector<std::string> values;
  values.reserve(count);
  for (int64_t v = start; v != after_last; v += step) values.push_back(std::to_string(v));
  return values;
}

// The next combination, the last group varying fastest; false after the last.
bool advance(std::vector<size_t>& position, const std::vector<AxisGroup>& groups) {
  for (size_t g = groups.size(); g-- > 0;) {
    if (++position[g] < groups[g].front().values.size()) return true;
    position[g] = 0;
  }
  return false;
}

}  // namespace

bool is_sweep_assignment(const std::string& assignment) {
  const auto equals = assignment.find('=');
  if (equals == std::string::npos) return false;
  const std::string value = trim(assignment.substr(equals + 1));
  std::vector<std::string> ignored;
  return call_arguments(value, "range", ignored) || call_arguments(value, "choice", ignored) ||
         split_top_level(value).parts.size() > 1;
}

std::vector<std::string> parse_axis_values(const std::string& text, const SourceLocation& where,
                                           const std::string& key) {
  const std::string value = trim(text);
  std::vector<std::string> arguments;
  std::vector<std::string> values;
  const TopLevelParts split = split_top_level(value);
  check_quotes_closed(split, value, where, key);
  if (call_arguments(value, "range", arguments)) return range_values(arguments, where, key);
  if (call_arguments(value, "choice", arguments)) {
    if (arguments.empty()) throw ConfigError(where, key, "choice() needs at least one value");
    values = arguments;
  } else {
    values = split.parts;
  }
  for (const auto& v : values) {
    if (v.empty()) throw ConfigError(where, key, fmt::format("empty value in '{}'", value));
  }
  return values;
}

void check_fixed_assignment(const std::string& assignment) {
  const auto equals = assignment.find('=');
  if (equals == std::string::npos) return;  // the config loader names what is wrong
  const std::string value = trim(assignment.substr(equals + 1));
  check_quotes_closed(split_top_level(value), value, override_location(assignment),
                      trim(assignment.substr(0, equals)));
}

void check_job_count(std::size_t configs, const std::vector<AxisGroup>& groups) {
  int64_t total = static_cast<int64_t>(configs);
  for (const auto& group : groups) {
    total *= static_cast<int64_t>(group.empty() ? 1 : group.front().values.size());
    if (total > kMaxAxisValues) {
      throw ConfigError(fmt::format("the sweep has more than {} jobs", kMaxAxisValues));
    }
  }
}

SweepAxis parse_axis_assignment(const std::string& assignment) {
  const SourceLocation where{"command-line sweep '" + assignment + "'", 0, 0};
  const auto equals = assignment.find('=');
  if (equals == std::string::npos || equals == 0) {
    throw ConfigError(where, "", "expected key.path=values");
  }
  SweepAxis axis;
  axis.key = trim(assignment.substr(0, equals));
  axis.where = where;
  axis.values = parse_axis_values(assignment.substr(equals + 1), where, axis.key);
  return axis;
}

std::vector<SweepJob> expand_jobs(const std::vector<std::string>& configs,
                                  const std::vector<std::string>& fixed,
                                  const std::vector<AxisGroup>& groups) {
  std::set<std::string> keys;
  for (const auto& group : groups) {
    for (const auto& axis : group) {
      if (axis.values.empty()) throw ConfigError(axis.where, axis.key, "the axis has no values");
      if (axis.values.size() != group.front().values.size()) {
        throw ConfigError(axis.where, axis.key,
                          fmt::format("zipped axes differ in length: {} has {} values, {} has {}",
                                      group.front().key, group.front().values.size(), axis.key,
                                      axis.values.size()));
      }
      if (!keys.insert(axis.key).second) {
        throw ConfigError(axis.where, axis.key, "swept twice");
      }
    }
  }
  check_job_count(configs.size(), groups);
  std::vector<SweepJob> jobs;
  for (const auto& config : configs) {
    std::vector<size_t> position(groups.size(), 0);
    do {
      SweepJob job;
      job.index = static_cast<int>(jobs.size());
      job.config_path = config;
      job.overrides = fixed;
      for (size_t g = 0; g < groups.size(); ++g) {
        for (const auto& axis : groups[g]) {
          job.overrides.push_back(axis.key + "=" + axis.values[position[g]]);
          job.axes.emplace_back(axis.key, axis.values[position[g]]);
        }
      }
      jobs.push_back(std::move(job));
    } while (advance(position, groups));
  }
  return jobs;
}

}  // namespace corrmp
