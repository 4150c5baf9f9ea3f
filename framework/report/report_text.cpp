// Report table cells (report_text.hpp).
#include "report/report_text.hpp"

#include <fmt/format.h>

#include <cmath>

namespace corrmp {

std::string markdown_cell(const std::string& text) {
  std::string escaped;
  for (char c : text) escaped += c == '|' ? std::string("\\|") : std::string(1, c);
  return escaped;
}

std::string csv_cell(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string fixed_number(double value, int decimals) {
  const double size = std::fabs(value);
  return size >= 0.1 || size == 0 ? fmt::format("{:.{}f}", value, decimals)
                                  : fmt::format("{:#.3g}", value);
}

std::string report_number(double value) {
  if (std::isnan(value)) return "-";
  return std::fabs(value) >= 1000 ? fmt::format("{:.4g}", value) : fixed_number(value, 3);
}

std::string csv_number(double value) {
  return std::isnan(value) ? std::string() : fmt::format("{}", value);
}

std::string mean_with_interval(const MeanInterval& m, double low, double high) {
  if (m.count == 0) return "-";
  if (!m.defined()) return report_number(m.mean) + " (1 run, no interval)";
  return fmt::format("{} [{}, {}]", report_number(m.mean), report_number(low), report_number(high));
}

std::string pooled_success_text(const ProportionInterval& p) {
  if (p.trials == 0) return "no trials";
  return fmt::format("{} of {} ({:.1f}%, 95% CI {:.1f}-{:.1f}%)", p.successes, p.trials,
                     100 * p.rate, 100 * p.low, 100 * p.high);
}

}  // namespace corrmp
