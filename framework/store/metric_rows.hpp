// Store-internal: a metric's declaration in the columns of the metrics table.
#pragma once

#include <string>

#include "core/metric.hpp"
#include "store/statement.hpp"

namespace corrmp {

// The declaration's columns, in the order bind_declaration binds and declaration_at reads them.
extern const char* const kDeclarationColumns;  // "unit, range_min, range_max, better, ..."
constexpr int kDeclarationColumnCount = 6;

// Binds the declaration to parameters first .. first + 5 (an unbounded end as NULL).
void bind_declaration(Statement& statement, int first, const MetricDeclaration& declaration);
// The declaration in columns first .. first + 5 of the current row.
MetricDeclaration declaration_at(const Statement& row, int first);

}  // namespace corrmp
