// Built-in registries and their listing.
#include "experiment/registries.hpp"

#include <fmt/format.h>

#include "cnmp/register_builtin.hpp"
#include "context/register_builtin.hpp"
#include "envs/register_builtin.hpp"
#include "policies/register_builtin.hpp"

namespace corrmp {

Registries builtin_registries() {
  Registries registries;
  register_builtin_envs(registries.environments, registries.demonstrations);
  register_builtin_cnmp(registries.demonstrations);
  register_builtin_contexts(registries.contexts);
  register_builtin_policies(registries.policies);
  return registries;
}

namespace {

template <class Base>
std::string describe_registry(const std::string& section, const Registry<Base>& registry) {
  const std::string& kind = registry.kind();
  const std::string plural =
      !kind.empty() && kind.back() == 'y' ? kind.substr(0, kind.size() - 1) + "ies" : kind + "s";
  std::string out = fmt::format("{} ({}):\n", section, plural);
  if (registry.entries().empty()) return out + "  (none registered yet)\n";
  for (const auto& entry : registry.entries()) {
    out += fmt::format("  {:<22} {}\n", entry.name, entry.description);
    for (const auto& p : entry.parameters) {
      const std::string value = p.default_value.empty() ? p.rule : "= " + p.default_value;
      out += fmt::format("      {:<26} {:<8} {:<14} {}\n", p.key, p.type, value, p.description);
    }
  }
  return out;
}

}  // namespace

std::string describe_registries(const Registries& registries) {
  return describe_registry("environment", registries.environments) + "\n" +
         describe_registry("demonstrations", registries.demonstrations) + "\n" +
         describe_registry("context", registries.contexts) + "\n" +
         describe_registry("policy", registries.policies);
}

}  // namespace corrmp
