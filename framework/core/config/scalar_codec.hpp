// Conversion between config scalars (text) and typed values, strictly: "3.5" is
// not an int, "yes" is not a bool. docs/architecture.md, "Configs".
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace corrmp {

std::optional<bool> decode_bool(const std::string& text);
std::optional<int64_t> decode_int(const std::string& text);
std::optional<uint64_t> decode_uint(const std::string& text);
std::optional<double> decode_double(const std::string& text);

std::string encode(bool value);
std::string encode(int64_t value);
std::string encode(uint64_t value);
std::string encode(double value);  // shortest text that reads back to the same double

// True when a plain (unquoted) scalar with this text would not read back as a
// string (it looks like a number, a bool, null, or is empty).
bool needs_quotes(const std::string& text);

}  // namespace corrmp
