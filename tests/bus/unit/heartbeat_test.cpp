// Heartbeats over memq://: identity, state changes, load, geometry key and model hash, and dead
// detection after 3 periods.
#include <gtest/gtest.h>

#include <thread>

#include "bus/heartbeat_monitor.hpp"
#include "bus/heartbeat_publisher.hpp"
#include "memq_bus.hpp"

namespace {
using namespace wrc::bus;

// The monitor sees identity, state, version and load of a publisher.
TEST(Heartbeat, MonitorSeesPublisher) {
  lcm::LCM lcm("memq://");
  HeartbeatMonitor monitor(lcm, "HEARTBEAT");
  HeartbeatPublisher publisher(lcm, "HEARTBEAT", {"wrc-test", "pingd", "a", "PING"}, 0.5);
  ServiceLoad load;
  load.requests_handled = 42;
  load.latency_p95 = 1e-4;
  publisher.set_load(load);
  publisher.set_geometry_key("k");
  publisher.set_model_hash("m");
  publisher.set_state(wrc::heartbeat_t::READY);
  test::drain(lcm);
  auto status = monitor.find("pingd", "a", monotonic_seconds());
  ASSERT_TRUE(status);
  EXPECT_TRUE(status->alive);
  EXPECT_TRUE(status->available());
  EXPECT_EQ(status->last.requests_handled, 42);
  EXPECT_DOUBLE_EQ(status->last.latency_p95, 1e-4);
  EXPECT_EQ(status->last.request_channel, "PING");
  EXPECT_EQ(status->last.geometry_key, "k");
  EXPECT_EQ(status->last.model_hash, "m");
  EXPECT_EQ(status->last.interface_version, wrc::heartbeat_t::INTERFACE_VERSION);
  EXPECT_EQ(status->last.pid, ::getpid());
  EXPECT_EQ(status->last.header.sender, sender_name("wrc-test", "a"));

  publisher.set_state(wrc::heartbeat_t::DRAINING);
  test::drain(lcm);
  status = monitor.find("pingd", "a", monotonic_seconds());
  EXPECT_TRUE(status->alive);
  EXPECT_FALSE(status->available());
}

// tick() publishes once per period; a silent service is dead after 3 periods, not before.
TEST(Heartbeat, DeadAfterThreeMissedPeriods) {
  lcm::LCM lcm("memq://");
  HeartbeatMonitor monitor(lcm, "HEARTBEAT");
  const double period = 0.05;
  HeartbeatPublisher publisher(lcm, "HEARTBEAT", {"wrc-test", "pingd", "b", ""}, period);
  EXPECT_TRUE(publisher.tick());
  EXPECT_FALSE(publisher.tick());  // not due yet
  test::drain(lcm);
  const auto seen = monitor.find("pingd", "b", monotonic_seconds());
  ASSERT_TRUE(seen);
  EXPECT_TRUE(seen->alive);
  EXPECT_TRUE(monitor.find("pingd", "b", seen->last_seen + 2.9 * period)->alive);
  EXPECT_FALSE(monitor.find("pingd", "b", seen->last_seen + 3.1 * period)->alive);
  std::this_thread::sleep_for(std::chrono::duration<double>(3.5 * period));
  EXPECT_FALSE(monitor.find("pingd", "b", monotonic_seconds())->alive);
  EXPECT_TRUE(publisher.tick());
  test::drain(lcm);
  EXPECT_TRUE(monitor.find("pingd", "b", monotonic_seconds())->alive);
}

// Garbage on the heartbeat channel and nonsense periods are rejected and counted.
TEST(Heartbeat, MonitorRejectsBadHeartbeats) {
  lcm::LCM lcm("memq://");
  HeartbeatMonitor monitor(lcm, "HEARTBEAT");
  const unsigned char garbage[] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
  lcm.publish("HEARTBEAT", garbage, sizeof garbage);
  wrc::heartbeat_t hb{};
  hb.model = "x";
  hb.period = -1.0;
  lcm.publish("HEARTBEAT", &hb);
  test::drain(lcm);
  EXPECT_EQ(monitor.rejected(), 2);
  EXPECT_TRUE(monitor.services(monotonic_seconds()).empty());
  EXPECT_THROW(HeartbeatPublisher(lcm, "HEARTBEAT", {}, 0.0), std::invalid_argument);
}
}  // namespace
