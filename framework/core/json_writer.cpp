// Minimal JSON writing.
#include "core/json_writer.hpp"

#include <fmt/format.h>

#include <cmath>

namespace corrmp {

std::string JsonObject::quote(const std::string& text) {
  std::string out = "\"";
  for (const unsigned char c : text) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      case '\r':
        out += "\\r";
        break;
      default:
        if (c < 0x20) {
          out += fmt::format("\\u{:04x}", c);
        } else {
          out += static_cast<char>(c);
        }
    }
  }
  return out + "\"";
}

namespace {
std::string number(double value) {
  return std::isfinite(value) ? fmt::format("{}", value) : std::string("null");
}
}  // namespace

JsonObject& JsonObject::add(const std::string& key, const std::string& value) {
  members_.emplace_back(key, quote(value));
  return *this;
}
JsonObject& JsonObject::add(const std::string& key, const char* value) {
  return add(key, std::string(value));
}
JsonObject& JsonObject::add(const std::string& key, double value) {
  members_.emplace_back(key, number(value));
  return *this;
}
JsonObject& JsonObject::add(const std::string& key, int64_t value) {
  members_.emplace_back(key, fmt::format("{}", value));
  return *this;
}
JsonObject& JsonObject::add(const std::string& key, bool value) {
  members_.emplace_back(key, value ? "true" : "false");
  return *this;
}
JsonObject& JsonObject::add(const std::string& key, const JsonObject& value) {
  members_.emplace_back(key, value.str());
  return *this;
}
JsonObject& JsonObject::add(const std::string& key, const std::vector<double>& values) {
  std::string encoded = "[";
  for (size_t i = 0; i < values.size(); ++i) encoded += (i ? "," : "") + number(values[i]);
  members_.emplace_back(key, encoded + "]");
  return *this;
}
JsonObject& JsonObject::add_null(const std::string& key) {
  members_.emplace_back(key, "null");
  return *this;
}

std::string JsonObject::str(int indent) const {
  if (members_.empty()) return "{}";
  const std::string pad(indent, ' ');
  const std::string separator = indent > 0 ? ",\n" : ",";
  std::string out = indent > 0 ? "{\n" : "{";
  for (size_t i = 0; i < members_.size(); ++i) {
    out += (i ? separator : "") + pad + quote(members_[i].first) + (indent > 0 ? ": " : ":") +
           members_[i].second;
  }
  return out + (indent > 0 ? "\n}" : "}");
}

}  // namespace corrmp
