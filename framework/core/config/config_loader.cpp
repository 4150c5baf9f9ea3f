// Config loading with includes and overrides. docs/architecture.md, "Configs".
#include "core/config/config_loader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "core/config/config_file.hpp"
#include "core/config/config_limits.hpp"
#include "core/config/config_text.hpp"

namespace corrmp {

namespace fs = std::filesystem;

namespace {

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream stream(text);
  std::string part;
  while (std::getline(stream, part, separator)) parts.push_back(part);
  // getline drops a trailing empty part ("a.b." -> a, b); keep it so that it
  // is reported as an empty key.
  if (!text.empty() && text.back() == separator) parts.emplace_back();
  return parts;
}

// A file on the include chain: how it was named and what it resolves to.
struct OpenFile {
  fs::path canonical;
  std::string shown;
};

// The file a path names, for recognising include cycles.
fs::path canonical_path(const fs::path& path) {
  std::error_code error;
  fs::path canonical = fs::weakly_canonical(path, error);
  if (error) canonical = fs::absolute(path, error).lexically_normal();
  return canonical;
}

std::string chain_text(const std::vector<OpenFile>& stack, const std::string& last) {
  std::string text;
  for (const auto& file : stack) text += file.shown + " -> ";
  return text + last;
}

ConfigNode load_with_includes(const fs::path& path, const SourceLocation* included_from,
                              std::vector<OpenFile>& stack, ConfigBudget& budget) {
  const std::string shown = path.string();
  const std::string text = read_config_file(shown, included_from);
  if (text.size() > budget.bytes_left) {
    const SourceLocation where =
        included_from != nullptr ? *included_from : SourceLocation{shown, 0, 0};
    throw ConfigError(where, included_from != nullptr ? "include" : "",
                      fmt::format("the config and its included files are larger than {} in total",
                                  describe_bytes(kMaxConfigTotalBytes)));
  }
  budget.bytes_left -= text.size();

  ConfigNode document = ConfigNode::parse(text, shown, budget);
  if (document.is_null()) document = ConfigNode::map(SourceLocation{shown, 1, 1});
  if (!document.is_map()) {
    throw ConfigError(document.where(), "", "a config file must be a YAML map");
  }
  const ConfigNode* includes = document.find("include");
  if (includes == nullptr) return document;

  std::vector<const ConfigNode*> names;
  if (includes->is_scalar()) {
    names.push_back(includes);
  } else if (includes->is_sequence()) {
    for (const auto& item : includes->items()) {
      if (!item.is_scalar()) throw ConfigError(item.where(), "include", "expected a file name");
      names.push_back(&item);
    }
  } else {
    throw ConfigError(includes->where(), "include", "expected a file name or a list of them");
  }

  stack.push_back(OpenFile{canonical_path(path), shown});
  ConfigNode merged = ConfigNode::map(document.where());
  for (const ConfigNode* name : names) {
    if (name->text().empty()) throw ConfigError(name->where(), "include", "empty file name");
    const fs::path included = (path.parent_path() / name->text()).lexically_normal();
    const fs::path canonical = canonical_path(included);
    const bool cycle = std::any_of(stack.begin(), stack.end(), [&](const OpenFile& file) {
      return file.canonical == canonical;
    });
    if (cycle) {
      throw ConfigError(name->where(), "include",
                        "include cycle: " + chain_text(stack, included.string()));
    }
    if (static_cast<int>(stack.size()) >= kMaxIncludeDepth) {
      throw ConfigError(name->where(), "include",
                        fmt::format("includes nested more than {} deep: {}", kMaxIncludeDepth,
                                    chain_text(stack, included.string())));
    }
    merged.merge_from(load_with_includes(included, &name->where(), stack, budget));
  }
  stack.pop_back();
  document.erase("include");
  merged.merge_from(document);
  return merged;
}

// How an override is named in messages: in full unless it is very long.
std::string shown_override(const std::string& assignment) {
  constexpr std::size_t kShown = 200;
  if (assignment.size() <= kShown) return assignment;
  return assignment.substr(0, kShown) + "...";
}

// A list index: decimal digits within the list's size.
std::size_t list_index(const ConfigNode& list, const std::string& key, const SourceLocation& where,
                       const std::string& path) {
  const std::size_t size = list.items().size();
  if (!std::all_of(key.begin(), key.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    throw ConfigError(where, path,
                      fmt::format("'{}' is not a list index: the list has {} element{}", key, size,
                                  size == 1 ? "" : "s"));
  }
  // Digits beyond what a list can hold are out of range, whatever their value.
  std::size_t index = 0;
  for (const char digit : key) {
    index = index * 10 + static_cast<std::size_t>(digit - '0');
    if (index >= size) break;
  }
  if (index >= size) {
    throw ConfigError(where, path,
                      fmt::format("list index {} is out of range: the list has {} element{}", key,
                                  size, size == 1 ? "" : "s"));
  }
  return index;
}

std::size_t count_nodes(const ConfigNode& node) {
  std::size_t count = 1;
  for (const auto& item : node.items()) count += count_nodes(item);
  for (const auto& entry : node.entries()) count += count_nodes(entry.value);
  return count;
}

void apply_override(ConfigNode& root, const std::string& assignment, ConfigBudget& budget) {
  const SourceLocation where = override_location(assignment);
  if (assignment.size() > kMaxConfigFileBytes) {
    throw ConfigError(
        where, "",
        "larger than " + describe_bytes(kMaxConfigFileBytes) + ", the limit for an override");
  }
  if (const auto problem = find_text_problem(assignment)) {
    throw ConfigError(where, "",
                      fmt::format("column {}: {}", problem->offset + 1, problem->message));
  }
  const auto equals = assignment.find('=');
  if (equals == std::string::npos || equals == 0) {
    throw ConfigError(where, "", "expected key.path=value");
  }
  const std::string key_path = assignment.substr(0, equals);
  const std::vector<std::string> keys = split(key_path, '.');
  if (static_cast<int>(keys.size()) >= kMaxConfigDepth) {
    throw ConfigError(where, "",
                      fmt::format("key path nested more than {} levels deep", kMaxConfigDepth));
  }
  ConfigNode value = ConfigNode::parse(assignment.substr(equals + 1), where.file, budget,
                                       static_cast<int>(keys.size()));
  value.set_where(where);
  if (keys.size() > budget.nodes_left) {
    throw ConfigError(where, "",
                      fmt::format("the config holds more than {} values", kMaxConfigNodes));
  }
  budget.nodes_left -= keys.size();

  ConfigNode* node = &root;
  std::string path;
  for (size_t i = 0; i < keys.size(); ++i) {
    const std::string& key = keys[i];
    path += (path.empty() ? "" : ".") + key;
    const bool last = i + 1 == keys.size();
    if (key.empty()) throw ConfigError(where, key_path, "empty key in path");
    if (node->is_sequence()) {
      auto it =
          std::next(node->items().begin(), static_cast<long>(list_index(*node, key, where, path)));
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

}  // namespace

ConfigNode load_config_file(const std::string& path) {
  ConfigBudget budget;
  std::vector<OpenFile> stack;
  return load_with_includes(fs::path(path), nullptr, stack, budget);
}

SourceLocation override_location(const std::string& assignment) {
  return {"command-line override '" + shown_override(assignment) + "'", 0, 0};
}

void apply_override(ConfigNode& root, const std::string& assignment) {
  ConfigBudget budget;
  budget.nodes_left -= std::min(budget.nodes_left, count_nodes(root));
  apply_override(root, assignment, budget);
}

ConfigNode load_config(const std::string& path, const std::vector<std::string>& overrides) {
  ConfigBudget budget;
  std::vector<OpenFile> stack;
  ConfigNode root = load_with_includes(fs::path(path), nullptr, stack, budget);
  for (const auto& assignment : overrides) apply_override(root, assignment, budget);
  return root;
}

}  // namespace corrmp
