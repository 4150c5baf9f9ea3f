// Uids of runs recorded before runs had one (run_uid.hpp).
#include "store/run_uid.hpp"

#include <fmt/format.h>

#include <cstdint>

namespace corrmp {

namespace {

uint64_t fnv1a(const std::string& bytes, uint64_t hash) {
  for (const unsigned char c : bytes) {
    hash ^= c;
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

}  // namespace

const std::vector<std::string> kRunIdentityColumns = {
    "id", "experiment", "config_hash", "seed", "started_at", "host", "pid"};

std::string derived_run_uid(const std::vector<std::string>& identity) {
  std::string key;  // each value with its length, so that no two lists give the same key
  for (const std::string& value : identity) key += std::to_string(value.size()) + ":" + value + ";";
  return fmt::format("{:016x}{:016x}", fnv1a(key, 0xcbf29ce484222325ULL),
                     fnv1a(key, 0x84222325cbf29ce4ULL));
}

}  // namespace corrmp
