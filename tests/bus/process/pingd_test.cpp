// SPDX-License-Identifier: Apache-2.0
// wrc-pingd as a real process on a real udpm bus: round trips, packet loss with retries,
// malformed messages, death detection and clean shutdown. Each test is bounded by deadlines.
#include <signal.h>
#include <sys/wait.h>

#include <cstdlib>

#include "bus/transport/clock.hpp"
#include "bus_fixture.hpp"
#include "wrc/heartbeat_t.hpp"

namespace wrc::bus::test {
namespace {

wrc::ping_request_t ping(int bytes) {
  wrc::ping_request_t req{};
  req.num_payload = bytes;
  req.payload.assign(static_cast<std::size_t>(bytes), 0x2a);
  return req;
}

// Every ping is answered with its own id and payload.
TEST_F(BusTest, PingRoundTrips) {
  auto pingd = start_pingd("a", 0.1);
  ASSERT_TRUE(wait_ready("pingd", "a", 5.0)) << "wrc-pingd sent no READY heartbeat";
  for (int i = 0; i < 200; ++i) {
    auto req = ping(i % 64);
    auto result = client_->call(req, {0.5, 2});
    ASSERT_TRUE(result) << "ping " << i << " unanswered";
    EXPECT_EQ(result.reply->request_id, req.request_id);
    EXPECT_EQ(result.reply->payload, req.payload);
    EXPECT_EQ(result.reply->instance, "a");
  }
}

// With 20 % of all UDP packets on the bus port dropped by nftables (requests, replies and
// heartbeats alike), every call still succeeds through retries, and retries did happen.
TEST_F(BusTest, RequestReplySurvivesPacketLoss) {
  if (!in_netns()) GTEST_SKIP() << "packet loss is only injected inside a private network namespace";
  if (std::system("nft --version >/dev/null 2>&1") != 0) GTEST_SKIP() << "nft (nftables) is not installed";
  if (std::system("nft add table inet t && nft add chain inet t in '{ type filter hook input priority 0; }'") != 0) {
    GTEST_SKIP() << "nft cannot create a table in this namespace (no CAP_NET_ADMIN?)";
  }
  auto pingd = start_pingd("a", 0.1);
  ASSERT_TRUE(wait_ready("pingd", "a", 5.0));
  ASSERT_EQ(std::system("nft add rule inet t in udp dport 7667 numgen random mod 100 lt 20 counter drop"), 0);
  const int calls = 100;
  for (int i = 0; i < calls; ++i) {
    auto req = ping(8);
    auto result = client_->call(req, {0.03, 20});
    ASSERT_TRUE(result) << "call " << i << " failed after " << result.attempts << " attempts";
    EXPECT_EQ(result.reply->request_id, req.request_id);
  }
  const auto& c = client_->counters();
  EXPECT_EQ(c.replies, calls);
  EXPECT_GT(c.retries, 0) << "no retry needed: the loss rule did not act";
  EXPECT_EQ(c.sent, calls + c.retries);
  std::system("nft delete table inet t");
}

// Wrong type, truncated bytes and garbage on PING are rejected and counted (reported in the
// heartbeat and the service's log); the service keeps answering.
TEST_F(BusTest, MalformedMessagesRejectedAndCounted) {
  const std::string log = temp_path("pingd.log");
  auto pingd = start_pingd("a", 0.1, log);
  ASSERT_TRUE(wait_ready("pingd", "a", 5.0));
  const std::string channel = names_.name(channel::kPing);

  wrc::heartbeat_t other_type{};
  publish_signed(*lcm_, channel, other_type);
  auto req = ping(100);
  req.request_id = 1;
  req.reply_channel = client_->reply_channel();
  std::vector<unsigned char> bytes(req.getEncodedSize());
  req.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  publish_signed_bytes(channel, {bytes.begin(), bytes.begin() + static_cast<long>(bytes.size() / 2)});
  const unsigned char garbage[] = {0xde, 0xad, 0xbe, 0xef};
  publish_signed_bytes(channel, {garbage, garbage + sizeof garbage});

  auto good = ping(16);
  auto result = client_->call(good, {0.5, 4});
  ASSERT_TRUE(result) << "service stopped answering after malformed messages";
  EXPECT_EQ(result.reply->payload, good.payload);
  ASSERT_TRUE(handle_until(
      [&] {
        auto s = monitor_->find("pingd", "a", monotonic_seconds());
        return s && s->last.requests_rejected >= 3;
      },
      5.0))
      << "heartbeat does not report the 3 rejections";
  EXPECT_EQ(monitor_->find("pingd", "a", monotonic_seconds())->last.requests_rejected, 3);
  EXPECT_TRUE(pingd->running());
  pingd->signal(SIGTERM);
  ASSERT_TRUE(pingd->wait(5.0));
  const std::string text = read_text(log);
  EXPECT_NE(text.find("dropped wrong-type message on PING: fingerprint mismatch"), std::string::npos) << text;
  EXPECT_NE(text.find("truncated or corrupt ping_request_t"), std::string::npos) << text;
  EXPECT_NE(text.find("too short"), std::string::npos) << text;
}

// A service killed with SIGKILL (no DRAINING) is reported dead once 3 heartbeat periods pass
// without a heartbeat (the monitor's rule, exact against the arrival of the last one), hence not
// before 2 periods after the kill: the last heartbeat arrived at most one period before it. The
// 30 ms allowance on that lower bound is for a heartbeat timer running late on a loaded machine
// (ctest -j2); the upper bound allows 0.5 s for scheduling of this test's own polling.
TEST_F(BusTest, KilledServiceDetectedByMissingHeartbeats) {
  const double period = 0.1;
  auto pingd = start_pingd("k", period);
  ASSERT_TRUE(wait_ready("pingd", "k", 5.0));
  const double killed = monotonic_seconds();  // before the signal: the kill cannot precede it
  pingd->signal(SIGKILL);
  ASSERT_TRUE(pingd->wait(2.0));
  ASSERT_TRUE(handle_until([&] { return !monitor_->find("pingd", "k", monotonic_seconds())->alive; }, 3.0));
  const double now = monotonic_seconds();
  EXPECT_GT(now - monitor_->find("pingd", "k", now)->last_seen, 3.0 * period);
  const double detected = now - killed;
  EXPECT_GE(detected, 2.0 * period - 0.03);
  EXPECT_LE(detected, 3.0 * period + 0.5);
  EXPECT_EQ(monitor_->find("pingd", "k", monotonic_seconds())->last.state, wrc::heartbeat_t::READY);
}

// SIGTERM: the service publishes a DRAINING heartbeat and exits with status 0.
TEST_F(BusTest, CleanShutdownPublishesDraining) {
  auto pingd = start_pingd("d", 0.2);
  ASSERT_TRUE(wait_ready("pingd", "d", 5.0));
  pingd->signal(SIGTERM);
  ASSERT_TRUE(handle_until(
      [&] { return monitor_->find("pingd", "d", monotonic_seconds())->last.state == wrc::heartbeat_t::DRAINING; },
      3.0));
  int status = -1;
  ASSERT_TRUE(pingd->wait(3.0, &status));
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "status " << status;
}

// A service with --channel-prefix lives on its own channels: clients with the same prefix reach
// it, the unprefixed heartbeat channel does not see it.
TEST_F(BusTest, ChannelPrefixSeparatesSimulations) {
  auto pingd = start_pingd("p", 0.1, "", {"--channel-prefix", "SIM2"});
  const ChannelNames sim2("SIM2");
  HeartbeatMonitor sim2_monitor(*lcm_, sim2.name(channel::kHeartbeat));
  ASSERT_TRUE(handle_until(
      [&] {
        auto s = sim2_monitor.find("pingd", "p", monotonic_seconds());
        return s && s->available();
      },
      5.0));
  EXPECT_EQ(sim2_monitor.find("pingd", "p", monotonic_seconds())->last.request_channel, "SIM2.PING");
  EXPECT_FALSE(monitor_->find("pingd", "p", monotonic_seconds()));
  PingClient prefixed(*lcm_, sim2.name(channel::kPing), sim2.name(channel::kPingReply, "t"), "t");
  auto req = ping(3);
  EXPECT_TRUE(prefixed.call(req, {0.5, 2}));
  auto unprefixed = ping(3);
  EXPECT_FALSE(client_->call(unprefixed, {0.05, 1}));
}

}  // namespace
}  // namespace wrc::bus::test
