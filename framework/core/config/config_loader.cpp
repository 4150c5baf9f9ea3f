// Config loading with includes and overrides. docs/architecture.md, "Configs".
#include "core/config/config_loader.hpp"

#include <algorithm>
#include <filesystem>
#include <sstream>

namespace corrmp {

namespace fs = std::filesystem;

namespace {

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream stream(text);
  std::string part;
  while (std::getline(stream, part, separator)) parts.push_back(part);
  return parts;
}

ConfigNode load_with_includes(const fs::path& path, std::vector<fs::path>& stack) {
  const fs::path canonical = fs::weakly_canonical(path);
  if (std::find(stack.begin(), stack.end(), canonical) != stack.end()) {
    throw ConfigError(SourceLocation{path.string(), 0, 0}, "include", "include cycle");
  }
  ConfigNode document = ConfigNode::load_file(path.string());
  if (document.is_null()) document = ConfigNode::map(SourceLocation{path.string(), 1, 1});
  if (!document.is_map()) {
    throw ConfigError(document.where(), "", "a config file must be a YAML map");
  }
  const ConfigNode* includes = document.find("include");
  if (includes == nullptr) return document;

  std::vector<std::string> files;
  if (includes->is_scalar()) {
    files.push_back(includes->text());
  } else if (includes->is_sequence()) {
    for (const auto& item : includes->items()) {
      if (!item.is_scalar()) throw ConfigError(item.where(), "include", "expected a file name");
      files.push_back(item.text());
    }
  } else {
    throw ConfigError(includes->where(), "include", "expected a file name or a list of them");
  }

  stack.push_back(canonical);
  ConfigNode merged = ConfigNode::map(document.where());
  for (const auto& file : files) {
    const fs::path included = path.parent_path() / file;
    if (!fs::exists(included)) {
      throw ConfigError(includes->where(), "include",
                        "included file '" + included.string() + "' does not exist");
    }
    merged.merge_from(load_with_includes(included, stack));
  }
  stack.pop_back();
  document.erase("include");
  merged.merge_from(document);
  return merged;
}

}  // namespace

ConfigNode load_config_file(const std::string& path) {
  std::vector<fs::path> stack;
  return load_with_includes(fs::path(path), stack);
}

void apply_override(ConfigNode& root, const std::string& assignment) {
  const SourceLocation where{"command-line override '" + assignment + "'", 0, 0};
  const auto equals = assignment.find('=');
  if (equals == std::string::npos || equals == 0) {
    throw ConfigError(where, "", "expected key.path=value");
  }
  const std::string key_path = assignment.substr(0, equals);
  const std::vector<std::string> keys = split(key_path, '.');
  ConfigNode value = ConfigNode::parse(assignment.substr(equals + 1), where.file);
  value.set_where(where);

  ConfigNode* node = &root;
  std::string path;
  for (size_t i = 0; i < keys.size(); ++i) {
    const std::string& key = keys[i];
    path += (path.empty() ? "" : ".") + key;
    const bool last = i + 1 == keys.size();
    if (key.empty()) throw ConfigError(where, key_path, "empty key in path");
    if (node->is_sequence()) {
      const bool numeric = std::all_of(key.begin(), key.end(), ::isdigit);
      const size_t index = numeric ? std::stoul(key) : node->items().size();
      if (index >= node->items().size()) {
        throw ConfigError(where, path, "no such list element to override");
      }
      auto it = std::next(node->items().begin(), static_cast<long>(index));
      if (last) {
        *it = std::move(value);
        return;
      }
      node = &*it;
      continue;
    }
    if (!node->is_map()) {
      throw ConfigError(where, path,
                        "cannot override inside " + std::string(kind_name(node->kind())));
    }
    ConfigNode* child = node->find(key);
    if (last) {
      node->set(key, std::move(value), where);
      return;
    }
    // A missing section is created: the strict typed reader rejects it, naming
    // this override, unless the schema declares it (with defaults).
    node = child != nullptr ? child : &node->set(key, ConfigNode::map(where), where);
  }
}

ConfigNode load_config(const std::string& path, const std::vector<std::string>& overrides) {
  ConfigNode root = load_config_file(path);
  for (const auto& assignment : overrides) apply_override(root, assignment);
  return root;
}

}  // namespace corrmp
