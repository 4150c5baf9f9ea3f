// A YAML document tree that remembers where every value came from (file, line,
// column), so that config errors can name them after includes and overrides
// have been merged. docs/architecture.md, "Configs".
#pragma once

#include <list>
#include <string>

#include "core/config/config_error.hpp"
#include "core/config/config_limits.hpp"

namespace corrmp {

struct MapEntry;

class ConfigNode {
 public:
  enum class Kind { Null, Scalar, Sequence, Map };

  ConfigNode() = default;
  static ConfigNode scalar(std::string text, SourceLocation where, bool quoted = false);
  static ConfigNode sequence(SourceLocation where);
  static ConfigNode map(SourceLocation where);

  // Parses YAML text (one document, UTF-8, within config_limits.hpp); `file`
  // names it in locations and errors. A null node for an empty text.
  static ConfigNode parse(const std::string& text, const std::string& file);
  // The same, taking its values from `budget`, whose text is placed
  // `base_depth` levels deep (an override's value, under its keys).
  static ConfigNode parse(const std::string& text, const std::string& file, ConfigBudget& budget,
                          int base_depth = 0);
  // Parses a regular file of at most kMaxConfigFileBytes.
  static ConfigNode load_file(const std::string& path);

  Kind kind() const { return kind_; }
  bool is_null() const { return kind_ == Kind::Null; }
  bool is_scalar() const { return kind_ == Kind::Scalar; }
  bool is_sequence() const { return kind_ == Kind::Sequence; }
  bool is_map() const { return kind_ == Kind::Map; }
  const SourceLocation& where() const { return where_; }
  void set_where(SourceLocation where) { where_ = std::move(where); }

  // Scalars. `quoted` is true for '...' or "..." scalars, which are always strings.
  const std::string& text() const { return text_; }
  bool quoted() const { return quoted_; }

  // Sequences. Elements keep their addresses when others are appended.
  std::list<ConfigNode>& items() { return items_; }
  const std::list<ConfigNode>& items() const { return items_; }

  // Maps, in document order. Entries keep their addresses when others are added.
  std::list<MapEntry>& entries() { return entries_; }
  const std::list<MapEntry>& entries() const { return entries_; }
  const ConfigNode* find(const std::string& key) const;
  ConfigNode* find(const std::string& key);
  // Sets `key` (replacing an existing value in place, keeping its position).
  ConfigNode& set(const std::string& key, ConfigNode value, SourceLocation key_where);
  bool erase(const std::string& key);

  // Deep merge: maps are merged key by key, anything else is replaced.
  void merge_from(const ConfigNode& overlay);

  // Block-style YAML text, or with `flow` everything on one line ({a: 1, b: [2]}).
  std::string to_yaml_string(bool flow = false) const;

 private:
  Kind kind_ = Kind::Null;
  SourceLocation where_;
  std::string text_;
  bool quoted_ = false;
  std::list<ConfigNode> items_;
  std::list<MapEntry> entries_;
};

struct MapEntry {
  std::string key;
  SourceLocation key_where;
  ConfigNode value;
};

const char* kind_name(ConfigNode::Kind kind);

}  // namespace corrmp
