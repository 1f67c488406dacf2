// SPDX-License-Identifier: Apache-2.0
// Heartbeats over memq://: identity, state changes, load, geometry key and model hash, and dead
// detection after 3 periods.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>
#include <vector>

#include "bus/auth/message_auth.hpp"
#include "bus/service/heartbeat_monitor.hpp"
#include "bus/service/heartbeat_publisher.hpp"
#include "bus/transport/drop_counters.hpp"
#include "memq_bus.hpp"
#include "test_bus_key.hpp"

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
// An unsigned heartbeat (a spoofed READY instance "0" with a period of an hour) and one signed
// under another key leave no entry; the drops are counted.
TEST(Heartbeat, UnsignedAndForgedHeartbeatsIgnored) {
  lcm::LCM lcm("memq://");
  HeartbeatMonitor monitor(lcm, "HEARTBEAT");
  wrc::heartbeat_t fake{};
  fake.model = "onepoint";
  fake.instance = "0";
  fake.state = wrc::heartbeat_t::READY;
  fake.period = 3600.0;
  fake.interface_version = wrc::heartbeat_t::INTERFACE_VERSION;
  const auto before = drop_counts();
  lcm.publish("HEARTBEAT", &fake);
  BusKey other;
  other.bytes.fill(9);
  MessageAuth forger(other, 77);
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(fake.getEncodedSize()));
  fake.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  forger.sign("HEARTBEAT", bytes);
  lcm.publish("HEARTBEAT", bytes.data(), static_cast<unsigned>(bytes.size()));
  test::drain(lcm);
  EXPECT_EQ(monitor.size(), 0u);
  EXPECT_EQ(monitor.rejected(), 2);
  EXPECT_EQ(drop_counts().unsigned_messages(), before.unsigned_messages() + 1);
  EXPECT_EQ(drop_counts().bad_signature(), before.bad_signature() + 1);
}

// Each process is an entry of its own (two processes with one name show twice); silent entries
// are forgotten; the table never holds more than kMaxEntries.
TEST(Heartbeat, TableIsPerProcessPrunedAndBounded) {
  lcm::LCM lcm("memq://");
  HeartbeatMonitor monitor(lcm, "HEARTBEAT");
  const BusKey key = test::test_bus_key();
  auto publish_from = [&](std::uint64_t nonce, const std::string& instance, double period) {
    wrc::heartbeat_t hb{};
    hb.model = "pingd";
    hb.instance = instance;
    hb.period = period;
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(hb.getEncodedSize()));
    hb.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
    MessageAuth(key, nonce).sign("HEARTBEAT", bytes);
    lcm.publish("HEARTBEAT", bytes.data(), static_cast<unsigned>(bytes.size()));
  };
  publish_from(1, "same", 0.01);
  publish_from(2, "same", 0.01);
  test::drain(lcm);
  EXPECT_EQ(monitor.services(monotonic_seconds()).size(), 2u);
  for (std::uint64_t nonce = 100; nonce < 100 + 2 * HeartbeatMonitor::kMaxEntries; ++nonce) {
    publish_from(nonce, "n" + std::to_string(nonce), 0.01);
    if (nonce % 500 == 0) test::drain(lcm);
  }
  test::drain(lcm);
  EXPECT_LE(monitor.size(), HeartbeatMonitor::kMaxEntries);
  std::this_thread::sleep_for(std::chrono::duration<double>(HeartbeatMonitor::kForgetMinimum + 0.1));
  publish_from(5, "late", 0.01);  // an arrival sweeps the silent ones out
  test::drain(lcm);
  EXPECT_EQ(monitor.size(), 1u);
}

}  // namespace
