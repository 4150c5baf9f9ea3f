// Documentation of a parameter struct's declared fields (name, type, default,
// constraint, description), for `run_experiment --list`. The same `describe`
// member that ConfigReader visits is visited here.
#pragma once

#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "core/config/config_reader.hpp"

namespace corrmp {

struct FieldDoc {
  std::string key;  // dotted, relative to the documented struct
  std::string type;
  std::string default_value;  // "" for required fields
  std::string description;
  std::string rule;  // "required", "must be >= 1", ...
};

class FieldDocs {
 public:
  template <class T>
  void operator()(const std::string& key, T& value, const std::string& description,
                  const FieldRule& rule = {}) {
    FieldDoc doc{prefix_ + key, type_name(value), "", description,
                 rule.is_required ? "required" : rule.describe()};
    // A nested struct's fields are documented one by one below it.
    if (!rule.is_required && !has_describe<T>::value) doc.default_value = default_text(value);
    docs_.push_back(doc);
    if constexpr (has_describe<T>::value) {
      FieldDocs nested;
      nested.prefix_ = prefix_ + key + ".";
      value.describe(nested);
      docs_.insert(docs_.end(), nested.docs_.begin(), nested.docs_.end());
    }
  }

  template <class T>
  static std::vector<FieldDoc> of() {
    T defaults{};
    FieldDocs docs;
    defaults.describe(docs);
    return docs.docs_;
  }

 private:
  static std::string type_name(const bool&) { return "bool"; }
  static std::string type_name(const int&) { return "int"; }
  static std::string type_name(const int64_t&) { return "int"; }
  static std::string type_name(const uint64_t&) { return "uint"; }
  static std::string type_name(const double&) { return "float"; }
  static std::string type_name(const std::string&) { return "string"; }
  static std::string type_name(const ComponentSpec&) { return "component"; }
  template <class T>
  static std::string type_name(const std::vector<T>&) {
    return "list of " + type_name(T{});
  }
  template <class T>
  static std::string type_name(const std::optional<T>&) {
    return type_name(T{});
  }
  template <class T, std::enable_if_t<has_describe<T>::value, int> = 0>
  static std::string type_name(const T&) {
    return "map";
  }

  template <class T>
  static std::string default_text(const T& value) {
    if constexpr (std::is_same_v<T, ComponentSpec> || is_optional<T>::value) {
      return "";
    } else {
      ConfigNode node = ConfigNode::map(SourceLocation{});
      T copy = value;
      ConfigReader reader(node, "");
      reader("v", copy, "");
      std::string text = node.find("v")->to_yaml_string(true);
      while (!text.empty() && text.back() == '\n') text.pop_back();
      return text;
    }
  }

  std::string prefix_;
  std::vector<FieldDoc> docs_;
};

}  // namespace corrmp
