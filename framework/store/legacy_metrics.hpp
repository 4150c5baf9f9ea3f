// The declaration of a metric recorded before metrics were declared (schema 3 and older), made
// from its name as the reports of that time read it: given to each such metric when its database
// is migrated or merged (result_store.cpp, store_merge.cpp). Names are parsed here and nowhere
// else: what a newer run records is declared where it is measured (core/metric.hpp).
#pragma once

#include <string>

#include "core/metric.hpp"

namespace corrmp {

// Split into words at '_':
// - <segment>_mp_error_mean_<unit> and ..._max_<unit> (closed-loop trajectory errors) are errors
//   in <unit> shown as "<segment>-MP error mean / max (<unit>)";
// - <segment>_error_mean and ..._max (held-out errors of a run without an environment) are
//   errors in the data's units shown as "<segment> error mean / max (held-out)";
// - a rate (the word "rate") lies in [0, 1], higher is better for task success, decision match
//   and a context found;
// - an error, mse, distance, time, seconds or duration is at least 0, lower is better, in the unit
//   its last word names (mm, cm, m, s) if it does;
// - failures are counts, lower is better; expected, demonstrations and parameters are counts;
// - anything else is unbounded, without unit or direction.
MetricDeclaration inferred_declaration(const std::string& name);

}  // namespace corrmp
