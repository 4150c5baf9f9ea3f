// Metric declarations in the metrics table (metric_rows.hpp).
#include "store/metric_rows.hpp"

#include <cmath>

namespace corrmp {

namespace {

const char* better_text(Better better) {
  switch (better) {
    case Better::higher:
      return "higher";
    case Better::lower:
      return "lower";
    case Better::neither:
      break;
  }
  return "neither";
}

Better better_of(const std::string& text) {
  if (text == "higher") return Better::higher;
  if (text == "lower") return Better::lower;
  return Better::neither;
}

}  // namespace

const char* const kDeclarationColumns = "unit, range_min, range_max, better, heading, statistic";

void bind_declaration(Statement& statement, int first, const MetricDeclaration& declaration) {
  statement.bind(first, declaration.unit);
  if (std::isinf(declaration.range.min)) {
    statement.bind_null(first + 1);
  } else {
    statement.bind(first + 1, declaration.range.min);
  }
  if (std::isinf(declaration.range.max)) {
    statement.bind_null(first + 2);
  } else {
    statement.bind(first + 2, declaration.range.max);
  }
  statement.bind(first + 3, std::string(better_text(declaration.better)))
      .bind(first + 4, declaration.heading)
      .bind(first + 5, declaration.statistic);
}

MetricDeclaration declaration_at(const Statement& row, int first) {
  MetricDeclaration declaration;
  declaration.unit = row.column_text(first);
  if (!row.column_is_null(first + 1)) declaration.range.min = row.column_double(first + 1);
  if (!row.column_is_null(first + 2)) declaration.range.max = row.column_double(first + 2);
  declaration.better = better_of(row.column_text(first + 3));
  declaration.heading = row.column_text(first + 4);
  declaration.statistic = row.column_text(first + 5);
  return declaration;
}

}  // namespace corrmp
