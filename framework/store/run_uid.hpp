// The uid of a run recorded before runs had one (schema version 2), made from the run's own
// fields, so that every copy of the run gets the same one: a merge of the old database and the
// upgrade of that database in place (result_store.hpp) agree, and merging it again adds nothing.
#pragma once

#include <string>
#include <vector>

namespace corrmp {

// The runs' columns that tell runs apart ("id" first), in the order derived_run_uid takes them.
extern const std::vector<std::string> kRunIdentityColumns;

// 32 hex digits from the values of kRunIdentityColumns (as SQLite gives them as text; NULL as "").
std::string derived_run_uid(const std::vector<std::string>& identity);

}  // namespace corrmp
