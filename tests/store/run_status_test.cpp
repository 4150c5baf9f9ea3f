// Tests of run statuses as the runs table spells them (store/run_status.hpp).
#include "store/run_status.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <stdexcept>

namespace corrmp {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

TEST(RunStatus, EachStatusIsReadBackFromItsText) {
  for (const RunStatus status :
       {RunStatus::running, RunStatus::completed, RunStatus::failed, RunStatus::interrupted}) {
    EXPECT_EQ(run_status_from_string(to_string(status)), status) << to_string(status);
  }
  EXPECT_EQ(to_string(RunStatus::completed), "completed");
  EXPECT_EQ(to_string(RunStatus::interrupted), "interrupted");
}

TEST(RunStatus, AnUnknownTextIsRefusedNamingIt) {
  for (const char* text : {"finished", "Completed", "", "completed "}) {
    EXPECT_THAT([&] { run_status_from_string(text); },
                ThrowsMessage<std::invalid_argument>(HasSubstr(std::string("'") + text + "'")))
        << text;
  }
}

}  // namespace
}  // namespace corrmp
