// Strict typed reading of one config map into a struct. A struct declares its
// fields in a `describe` member, visited field by field (Drake-style):
//
//   struct CnmpParams {
//     int width = 128;
//     template <class Fields> void describe(Fields& f) {
//       f("width", width, "hidden layer width", at_least(1));
//     }
//   };
//
// ConfigReader fills the struct from a ConfigNode and writes every default it
// used back into the node, so the resolved config shows every value in force.
// Unknown keys (with a did-you-mean), missing required keys, wrong types and
// out-of-range values throw ConfigError naming file:line:column and the dotted
// key path. docs/architecture.md, "Configs".
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "core/config/config_error.hpp"
#include "core/config/config_node.hpp"
#include "core/config/field_rule.hpp"
#include "core/config/scalar_codec.hpp"

namespace corrmp {

// A component section: `type:` names a registry entry, the other keys are that
// entry's parameters, read later by the registry. `node` points into the config
// tree owned by the caller (LoadedConfig), which outlives the spec.
struct ComponentSpec {
  std::string type;
  std::string path;
  ConfigNode* node = nullptr;
};

template <class T, class = void>
struct has_describe : std::false_type {};

template <class T>
struct is_optional : std::false_type {};
template <class T>
struct is_optional<std::optional<T>> : std::true_type {};

class ConfigReader;
template <class T>
struct has_describe<
    T, std::void_t<decltype(std::declval<T&>().describe(std::declval<ConfigReader&>()))>>
    : std::true_type {};

class ConfigReader {
 public:
  // `map` must be a map or null (treated as an empty map); `path` is its dotted
  // key path from the document root ("" for the root).
  ConfigReader(ConfigNode& map, std::string path);

  // Reads one declared field. Absent and not required: keeps the default and
  // writes it into the node (a std::optional field stays empty instead).
  template <class T>
  void operator()(const std::string& key, T& value, const std::string& description,
                  const FieldRule& rule = {}) {
    (void)description;
    declared_.push_back(key);
    const std::string path = child_path(key);
    ConfigNode* node = map_.find(key);
    if (node == nullptr) {
      if (rule.is_required) throw ConfigError(map_.where(), path, "missing required key");
      if constexpr (is_optional<T>::value) return;
      ConfigNode written = encode_value(value, path, rule);
      map_.set(key, std::move(written), SourceLocation{"<default>", 0, 0});
      return;
    }
    decode_value(*node, path, rule, value);
  }

  // Throws for any key in the map that no field declared.
  void finish() const;

  // Keys that a component section reads itself (such as `type`).
  void declare(const std::string& key) { declared_.push_back(key); }

  const std::string& path() const { return path_; }
  ConfigNode& node() { return map_; }

  // Reads a whole struct from `map`, checking for unknown keys.
  template <class T>
  static void read(ConfigNode& map, const std::string& path, T& value) {
    ConfigReader reader(map, path);
    value.describe(reader);
    reader.finish();
  }

 private:
  std::string child_path(const std::string& key) const {
    return path_.empty() ? key : path_ + "." + key;
  }

  static void decode_value(ConfigNode& node, const std::string& path, const FieldRule& rule,
                           bool& value);
  static void decode_value(ConfigNode& node, const std::string& path, const FieldRule& rule,
                           int& value);
  static void decode_value(ConfigNode& node, const std::string& path, const FieldRule& rule,
                           int64_t& value);
  static void decode_value(ConfigNode& node, const std::string& path, const FieldRule& rule,
                           uint64_t& value);
  static void decode_value(ConfigNode& node, const std::string& path, const FieldRule& rule,
                           double& value);
  static void decode_value(ConfigNode& node, const std::string& path, const FieldRule& rule,
                           std::string& value);
  static void decode_value(ConfigNode& node, const std::string& path, const FieldRule& rule,
                           ComponentSpec& value);

  template <class T>
  static void decode_value(ConfigNode& node, const std::string& path, const FieldRule& rule,
                           std::vector<T>& value) {
    if (!node.is_sequence()) {
      throw ConfigError(node.where(), path,
                        std::string("expected a list, got ") + kind_name(node.kind()));
    }
    if (rule.list_size >= 0 && static_cast<int>(node.items().size()) != rule.list_size) {
      throw ConfigError(node.where(), path,
                        "expected a list of " + std::to_string(rule.list_size) + " items, got " +
                            std::to_string(node.items().size()));
    }
    value.clear();
    int index = 0;
    for (auto& item : node.items()) {
      value.emplace_back();
      decode_value(item, path + "[" + std::to_string(index++) + "]", rule, value.back());
    }
  }

  // A map with any keys (such as labels): each value is read as a T under the field's rule.
  template <class T>
  static void decode_value(ConfigNode& node, const std::string& path, const FieldRule& rule,
                           std::map<std::string, T>& value) {
    if (node.is_null()) node = ConfigNode::map(node.where());
    if (!node.is_map()) {
      throw ConfigError(node.where(), path,
                        std::string("expected a map, got ") + kind_name(node.kind()));
    }
    value.clear();
    for (auto& entry : node.entries()) {
      decode_value(entry.value, path + "." + entry.key, rule, value[entry.key]);
    }
  }

  template <class T>
  static void decode_value(ConfigNode& node, const std::string& path, const FieldRule& rule,
                           std::optional<T>& value) {
    value.emplace();
    decode_value(node, path, rule, *value);
  }

  template <class T, std::enable_if_t<has_describe<T>::value, int> = 0>
  static void decode_value(ConfigNode& node, const std::string& path, const FieldRule&, T& value) {
    if (node.is_null()) node = ConfigNode::map(node.where());
    if (!node.is_map()) {
      throw ConfigError(node.where(), path,
                        std::string("expected a map, got ") + kind_name(node.kind()));
    }
    read(node, path, value);
  }

  static ConfigNode encode_value(bool value, const std::string&, const FieldRule&);
  static ConfigNode encode_value(int value, const std::string&, const FieldRule&);
  static ConfigNode encode_value(int64_t value, const std::string&, const FieldRule&);
  static ConfigNode encode_value(uint64_t value, const std::string&, const FieldRule&);
  static ConfigNode encode_value(double value, const std::string&, const FieldRule&);
  static ConfigNode encode_value(const std::string& value, const std::string&, const FieldRule&);
  static ConfigNode encode_value(const ComponentSpec& value, const std::string& path,
                                 const FieldRule&);

  template <class T>
  static ConfigNode encode_value(const std::vector<T>& value, const std::string& path,
                                 const FieldRule& rule) {
    ConfigNode out = ConfigNode::sequence(SourceLocation{"<default>", 0, 0});
    for (const auto& item : value) out.items().push_back(encode_value(item, path, rule));
    return out;
  }

  template <class T>
  static ConfigNode encode_value(const std::map<std::string, T>& value, const std::string& path,
                                 const FieldRule& rule) {
    ConfigNode out = ConfigNode::map(SourceLocation{"<default>", 0, 0});
    for (const auto& [key, item] : value) {
      out.set(key, encode_value(item, path + "." + key, rule), SourceLocation{"<default>", 0, 0});
    }
    return out;
  }

  template <class T>
  static ConfigNode encode_value(const std::optional<T>& value, const std::string& path,
                                 const FieldRule& rule) {
    return encode_value(*value, path, rule);
  }

  // Writes the current value of each field of a struct (a default list element).
  struct FieldEncoder {
    ConfigNode& map;
    std::string path;
    template <class T>
    void operator()(const std::string& key, T& value, const std::string&,
                    const FieldRule& rule = {}) {
      if constexpr (is_optional<T>::value) {
        if (!value) return;
      }
      map.set(key, encode_value(value, path + "." + key, rule), SourceLocation{"<default>", 0, 0});
    }
  };

  template <class T, std::enable_if_t<has_describe<T>::value, int> = 0>
  static ConfigNode encode_value(const T& value, const std::string& path, const FieldRule&) {
    ConfigNode out = ConfigNode::map(SourceLocation{"<default>", 0, 0});
    FieldEncoder encoder{out, path};
    T copy = value;
    copy.describe(encoder);
    return out;
  }

  ConfigNode& map_;
  std::string path_;
  std::vector<std::string> declared_;
};

}  // namespace corrmp
