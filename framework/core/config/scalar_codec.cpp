// Strict scalar decoding and round-trip encoding for configs.
#include "core/config/scalar_codec.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace corrmp {

std::optional<bool> decode_bool(const std::string& text) {
  if (text == "true" || text == "True" || text == "TRUE") return true;
  if (text == "false" || text == "False" || text == "FALSE") return false;
  return std::nullopt;
}

std::optional<int64_t> decode_int(const std::string& text) {
  if (text.empty()) return std::nullopt;
  errno = 0;
  char* end = nullptr;
  const long long value = std::strtoll(text.c_str(), &end, 10);
  if (errno != 0 || end != text.c_str() + text.size()) return std::nullopt;
  return static_cast<int64_t>(value);
}

std::optional<uint64_t> decode_uint(const std::string& text) {
  if (text.empty() || text[0] == '-') return std::nullopt;
  errno = 0;
  char* end = nullptr;
  const unsigned long long value = std::strtoull(text.c_str(), &end, 10);
  if (errno != 0 || end != text.c_str() + text.size()) return std::nullopt;
  return static_cast<uint64_t>(value);
}

std::optional<double> decode_double(const std::string& text) {
  if (text.empty()) return std::nullopt;
  errno = 0;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (errno != 0 || end != text.c_str() + text.size() || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

std::string encode(bool value) { return value ? "true" : "false"; }
std::string encode(int64_t value) { return fmt::format("{}", value); }
std::string encode(uint64_t value) { return fmt::format("{}", value); }
std::string encode(double value) {
  std::string text = fmt::format("{}", value);
  // Keep doubles recognisable as such when the config is read back.
  if (text.find_first_of(".eEn") == std::string::npos) text += ".0";
  return text;
}

bool needs_quotes(const std::string& text) {
  return text.empty() || text == "null" || text == "~" || decode_bool(text).has_value() ||
         decode_double(text).has_value();
}

}  // namespace corrmp
