// Config errors: formatting of locations and messages. docs/architecture.md, "Configs".
#include "core/config/config_error.hpp"

#include <fmt/format.h>

namespace corrmp {

std::string SourceLocation::str() const {
  if (line <= 0) return file;
  return fmt::format("{}:{}:{}", file, line, column);
}

namespace {
std::string compose(const SourceLocation& where, const std::string& key_path,
                    const std::string& what) {
  std::string out = where.str();
  if (!out.empty()) out += ": ";
  if (!key_path.empty()) out += key_path + ": ";
  return out + what;
}
}  // namespace

ConfigError::ConfigError(const SourceLocation& where, const std::string& key_path,
                         const std::string& what)
    : std::runtime_error(compose(where, key_path, what)) {}

}  // namespace corrmp
