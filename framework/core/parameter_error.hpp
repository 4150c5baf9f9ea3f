// A component refusing one of its parameters: the key (relative to the component's section,
// "segments[1].name") and the reason. The registry turns it into a ConfigError at the file,
// line and full key path of that value (core/registry.hpp). docs/architecture.md, "Configs".
#pragma once

#include <stdexcept>
#include <string>

#include "core/config/config_node.hpp"

namespace corrmp {

class ParameterError : public std::invalid_argument {
 public:
  ParameterError(std::string key, const std::string& what)
      : std::invalid_argument(what), key_(std::move(key)) {}
  const std::string& key() const { return key_; }

 private:
  std::string key_;
};

// Names that become file or directory names (an experiment, a segment): letters, digits, '_',
// '-', '.', not starting with '.', so no name reaches outside the run directory.
bool is_safe_file_name(const std::string& name);
// Throws a ParameterError for `key` when `name` is not a safe file name.
void check_file_name(const std::string& key, const std::string& name);

// The node a relative key path ("a.b[2].c") names under `section`, or the deepest node on the
// way when the path goes further than the config (a default not written down).
const ConfigNode& node_at(const ConfigNode& section, const std::string& key);

// Where the value at `key` under `section` was written (a file line, an override), or
// `otherwise` when it is a default nobody wrote down.
SourceLocation stated_location(const ConfigNode& section, const std::string& key,
                               const SourceLocation& otherwise);

}  // namespace corrmp
