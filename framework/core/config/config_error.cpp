// Config errors: formatting of locations and messages. docs/architecture.md, "Configs".
#include "core/config/config_error.hpp"

#include <fmt/format.h>

#include "core/config/config_text.hpp"

namespace corrmp {

std::string SourceLocation::str() const {
  if (line <= 0) return file;
  return fmt::format("{}:{}:{}", file, line, column);
}

namespace {

// The message on one line of valid UTF-8: control characters and bytes that
// are not UTF-8 (from a file name or a value) written as escapes, and the
// middle of a very long message (a huge value quoted in it) left out.
std::string one_line(const std::string& message) {
  std::string out;
  for (std::size_t at = 0; at < message.size();) {
    const auto byte = static_cast<unsigned char>(message[at]);
    const std::size_t length = utf8_length(message, at);
    if (byte == '\n') {
      out += "\\n";
    } else if (byte == '\r') {
      out += "\\r";
    } else if (byte == '\t') {
      out += "\\t";
    } else if (byte < 0x20 || byte == 0x7F || length == 0) {
      out += fmt::format("\\x{:02x}", byte);
    } else {
      out.append(message, at, length);
      at += length;
      continue;
    }
    ++at;
  }
  constexpr std::size_t kHead = 1500, kTail = 500;
  if (out.size() <= kHead + kTail + 100) return out;
  std::size_t head = kHead, tail = out.size() - kTail;
  // Cut between characters, not inside one.
  while (head > 0 && (static_cast<unsigned char>(out[head]) & 0xC0) == 0x80) --head;
  while (tail < out.size() && (static_cast<unsigned char>(out[tail]) & 0xC0) == 0x80) ++tail;
  return fmt::format("{} [... {} bytes left out ...] {}", out.substr(0, head), tail - head,
                     out.substr(tail));
}

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
    : std::runtime_error(one_line(compose(where, key_path, what))),
      where_(where),
      key_path_(key_path),
      reason_(what) {}

ConfigError::ConfigError(const std::string& message) : std::runtime_error(one_line(message)) {}

}  // namespace corrmp
