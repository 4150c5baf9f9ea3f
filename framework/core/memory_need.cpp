// Memory estimates (memory_need.hpp).
#include "core/memory_need.hpp"

#include <fmt/format.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>

namespace corrmp {

std::string format_bytes(double bytes) {
  const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  int unit = 0;
  while (bytes >= 1024.0 && unit < 6) {
    bytes /= 1024.0;
    ++unit;
  }
  return unit == 0 ? fmt::format("{:.0f} B", bytes) : fmt::format("{:.1f} {}", bytes, units[unit]);
}

double physical_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page_size = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page_size <= 0) return 0.0;
  return static_cast<double>(pages) * static_cast<double>(page_size);
}

MemoryBudget usable_memory() {
  MemoryBudget budget{physical_memory_bytes(), false};
  for (const int resource : {RLIMIT_AS, RLIMIT_DATA}) {
    rlimit limit{};
    if (getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) continue;
    const double bytes = static_cast<double>(limit.rlim_cur);
    if (budget.bytes <= 0.0 || bytes < budget.bytes) {
      budget = {bytes, true};
    }
  }
  return budget;
}

std::optional<size_t> largest_need_beyond(const std::vector<MemoryNeed>& needs,
                                          const MemoryBudget& budget) {
  if (needs.empty() || budget.bytes <= 0.0) return std::nullopt;
  double total = 0.0;
  for (const auto& need : needs) total += need.bytes;
  if (total <= kMemoryShare * budget.bytes) return std::nullopt;
  return static_cast<size_t>(
      std::max_element(needs.begin(), needs.end(),
                       [](const auto& a, const auto& b) { return a.bytes < b.bytes; }) -
      needs.begin());
}

std::string memory_refusal(const std::vector<MemoryNeed>& needs, size_t largest,
                           const MemoryBudget& budget) {
  double total = 0.0;
  for (const auto& need : needs) total += need.bytes;
  const std::string available =
      budget.limited ? fmt::format("this process may use {} (ulimit)", format_bytes(budget.bytes))
                     : fmt::format("this machine has {}", format_bytes(budget.bytes));
  return fmt::format("the declared sizes need about {} of memory, {} of it for {}; {}: reduce them",
                     format_bytes(total), format_bytes(needs[largest].bytes), needs[largest].what,
                     available);
}

}  // namespace corrmp
