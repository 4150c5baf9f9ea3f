// The paper's own knowledge for the reports (Akbulut, Girgin et al.): which
// experiments form its PC, AE and Mono columns, its labels and their order,
// its reference numbers, the rope experiments it gives no number for and the
// figures its reproduction report shows. All of it is data in assets/paper/
// (report.yaml, which includes tables.yaml), read strictly into the generic
// report's spec (report/reproduction_report.hpp); `report --paper` and
// `report --reproduction` use it.
#pragma once

#include <string>

#include "report/reproduction_report.hpp"

namespace corrmp {

// assets/paper/ of the source tree.
std::string paper_directory();

// Reads <directory>/report.yaml. Throws ConfigError naming the file, line and
// key path when it does not hold a valid spec (an unknown key, a missing one, a
// column's numbers for other labels than the tables').
ReproductionSpec load_paper(const std::string& directory = paper_directory());

}  // namespace corrmp
