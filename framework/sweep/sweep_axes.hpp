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

// The values of `text`: `range(stop)`, `range(start, stop[, step])` (integers,
// stop excluded), `choice(a, b, ...)`, `a,b,c`, or a single value. Throws
// ConfigError (naming `where` and `key`) for an empty axis, a malformed or
// empty range, a zero step or an empty value.
std::vector<std::string> parse_axis_values(const std::string& text, const SourceLocation& where,
                                           const std::string& key);

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
