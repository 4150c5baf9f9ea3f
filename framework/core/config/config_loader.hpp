// Loading a config: YAML file -> `include:` files deep-merged underneath it ->
// command-line overrides `key.path=value` on top. docs/architecture.md, "Configs".
#pragma once

#include <string>
#include <vector>

#include "core/config/config_node.hpp"

namespace corrmp {

// Loads `path` and the files its top-level `include:` list names (relative to
// the including file, merged in order, the including file last: maps are
// deep-merged, scalars and lists replaced). The `include` key is removed.
// Every file must be a regular file holding one UTF-8 YAML document, within
// the bounds of config_limits.hpp; an include cycle is an error naming the
// chain of files.
ConfigNode load_config_file(const std::string& path);

// Applies one `key.path=value` override; the value is YAML (a scalar or a flow
// list such as [1, 2]). Keys that are not in the file are added, and the strict
// typed reader then rejects any the schema does not declare, naming the override.
// Sequence elements are addressed by index (segments.1.context=...).
void apply_override(ConfigNode& root, const std::string& assignment);
// The place apply_override gives the values of `assignment` ("command-line override
// 'key=value'"): errors about them name its file, whatever their line.
SourceLocation override_location(const std::string& assignment);

// load_config_file followed by each override in order.
ConfigNode load_config(const std::string& path, const std::vector<std::string>& overrides);

}  // namespace corrmp
