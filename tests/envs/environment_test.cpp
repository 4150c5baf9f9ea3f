// Tests of what the environment interface itself declares.
#include "envs/environment.hpp"

#include <gtest/gtest.h>

namespace corrmp {
namespace {

// A task report holds no task's values: every task declares its own columns and error unit.
TEST(TaskReport, HasNoTasksDefaults) {
  const TaskReport task;
  EXPECT_TRUE(task.trajectory_columns.empty());
  EXPECT_TRUE(task.error_unit.empty());
  EXPECT_EQ(task.error_scale, 1.0);
}

}  // namespace
}  // namespace corrmp
