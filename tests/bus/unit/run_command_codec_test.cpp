// The scheduled swaps of a run command: each limit with its own message (issue 21 item 8: 10 000
// swaps were said to "not match the swap lists" while the limit is kMaxScheduledSwaps).
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "protocol/run/run_command_codec.hpp"

namespace wrc::protocol {
namespace {

run_command_t command_with_swaps(std::size_t count) {
  RunRequest request;
  request.model = "onepoint";
  request.run_id = "swaps";
  request.spec.integrator.t_end = 1e6;
  for (std::size_t k = 0; k < count; ++k) request.swaps.push_back({static_cast<double>(k + 1), "interp"});
  return to_message(request);
}

std::string error_of(const run_command_t& command) {
  try {
    from_message(command);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "no error";
}

TEST(RunCommandCodec, EachSwapLimitHasItsOwnMessage) {
  EXPECT_EQ(kMaxScheduledSwaps, 1000u);
  EXPECT_EQ(from_message(command_with_swaps(kMaxScheduledSwaps)).swaps.size(), kMaxScheduledSwaps);
  EXPECT_EQ(error_of(command_with_swaps(10000)),
            "num_scheduled_swaps = 10000 is more than the limit of 1000 scheduled swaps");
  EXPECT_EQ(error_of(command_with_swaps(kMaxScheduledSwaps + 1)),
            "num_scheduled_swaps = 1001 is more than the limit of 1000 scheduled swaps");
  run_command_t negative = command_with_swaps(0);
  negative.num_scheduled_swaps = -1;
  EXPECT_EQ(error_of(negative), "num_scheduled_swaps = -1 is negative");
  run_command_t mismatch = command_with_swaps(3);
  mismatch.scheduled_swap_models.pop_back();
  EXPECT_EQ(error_of(mismatch), "num_scheduled_swaps = 3 does not match the swap lists (3 times, 2 models)");
}

}  // namespace
}  // namespace wrc::protocol
