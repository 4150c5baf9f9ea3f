// Checks that config text (a file's bytes or a command-line override) is YAML
// text: UTF-8 throughout, no NUL bytes and no control characters other than
// tab, line feed and carriage return. yaml-cpp accepts invalid UTF-8 (which
// would end up in the result database) and misreports NUL bytes, so these are
// caught before it parses. docs/architecture.md, "Configs".
#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace corrmp {

// The first character that is not allowed, and where it is.
struct TextProblem {
  std::size_t offset = 0;  // byte offset into the text
  int line = 1;            // 1-based
  int column = 1;          // 1-based, in bytes (as yaml-cpp counts columns)
  std::string message;     // e.g. "invalid UTF-8 (byte 0xff)"
};

// std::nullopt when every character is allowed. A byte order mark is allowed
// as the very first character only.
std::optional<TextProblem> find_text_problem(const std::string& text);

// Length in bytes of the valid UTF-8 character at `offset`, or 0 when the
// bytes there are not UTF-8 (overlong forms and surrogates included).
std::size_t utf8_length(const std::string& text, std::size_t offset);

// 1-based line and byte column of `offset` in `text`.
void line_and_column(const std::string& text, std::size_t offset, int& line, int& column);

}  // namespace corrmp
