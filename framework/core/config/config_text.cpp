// Config text checks: UTF-8 decoding and the YAML printable character set.
// docs/architecture.md, "Configs".
#include "core/config/config_text.hpp"

#include <fmt/format.h>

namespace corrmp {

namespace {

// YAML 1.2's printable characters (c-printable), less the byte order mark,
// which is handled separately.
bool printable(char32_t c) {
  return c == 0x09 || c == 0x0A || c == 0x0D || (c >= 0x20 && c <= 0x7E) || c == 0x85 ||
         (c >= 0xA0 && c <= 0xD7FF) || (c >= 0xE000 && c <= 0xFFFD && c != 0xFEFF) ||
         (c >= 0x10000 && c <= 0x10FFFF);
}

// Decodes one UTF-8 character at `at`; returns its length, or 0 when the bytes
// there are not valid UTF-8 (overlong forms and surrogates included).
std::size_t decode(const std::string& text, std::size_t at, char32_t& out) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  const unsigned char lead = byte(at);
  std::size_t length = 0;
  char32_t min = 0;
  if (lead < 0x80) {
    out = lead;
    return 1;
  } else if ((lead & 0xE0) == 0xC0) {
    length = 2, out = lead & 0x1F, min = 0x80;
  } else if ((lead & 0xF0) == 0xE0) {
    length = 3, out = lead & 0x0F, min = 0x800;
  } else if ((lead & 0xF8) == 0xF0) {
    length = 4, out = lead & 0x07, min = 0x10000;
  } else {
    return 0;
  }
  if (at + length > text.size()) return 0;
  for (std::size_t i = 1; i < length; ++i) {
    if ((byte(at + i) & 0xC0) != 0x80) return 0;
    out = (out << 6) | (byte(at + i) & 0x3F);
  }
  if (out < min || out > 0x10FFFF || (out >= 0xD800 && out <= 0xDFFF)) return 0;
  return length;
}

std::optional<TextProblem> problem_at(const std::string& text, std::size_t offset,
                                      std::string message) {
  TextProblem problem;
  problem.offset = offset;
  problem.message = std::move(message);
  line_and_column(text, offset, problem.line, problem.column);
  return problem;
}

bool starts_with(const std::string& text, const char* prefix, std::size_t length) {
  return text.compare(0, length, prefix, length) == 0;
}

}  // namespace

std::size_t utf8_length(const std::string& text, std::size_t offset) {
  char32_t ignored = 0;
  return offset < text.size() ? decode(text, offset, ignored) : 0;
}

void line_and_column(const std::string& text, std::size_t offset, int& line, int& column) {
  line = 1;
  std::size_t line_start = 0;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      line_start = i + 1;
    }
  }
  column = static_cast<int>(offset - line_start) + 1;
}

std::optional<TextProblem> find_text_problem(const std::string& text) {
  if (starts_with(text, "\xFF\xFE", 2) || starts_with(text, "\xFE\xFF", 2) ||
      starts_with(text, "\0\0\xFE\xFF", 4)) {
    return problem_at(text, 0, "the text is UTF-16 or UTF-32: config text must be UTF-8");
  }
  std::size_t at = 0;
  while (at < text.size()) {
    char32_t c = 0;
    const std::size_t length = decode(text, at, c);
    if (length == 0) {
      return problem_at(text, at,
                        fmt::format("invalid UTF-8 (byte 0x{:02x}): config text must be UTF-8",
                                    static_cast<unsigned char>(text[at])));
    }
    if (c == 0) return problem_at(text, at, "NUL byte: config text cannot contain one");
    if (c == 0xFEFF && at != 0) {
      return problem_at(text, at, "byte order mark (U+FEFF) after the start of the text");
    }
    if (c != 0xFEFF && !printable(c)) {
      return problem_at(text, at,
                        fmt::format("control character U+{:04X} is not allowed in YAML",
                                    static_cast<unsigned>(c)));
    }
    at += length;
  }
  return std::nullopt;
}

}  // namespace corrmp
