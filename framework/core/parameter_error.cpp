// Resolving a component's relative key path to its config node (parameter_error.hpp).
#include "core/parameter_error.hpp"

#include <cctype>
#include <iterator>

namespace corrmp {

bool is_safe_file_name(const std::string& name) {
  if (name.empty() || name[0] == '.' || name.size() > 128) return false;
  for (char c : name) {
    const bool allowed =
        std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
    if (!allowed) return false;
  }
  return true;
}

void check_file_name(const std::string& key, const std::string& name) {
  if (is_safe_file_name(name)) return;
  throw ParameterError(key, "'" + name +
                                "' is not a valid name (it names files): use up to 128 letters, "
                                "digits, '_', '-', '.', not starting with '.'");
}

const ConfigNode& node_at(const ConfigNode& section, const std::string& key) {
  const ConfigNode* node = &section;
  size_t i = 0;
  while (i < key.size()) {
    if (key[i] == '.') {
      ++i;
      continue;
    }
    if (key[i] == '[') {
      const size_t close = key.find(']', i);
      if (close == std::string::npos || !node->is_sequence()) return *node;
      size_t index = 0;
      for (size_t c = i + 1; c < close; ++c) {
        if (!std::isdigit(static_cast<unsigned char>(key[c]))) return *node;
        index = index * 10 + static_cast<size_t>(key[c] - '0');
        if (index >= node->items().size()) return *node;
      }
      node = &*std::next(node->items().begin(), static_cast<long>(index));
      i = close + 1;
      continue;
    }
    const size_t end = key.find_first_of(".[", i);
    const std::string name = key.substr(i, end == std::string::npos ? std::string::npos : end - i);
    const ConfigNode* child = node->is_map() ? node->find(name) : nullptr;
    if (child == nullptr) return *node;
    node = child;
    i = end == std::string::npos ? key.size() : end;
  }
  return *node;
}

SourceLocation stated_location(const ConfigNode& section, const std::string& key,
                               const SourceLocation& otherwise) {
  const SourceLocation& where = node_at(section, key).where();
  return where.file == "<default>" ? otherwise : where;
}

}  // namespace corrmp
