// SPDX-License-Identifier: Apache-2.0
#pragma once
// Fixture of the multi-process tests: a bus key of the test's own (installed here, and in
// $WRC_BUS_KEY for the processes it starts), an LCM instance on the test's private bus (the
// default URL inside the namespace made by clients/lib/netns.sh, or its LCM_DEFAULT_URL
// fallback), a heartbeat monitor, a ping client, and helpers to start wrc-pingd and wait with
// deadlines.
#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "bus/auth/signed_publish.hpp"
#include "bus/service/heartbeat_monitor.hpp"
#include "bus/transport/channels.hpp"
#include "bus/transport/request_client.hpp"
#include "child_process.hpp"
#include "wrc/ping_reply_t.hpp"
#include "wrc/ping_request_t.hpp"

namespace wrc::bus::test {

using PingClient = RequestClient<wrc::ping_request_t, wrc::ping_reply_t>;

class BusTest : public ::testing::Test {
 protected:
  void SetUp() override;
  /// Removes the test's temporary directory (logs, key, caches) when the test passed; keeps it,
  /// and says where, when it failed. Fixtures overriding TearDown call this last.
  void TearDown() override;

  /// Handles messages until pred() or timeout [s]; returns pred().
  bool handle_until(const std::function<bool()>& pred, double timeout);
  /// Starts wrc-pingd with the given instance and heartbeat period [s].
  std::unique_ptr<ChildProcess> start_pingd(const std::string& instance, double period,
                                            const std::string& log_path = "",
                                            const std::vector<std::string>& extra = {});
  /// Starts `wrc launch` with the shipped launch profile (profiles/launch/default.txt) and the
  /// services named (profile names: "geometry", "contact-onepoint", "dynamics", ...), its output
  /// to log.
  std::unique_ptr<ChildProcess> launch(const std::vector<std::string>& services, const std::string& log) const;
  /// Waits until model/instance heartbeats READY (optionally from a pid other than not_pid).
  bool wait_ready(const std::string& model, const std::string& instance, double timeout,
                  int not_pid = 0);
  /// True inside a private network namespace (not the port fallback).
  static bool in_netns();
  /// Publishes bytes (any content) on channel with a valid authentication trailer, so that they
  /// reach the decoder of the receiving process.
  void publish_signed_bytes(const std::string& channel, std::vector<std::uint8_t> bytes);
  /// A file path in a per-test temporary directory.
  std::string temp_path(const std::string& name) const;

  std::unique_ptr<lcm::LCM> lcm_;
  ChannelNames names_;
  std::unique_ptr<HeartbeatMonitor> monitor_;
  std::unique_ptr<PingClient> client_;
  std::string temp_dir_;
  std::string key_path_;  ///< the test's bus key file
};

}  // namespace wrc::bus::test
