// A minimal JSON object writer for run.json and the trials' scenario column.
// Values are written in insertion order; strings are escaped per RFC 8259.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace corrmp {

class JsonObject {
 public:
  JsonObject& add(const std::string& key, const std::string& value);
  JsonObject& add(const std::string& key, const char* value);
  JsonObject& add(const std::string& key, double value);
  JsonObject& add(const std::string& key, int64_t value);
  JsonObject& add(const std::string& key, int value) { return add(key, int64_t{value}); }
  JsonObject& add(const std::string& key, bool value);
  JsonObject& add(const std::string& key, const JsonObject& value);
  JsonObject& add(const std::string& key, const std::vector<double>& values);
  JsonObject& add_null(const std::string& key);

  // Compact ("{"a":1}") or, with indent > 0, one key per line.
  std::string str(int indent = 0) const;

  static std::string quote(const std::string& text);

 private:
  std::vector<std::pair<std::string, std::string>> members_;  // key, encoded value
};

}  // namespace corrmp
