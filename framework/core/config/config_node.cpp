// A location-aware YAML tree built from yaml-cpp nodes. docs/architecture.md, "Configs".
#include "core/config/config_node.hpp"

#include <yaml-cpp/yaml.h>

#include "core/config/config_file.hpp"
#include "core/config/config_text.hpp"
#include "core/config/yaml_tree_builder.hpp"

namespace corrmp {

ConfigNode ConfigNode::scalar(std::string text, SourceLocation where, bool quoted) {
  ConfigNode node;
  node.kind_ = Kind::Scalar;
  node.text_ = std::move(text);
  node.where_ = std::move(where);
  node.quoted_ = quoted;
  return node;
}

ConfigNode ConfigNode::sequence(SourceLocation where) {
  ConfigNode node;
  node.kind_ = Kind::Sequence;
  node.where_ = std::move(where);
  return node;
}

ConfigNode ConfigNode::map(SourceLocation where) {
  ConfigNode node;
  node.kind_ = Kind::Map;
  node.where_ = std::move(where);
  return node;
}

ConfigNode ConfigNode::parse(const std::string& text, const std::string& file) {
  ConfigBudget budget;
  return parse(text, file, budget);
}

ConfigNode ConfigNode::parse(const std::string& text, const std::string& file, ConfigBudget& budget,
                             int base_depth) {
  if (text.size() > kMaxConfigFileBytes) {
    throw ConfigError(
        SourceLocation{file, 0, 0}, "",
        "larger than " + describe_bytes(kMaxConfigFileBytes) + ", the limit for a config file");
  }
  if (const auto problem = find_text_problem(text)) {
    throw ConfigError(SourceLocation{file, problem->line, problem->column}, "", problem->message);
  }
  return build_yaml_tree(text, file, budget, base_depth);
}

ConfigNode ConfigNode::load_file(const std::string& path) {
  return parse(read_config_file(path), path);
}

const ConfigNode* ConfigNode::find(const std::string& key) const {
  for (const auto& entry : entries_) {
    if (entry.key == key) return &entry.value;
  }
  return nullptr;
}

ConfigNode* ConfigNode::find(const std::string& key) {
  for (auto& entry : entries_) {
    if (entry.key == key) return &entry.value;
  }
  return nullptr;
}

ConfigNode& ConfigNode::set(const std::string& key, ConfigNode value, SourceLocation key_where) {
  if (kind_ == Kind::Null) kind_ = Kind::Map;
  for (auto& entry : entries_) {
    if (entry.key == key) {
      entry.value = std::move(value);
      return entry.value;
    }
  }
  entries_.push_back(MapEntry{key, std::move(key_where), std::move(value)});
  return entries_.back().value;
}

bool ConfigNode::erase(const std::string& key) {
  for (auto it = entries_.begin(); it != entries_.end(); ++it) {
    if (it->key == key) {
      entries_.erase(it);
      return true;
    }
  }
  return false;
}

void ConfigNode::merge_from(const ConfigNode& overlay) {
  if (!(is_map() && overlay.is_map())) {
    *this = overlay;
    return;
  }
  for (const auto& entry : overlay.entries()) {
    ConfigNode* existing = find(entry.key);
    if (existing != nullptr && existing->is_map() && entry.value.is_map()) {
      existing->merge_from(entry.value);
    } else {
      set(entry.key, entry.value, entry.key_where);
    }
  }
}

namespace {

bool is_flat_sequence(const ConfigNode& node) {
  for (const auto& item : node.items()) {
    if (!item.is_scalar()) return false;
  }
  return true;
}

void emit(const ConfigNode& node, YAML::Emitter& out) {
  switch (node.kind()) {
    case ConfigNode::Kind::Scalar:
      if (node.quoted()) out << YAML::DoubleQuoted;
      out << node.text();
      return;
    case ConfigNode::Kind::Sequence:
      if (is_flat_sequence(node)) out << YAML::Flow;
      out << YAML::BeginSeq;
      for (const auto& item : node.items()) emit(item, out);
      out << YAML::EndSeq;
      return;
    case ConfigNode::Kind::Map:
      out << YAML::BeginMap;
      for (const auto& entry : node.entries()) {
        out << YAML::Key << entry.key << YAML::Value;
        emit(entry.value, out);
      }
      out << YAML::EndMap;
      return;
    case ConfigNode::Kind::Null:
      out << YAML::Null;
      return;
  }
}

}  // namespace

std::string ConfigNode::to_yaml_string(bool flow) const {
  YAML::Emitter out;
  if (flow) {
    out.SetMapFormat(YAML::Flow);
    out.SetSeqFormat(YAML::Flow);
  }
  emit(*this, out);
  return std::string(out.c_str()) + "\n";
}

const char* kind_name(ConfigNode::Kind kind) {
  switch (kind) {
    case ConfigNode::Kind::Null:
      return "null";
    case ConfigNode::Kind::Scalar:
      return "a scalar";
    case ConfigNode::Kind::Sequence:
      return "a list";
    case ConfigNode::Kind::Map:
      return "a map";
  }
  return "?";
}

}  // namespace corrmp
