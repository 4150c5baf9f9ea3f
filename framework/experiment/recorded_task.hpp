// What a run's task declares (TaskReport, envs/environment.hpp) as the result store keeps it with
// the run (store/records.hpp), so that reports read the task's labels, columns and units from the
// database.
#pragma once

#include "envs/environment.hpp"
#include "store/records.hpp"

namespace corrmp {

TaskDeclaration recorded_task(const TaskReport& report);

}  // namespace corrmp
