// Strict typed config reading: scalar decoding, range checks, unknown keys.
// docs/architecture.md, "Configs".
#include "core/config/config_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "core/config/did_you_mean.hpp"

namespace corrmp {

namespace {

const SourceLocation kDefault{"<default>", 0, 0};

const std::string& scalar_text(const ConfigNode& node, const std::string& path,
                               const char* expected) {
  if (!node.is_scalar()) {
    throw ConfigError(node.where(), path,
                      fmt::format("expected {}, got {}", expected, kind_name(node.kind())));
  }
  return node.text();
}

template <class T>
void check_range(const ConfigNode& node, const std::string& path, const FieldRule& rule, T value) {
  if (!rule.accepts(static_cast<double>(value))) {
    throw ConfigError(node.where(), path,
                      fmt::format("value {} is out of range: {}", node.text(), rule.describe()));
  }
}

template <class T>
T decode_integer(const ConfigNode& node, const std::string& path, const FieldRule& rule) {
  const std::string& text = scalar_text(node, path, "an integer");
  const auto parsed = decode_int(text);
  if (!parsed || node.quoted()) {
    throw ConfigError(node.where(), path, fmt::format("expected an integer, got '{}'", text));
  }
  if (*parsed < std::numeric_limits<T>::min() || *parsed > std::numeric_limits<T>::max()) {
    throw ConfigError(node.where(), path, fmt::format("integer {} does not fit", text));
  }
  check_range(node, path, rule, *parsed);
  return static_cast<T>(*parsed);
}

}  // namespace

ConfigReader::ConfigReader(ConfigNode& map, std::string path) : map_(map), path_(std::move(path)) {
  if (map_.is_null()) map_ = ConfigNode::map(map_.where());
  if (!map_.is_map()) {
    throw ConfigError(map_.where(), path_,
                      std::string("expected a map, got ") + kind_name(map_.kind()));
  }
}

void ConfigReader::finish() const {
  for (const auto& entry : map_.entries()) {
    if (std::find(declared_.begin(), declared_.end(), entry.key) == declared_.end()) {
      throw ConfigError(entry.key_where, child_path(entry.key),
                        "unknown key" + did_you_mean(entry.key, declared_));
    }
  }
}

void ConfigReader::decode_value(ConfigNode& node, const std::string& path, const FieldRule&,
                                bool& value) {
  const std::string& text = scalar_text(node, path, "true or false");
  const auto parsed = decode_bool(text);
  if (!parsed || node.quoted()) {
    throw ConfigError(node.where(), path, fmt::format("expected true or false, got '{}'", text));
  }
  value = *parsed;
}

void ConfigReader::decode_value(ConfigNode& node, const std::string& path, const FieldRule& rule,
                                int& value) {
  value = decode_integer<int>(node, path, rule);
}

void ConfigReader::decode_value(ConfigNode& node, const std::string& path, const FieldRule& rule,
                                int64_t& value) {
  value = decode_integer<int64_t>(node, path, rule);
}

void ConfigReader::decode_value(ConfigNode& node, const std::string& path, const FieldRule& rule,
                                uint64_t& value) {
  const std::string& text = scalar_text(node, path, "a non-negative integer");
  const auto parsed = decode_uint(text);
  if (!parsed || node.quoted()) {
    throw ConfigError(node.where(), path,
                      fmt::format("expected a non-negative integer, got '{}'", text));
  }
  check_range(node, path, rule, *parsed);
  value = *parsed;
}

void ConfigReader::decode_value(ConfigNode& node, const std::string& path, const FieldRule& rule,
                                double& value) {
  const std::string& text = scalar_text(node, path, "a number");
  const auto parsed = decode_double(text);
  if (!parsed || node.quoted()) {
    throw ConfigError(node.where(), path, fmt::format("expected a number, got '{}'", text));
  }
  check_range(node, path, rule, *parsed);
  value = *parsed;
}

void ConfigReader::decode_value(ConfigNode& node, const std::string& path, const FieldRule& rule,
                                std::string& value) {
  const std::string& text = scalar_text(node, path, "a string");
  if (!rule.accepts(text)) {
    throw ConfigError(node.where(), path,
                      fmt::format("'{}' is not allowed: {}", text, rule.describe()) +
                          did_you_mean(text, rule.allowed));
  }
  value = text;
}

void ConfigReader::decode_value(ConfigNode& node, const std::string& path, const FieldRule&,
                                ComponentSpec& value) {
  if (!node.is_map()) {
    throw ConfigError(
        node.where(), path,
        std::string("expected a map with a 'type' key, got ") + kind_name(node.kind()));
  }
  const ConfigNode* type = node.find("type");
  if (type == nullptr) throw ConfigError(node.where(), path + ".type", "missing required key");
  value.type = scalar_text(*type, path + ".type", "a type name");
  value.path = path;
  value.node = &node;
}

ConfigNode ConfigReader::encode_value(bool value, const std::string&, const FieldRule&) {
  return ConfigNode::scalar(encode(value), kDefault);
}
ConfigNode ConfigReader::encode_value(int value, const std::string&, const FieldRule&) {
  return ConfigNode::scalar(encode(static_cast<int64_t>(value)), kDefault);
}
ConfigNode ConfigReader::encode_value(int64_t value, const std::string&, const FieldRule&) {
  return ConfigNode::scalar(encode(value), kDefault);
}
ConfigNode ConfigReader::encode_value(uint64_t value, const std::string&, const FieldRule&) {
  return ConfigNode::scalar(encode(value), kDefault);
}
ConfigNode ConfigReader::encode_value(double value, const std::string&, const FieldRule&) {
  return ConfigNode::scalar(encode(value), kDefault);
}
ConfigNode ConfigReader::encode_value(const std::string& value, const std::string&,
                                      const FieldRule&) {
  return ConfigNode::scalar(value, kDefault, needs_quotes(value));
}
ConfigNode ConfigReader::encode_value(const ComponentSpec&, const std::string& path,
                                      const FieldRule&) {
  throw ConfigError(SourceLocation{}, path, "missing required section");
}

}  // namespace corrmp
