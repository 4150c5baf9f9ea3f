// Config errors: one line naming the file, line, column and dotted key path.
// docs/architecture.md, "Configs".
#pragma once

#include <stdexcept>
#include <string>

namespace corrmp {

// Where a config value came from: a YAML file position, a command-line
// override, or a default filled in by the reader.
struct SourceLocation {
  std::string file;  // "<default>" for values filled in from declared defaults
  int line = 0;      // 1-based; 0 when unknown
  int column = 0;    // 1-based; 0 when unknown

  std::string str() const;
};

// Thrown for every malformed config; what() is the complete one-line message
// (control characters and invalid UTF-8 escaped, a very long one shortened),
// e.g. "configs/x.yaml:12:5: policy.cnmp.widht: unknown key (did you mean 'width'?)".
class ConfigError : public std::runtime_error {
 public:
  ConfigError(const SourceLocation& where, const std::string& key_path, const std::string& what);
  explicit ConfigError(const std::string& message);

  /// The parts of the message, for a caller that knows better where the value came from (a
  /// sweep file's override, say); empty for an error made from a whole message.
  const SourceLocation& where() const { return where_; }
  const std::string& key_path() const { return key_path_; }
  const std::string& reason() const { return reason_; }

 private:
  SourceLocation where_;
  std::string key_path_;
  std::string reason_;
};

}  // namespace corrmp
