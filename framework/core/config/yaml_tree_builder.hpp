// Builds a ConfigNode tree from YAML text through yaml-cpp's event parser,
// enforcing what yaml-cpp's own tree does not: one document per text, map keys
// that are scalars and unique (errors name the full key path), no merge keys,
// no alias that contains itself, and the bounds of config_limits.hpp (nesting
// depth, and values counted with every alias expanded), each checked before the
// tree is built so that an alias bomb fails fast. docs/architecture.md, "Configs".
#pragma once

#include <string>

#include "core/config/config_limits.hpp"
#include "core/config/config_node.hpp"

namespace corrmp {

// Parses `text` (already checked by find_text_problem); `file` names it in
// locations. `base_depth` is the nesting level the text's root is placed under
// (0 for a file; the number of keys for an override's value). Each value built
// is taken from `budget`. Null for an empty text.
ConfigNode build_yaml_tree(const std::string& text, const std::string& file, ConfigBudget& budget,
                           int base_depth);

}  // namespace corrmp
