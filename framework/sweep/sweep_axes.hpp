// Sweep axes: the values a multirun gives one config key, written on the
// command line (`run_experiment CONFIG -m key=a,b,c seed=range(0,5)`) or in a
// sweep file, and the cross product of the axes into jobs. docs/sweeps.md.
#pragma once

#include <string>
#include <vector>

#include "core/config/config_error.hpp"
#include "sweep/sweep.hpp"

namespace corrmp {

struct SweepAxis {
  std::string key;
  std::vector<std::string> values;
  SourceLocation where;
};

// Axes that advance together (a sweep file's `zip:`); a single axis otherwise.
using AxisGroup = std::vector<SweepAxis>;

// Whether a command-line assignment sweeps: its value is range(...), choice(...)
// or holds a comma outside brackets and quotes.
bool is_sweep_assignment(const std::string& assignment);

// The values of `text`: `range(stop)`, `range(start, stop[, step])` (64-bit
// integers, stop excluded), `choice(a, b, ...)`, `a,b,c`, or a single value.
// Throws ConfigError (naming `where` and `key`) for an empty axis, a malformed or
// empty range, a zero step, a range stepping beyond the 64-bit integers or past
// 100000 values, an empty value or an unmatched quote.
std::vector<std::string> parse_axis_values(const std::string& text, const SourceLocation& where,
                                           const std::string& key);

// A sweep's fixed command-line assignment: throws ConfigError for an unmatched quote
// in its value, which an axis's syntax would read otherwise (`it's,b`).
void check_fixed_assignment(const std::string& assignment);

// Throws ConfigError when `configs` crossed with `groups` make more than 100000 jobs;
// checked as each group is read, so that no more values are made than a sweep can run.
void check_job_count(std::size_t configs, const std::vector<AxisGroup>& groups);

// `key=values` from the command line, as one axis.
SweepAxis parse_axis_assignment(const std::string& assignment);

// The jobs: every base config crossed with every combination of the groups
// (the first group varies slowest), each job's overrides being `fixed` then
// one `key=value` per axis. Throws ConfigError when a zipped group's axes
// differ in length or a key is swept twice.
std::vector<SweepJob> expand_jobs(const std::vector<std::string>& configs,
                                  const std::vector<std::string>& fixed,
                                  const std::vector<AxisGroup>& groups);

}  // namespace corrmp
