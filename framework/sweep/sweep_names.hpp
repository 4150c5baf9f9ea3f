// A sweep's name and id become folder and file names (<out>/sweeps/<id>/, the runs' folders,
// the lock beside the database) and words of printed commands: both must be safe file names,
// wherever they come from (a sweep file, a config's file name, a manifest, a database, the
// command line). docs/sweeps.md.
#pragma once

#include <string>

namespace corrmp {

// The longest sweep name: its id adds 21 characters (-<UTC time>-<hex>) and stays a safe file
// name (core/parameter_error.hpp, up to 128).
constexpr std::size_t kMaxSweepNameLength = 100;

// Why `name` cannot name a sweep ("'a b' is not a valid sweep name (...)"); empty when it can.
std::string sweep_name_problem(const std::string& name);

// Why `id` cannot be a sweep's id; empty when it can.
std::string sweep_id_problem(const std::string& id);

}  // namespace corrmp
