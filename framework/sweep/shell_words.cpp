// Words for bash command lines (shell_words.hpp).
#include "sweep/shell_words.hpp"

#include <algorithm>
#include <cctype>

namespace corrmp {

std::string shell_quoted(const std::string& text) {
  std::string quoted = "'";
  for (const char c : text) {
    if (c == '\'') {
      quoted += "'\\''";
    } else {
      quoted += c;
    }
  }
  return quoted + "'";
}

std::string shell_word(const std::string& text) {
  const bool plain = !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) ||
           std::string("_/.,:=+-@%").find(c) != std::string::npos;
  });
  return plain ? text : shell_quoted(text);
}

}  // namespace corrmp
