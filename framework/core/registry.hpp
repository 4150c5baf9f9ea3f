// Named component factories (environments, demonstrators, context extractors,
// policies). Filled by one explicit register_builtin_*() per module; static
// self-registration is avoided because the linker drops it from static
// libraries. Unknown name: a ConfigError listing the valid names. Duplicate
// name: std::logic_error at start-up. A factory's std::invalid_argument
// becomes a ConfigError at the component's section, a ParameterError one at
// the value it names. docs/architecture.md, "Components".
#pragma once

#include <fmt/format.h>

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/config/config_reader.hpp"
#include "core/config/did_you_mean.hpp"
#include "core/config/field_docs.hpp"
#include "core/parameter_error.hpp"
#include "core/seeds.hpp"

namespace corrmp {

template <class Base>
class Registry {
 public:
  struct Entry {
    std::string name;
    std::string description;
    std::vector<FieldDoc> parameters;
    std::function<std::unique_ptr<Base>(ConfigNode&, const std::string&, const SeedTree&)> build;
  };

  // `kind` names what this registry holds in messages ("environment").
  explicit Registry(std::string kind) : kind_(std::move(kind)) {}

  // Registers `name`, built by make(const Params&, const SeedTree& seeds) (a
  // std::unique_ptr to a Base) from a Params struct read strictly from the
  // component's config section; `seeds` are the run's seed streams, from
  // which a component takes its own by name.
  template <class Params, class Make>
  void add(const std::string& name, const std::string& description, Make make) {
    if (find(name) != nullptr) {
      throw std::logic_error(fmt::format("duplicate {} '{}' in the registry", kind_, name));
    }
    entries_.push_back(
        Entry{name, description, FieldDocs::of<Params>(),
              [make](ConfigNode& node, const std::string& path, const SeedTree& seeds) {
                Params params;
                ConfigReader reader(node, path);
                reader.declare("type");
                params.describe(reader);
                reader.finish();
                try {
                  return std::unique_ptr<Base>(make(params, seeds));
                } catch (const ParameterError& e) {
                  throw ConfigError(stated_location(node, e.key(), node.where()),
                                    path + "." + e.key(), e.what());
                } catch (const std::invalid_argument& e) {
                  // A component refusing its parameters is a config error too.
                  throw ConfigError(node.where(), path, e.what());
                }
              }});
  }

  // Builds the component a config section names; its parameters are validated
  // (and their defaults written into the section) on the way.
  std::unique_ptr<Base> create(const ComponentSpec& spec, const SeedTree& seeds) const {
    const Entry* entry = find(spec.type);
    if (entry == nullptr) {
      const ConfigNode* type = spec.node->find("type");
      throw ConfigError(type->where(), spec.path + ".type",
                        fmt::format("unknown {} '{}'{}; valid: {}", kind_, spec.type,
                                    did_you_mean(spec.type, names()), valid_names()));
    }
    return entry->build(*spec.node, spec.path, seeds);
  }

  const Entry* find(const std::string& name) const {
    for (const auto& entry : entries_) {
      if (entry.name == name) return &entry;
    }
    return nullptr;
  }

  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& entry : entries_) out.push_back(entry.name);
    return out;
  }

  const std::vector<Entry>& entries() const { return entries_; }
  const std::string& kind() const { return kind_; }

 private:
  std::string valid_names() const {
    return entries_.empty() ? std::string("(none registered yet)")
                            : fmt::format("{}", fmt::join(names(), ", "));
  }

  std::string kind_;
  std::vector<Entry> entries_;
};

}  // namespace corrmp
