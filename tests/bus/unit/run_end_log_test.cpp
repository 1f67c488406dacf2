// SPDX-License-Identifier: Apache-2.0
// The line wrc-dynamicsd logs at the end of a run (dynamicsd/run_end_log.hpp): a normal end has
// no empty "()", a reason is shown in parentheses, and the run id and reason, which come from
// messages, are escaped.
#include <gtest/gtest.h>

#include <string>

#include "dynamicsd/run_end_log.hpp"

namespace wrc::dynamics {
namespace {

TEST(RunEndLog, ANormalEndHasNoEmptyParenthesesAndAReasonIsShownEscaped) {
  RunCounters c;
  c.steps = 353;
  c.restarts = 2;
  c.contact_queries = 1115;
  EXPECT_EQ(run_end_log_line("bench-1", 0.5, "", 0.28, c),
            "wrc-dynamicsd: run bench-1 ended at t = 0.5 s in 0.28 s, 353 steps, 2 restarts, 1115 contact queries");
  EXPECT_EQ(run_end_log_line("r\n2", 0.125, "stopped by\x1b[2J wrc stop", 1.5, c),
            "wrc-dynamicsd: run r\\x0a2 ended at t = 0.125 s (stopped by\\x1b[2J wrc stop) in 1.5 s, 353 steps, 2 "
            "restarts, 1115 contact queries");
}

}  // namespace
}  // namespace wrc::dynamics
