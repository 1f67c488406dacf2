// SPDX-License-Identifier: Apache-2.0
// The scheduled swaps of a run command: each limit with its own message (issue 21 item 8: 10 000
// swaps were said to "not match the swap lists" while the limit is kMaxScheduledSwaps). The track
// layout of a run command: every segment through the LCM encoding exactly, and each bad field
// named.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "bus/transport/decode.hpp"
#include "protocol/run/run_command_codec.hpp"
#include "protocol/run/track_layout_codec.hpp"
#include <vector>

namespace wrc::protocol {
namespace {

run_command_t command_with_swaps(std::size_t count) {
  RunRequest request;
  request.model = "onepoint";
  request.run_id = "swaps";
  request.spec.integrator.t_end = 1e6;
  request.spec.integrator.output_period = 10.0;  // 1e5 samples: within the 200 000 a run may write
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

// in_process is a flag: 0 or 1, anything else refused naming the value (it used to mean true).
TEST(RunCommandCodec, InProcessIsZeroOrOne) {
  run_command_t command = command_with_swaps(0);
  command.in_process = 1;
  EXPECT_TRUE(from_message(command).in_process);
  command.in_process = 0;
  EXPECT_FALSE(from_message(command).in_process);
  command.in_process = 5;
  EXPECT_EQ(error_of(command), "in_process = 5 is neither 0 nor 1");
  command.in_process = -1;
  EXPECT_EQ(error_of(command), "in_process = -1 is neither 0 nor 1");
}

// A layout of every kind of segment crosses run_command_t (and its LCM encoding) exactly: the same
// curvature and cant at every sampled distance; straight track crosses as no segments.
TEST(RunCommandCodec, TheTrackLayoutCrossesExactly) {
  RunRequest request;
  request.model = "spline";
  request.run_id = "curve";
  request.spec.track = TrackLayout({{TrackSegmentKind::kStraight, 100.25, 0, true, 0},
                                    {TrackSegmentKind::kTransition, 90, 0, true, 0},
                                    {TrackSegmentKind::kCurve, 400, 612.5, false, 0.1275},
                                    {TrackSegmentKind::kTransition, 90, 0, true, 0},
                                    {TrackSegmentKind::kStraight, 100, 0, true, 0}},
                                   1.435);
  const run_command_t m = to_message(request);
  std::vector<unsigned char> bytes(static_cast<std::size_t>(m.getEncodedSize()));
  ASSERT_EQ(m.encode(bytes.data(), 0, static_cast<int>(bytes.size())), static_cast<int>(bytes.size()));
  run_command_t decoded;
  ASSERT_FALSE(bus::decode_bytes(bytes.data(), bytes.size(), decoded));  // the services' own decoding
  const TrackLayout back = from_message(decoded).spec.track;
  ASSERT_EQ(back.segments().size(), 5u);
  EXPECT_EQ(back.cant_base(), 1.435);
  for (double s = 0; s < 800; s += 3.7) {
    EXPECT_EQ(back.at(s).curvature, request.spec.track.at(s).curvature) << s;
    EXPECT_EQ(back.at(s).cant_angle, request.spec.track.at(s).cant_angle) << s;
    EXPECT_EQ(back.at(s).curvature_rate, request.spec.track.at(s).curvature_rate) << s;
  }
  RunRequest straight_track = request;
  straight_track.spec.track = TrackLayout();
  EXPECT_TRUE(from_message(to_message(straight_track)).spec.track.straight());

  run_command_t bad_kind = m;
  bad_kind.layout_segments[2].kind = 7;
  EXPECT_EQ(error_of(bad_kind), "layout_segments[2].kind = 7 is not STRAIGHT, TRANSITION or CURVE");
  run_command_t bad_count = m;
  bad_count.num_layout_segments = 4;
  EXPECT_EQ(error_of(bad_count), "num_layout_segments = 4 does not match the 5 segments of the list");
  run_command_t bad_radius = m;
  bad_radius.layout_segments[2].radius = 10.0;
  EXPECT_NE(error_of(bad_radius).find("layout: segment 3 (curve): radius 10"), std::string::npos)
      << error_of(bad_radius);
}

}  // namespace
}  // namespace wrc::protocol
