// SPDX-License-Identifier: Apache-2.0
// The heartbeat keeper (HeartbeatPublisher::start_keeper) over memq://: while the owner's loop is
// busy (no tick() for many periods, but less than max_busy) heartbeats keep coming once per period
// from the keeper thread, so a service answering a burst of requests or retrying a contact query
// is not taken for dead; once the loop has not ticked for max_busy the heartbeats stop, so a
// stuck loop still goes silent. Period 0.05 s, max_busy 0.6 s; the windows below leave at least
// 0.15 s (3 periods) around each threshold.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "bus/service/heartbeat_monitor.hpp"
#include "bus/service/heartbeat_publisher.hpp"
#include "memq_bus.hpp"
#include "test_bus_key.hpp"

namespace {
using namespace wrc::bus;

TEST(HeartbeatKeeper, CoversABusyLoopButNotAStuckOne) {
  lcm::LCM lcm("memq://");
  HeartbeatMonitor monitor(lcm, "HEARTBEAT");
  // 0.1 s periods: a keeper thread delayed by a loaded machine (the whole suite on two cores) for
  // less than the monitor's three periods still counts as keeping up.
  const double period = 0.1;
  HeartbeatPublisher publisher(lcm, "HEARTBEAT", {"wrc-test", "pingd", "k", ""}, period);
  publisher.set_state(wrc::heartbeat_t::READY);
  publisher.start_keeper(1.2);
  ASSERT_TRUE(test::handle_until(lcm, [&] { return monitor.find("pingd", "k", monotonic_seconds()).has_value(); }));

  // Busy for 0.8 s (8 periods) without a tick: the monitor keeps it alive, the keeper sent them.
  const std::int64_t before = publisher.published();
  const double busy_until = monotonic_seconds() + 0.8;
  bool always_alive = true;
  while (monotonic_seconds() < busy_until) {
    lcm.handleTimeout(10);
    auto s = monitor.find("pingd", "k", monotonic_seconds());
    always_alive = always_alive && s && s->alive;
  }
  EXPECT_TRUE(always_alive);
  EXPECT_GE(publisher.published() - before, 5);  // 8 periods, one each, less scheduling slack
  EXPECT_EQ(publisher.kept_alive(), publisher.published() - before);
  auto s = monitor.find("pingd", "k", monotonic_seconds());
  ASSERT_TRUE(s);
  EXPECT_EQ(s->last.state, wrc::heartbeat_t::READY);  // the last heartbeat again

  // Still no tick: past max_busy (1.2 s after the last tick) the keeper stops; 3 periods later
  // the monitor calls it dead.
  EXPECT_TRUE(test::handle_until(
      lcm, [&] { return !monitor.find("pingd", "k", monotonic_seconds())->alive; }, 2.0));
  const std::int64_t stopped_at = publisher.published();
  test::handle_until(lcm, [] { return false; }, 0.4);
  EXPECT_EQ(publisher.published(), stopped_at);

  // The loop comes back: tick() publishes at once and the keeper covers again.
  EXPECT_TRUE(publisher.tick());
  EXPECT_TRUE(test::handle_until(lcm, [&] { return monitor.find("pingd", "k", monotonic_seconds())->alive; }));
}

// A loop that comes round often but not on the period's beat (a service loop running steps or
// answering a burst) publishes its own heartbeats: the keeper's copies of the last one (sent when
// the loop is a little late) do not postpone them. They used to: once the keeper had sent a copy,
// its next wake-up fell exactly on the next due time, before the loop looked, so every later
// heartbeat was a copy of the old one (a running wrc-dynamicsd said "idle" in `wrc status` for
// whole runs, with stale loads and drop counts; here 17 copies in 20 periods, 50 turns stale).
TEST(HeartbeatKeeper, CopiesDoNotPostponeTheLoopsOwnHeartbeats) {
  lcm::LCM lcm("memq://");
  HeartbeatMonitor monitor(lcm, "HEARTBEAT");
  const double period = 0.05;
  HeartbeatPublisher publisher(lcm, "HEARTBEAT", {"wrc-test", "pingd", "k", ""}, period);
  int turn = 0;  // the loop's iterations, reported as the activity
  publisher.set_activity_source([&turn] { return std::to_string(turn); });
  publisher.set_state(wrc::heartbeat_t::READY);
  publisher.start_keeper(1.0);
  int stalest = 0;  // most iterations between the loop's state and what the last heartbeat says
  const double end = monotonic_seconds() + 1.0;  // 20 periods
  while (monotonic_seconds() < end) {
    const double busy_until = monotonic_seconds() + 0.3 * period;  // work, then one look
    while (monotonic_seconds() < busy_until) lcm.handleTimeout(1);
    ++turn;
    publisher.tick();
    lcm.handleTimeout(0);
    if (auto s = monitor.find("pingd", "k", monotonic_seconds())) stalest = std::max(stalest, turn - std::stoi(s->last.activity));
  }
  // The loop's own heartbeat is due once a period and the loop looks every 0.3 periods: what the
  // monitor holds is at most about 4 turns old.
  EXPECT_LE(stalest, 6) << publisher.kept_alive() << " copies by the keeper";
}

}  // namespace
