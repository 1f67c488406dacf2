// SPDX-License-Identifier: Apache-2.0
#include "bus_fixture.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "bus/auth/bus_auth.hpp"
#include "bus/transport/clock.hpp"
#include "bus/transport/lcm_url.hpp"

namespace wrc::bus::test {

void BusTest::SetUp() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = info->name();  // "Case/1" for a parameterised test: one directory, not two
  std::replace(name.begin(), name.end(), '/', '_');
  temp_dir_ = (std::filesystem::temp_directory_path() / ("wrc-bus-" + name + "-" + std::to_string(::getpid()))).string();
  std::filesystem::create_directories(temp_dir_);
  // A bus key of this test's own: the services it starts find it through $WRC_BUS_KEY.
  key_path_ = temp_path("bus.key");
  std::filesystem::remove(key_path_);
  install_bus_key(read_or_create_bus_key(key_path_));
  ::setenv("WRC_BUS_KEY", key_path_.c_str(), 1);
  lcm_ = std::make_unique<lcm::LCM>(effective_lcm_url(""));
  ASSERT_TRUE(lcm_->good()) << "LCM not usable; run this test through clients/lib/netns.sh";
  monitor_ = std::make_unique<HeartbeatMonitor>(*lcm_, names_.name(channel::kHeartbeat));
  const std::string id = make_client_id("test");
  client_ = std::make_unique<PingClient>(*lcm_, names_.name(channel::kPing),
                                         names_.name(channel::kPingReply, id), id);
}

void BusTest::TearDown() {
  if (temp_dir_.empty()) return;
  if (HasFailure()) {
    std::fprintf(stderr, "kept %s for inspection\n", temp_dir_.c_str());
    return;
  }
  std::error_code ec;
  std::filesystem::remove_all(temp_dir_, ec);
}

bool BusTest::handle_until(const std::function<bool()>& pred, double timeout) {
  const double deadline = monotonic_seconds() + timeout;
  while (!pred() && monotonic_seconds() < deadline) lcm_->handleTimeout(10);
  return pred();
}

std::unique_ptr<ChildProcess> BusTest::start_pingd(const std::string& instance, double period,
                                                   const std::string& log_path,
                                                   const std::vector<std::string>& extra) {
  std::vector<std::string> args{"--instance", instance, "--heartbeat-period", std::to_string(period)};
  args.insert(args.end(), extra.begin(), extra.end());
  return std::make_unique<ChildProcess>(WRC_PINGD_PATH, args, log_path);
}

std::unique_ptr<ChildProcess> BusTest::launch(const std::vector<std::string>& services, const std::string& log) const {
  std::vector<std::string> args{"launch", "--profile", std::string(WRC_SOURCE_DIR) + "/profiles/launch/default.txt",
                                "--build-dir", WRC_TEST_BUILD_DIR};
  args.insert(args.end(), services.begin(), services.end());
  return std::make_unique<ChildProcess>(WRC_CLI_PATH, args, log);
}

bool BusTest::wait_ready(const std::string& model, const std::string& instance, double timeout,
                         int not_pid) {
  return handle_until(
      [&] {
        auto s = monitor_->find(model, instance, monotonic_seconds());
        return s && s->available() && s->last.pid != not_pid;
      },
      timeout);
}

void BusTest::publish_signed_bytes(const std::string& channel, std::vector<std::uint8_t> bytes) {
  bus_auth().sign(channel, bytes);
  lcm_->publish(channel, bytes.data(), static_cast<unsigned>(bytes.size()));
}

bool BusTest::in_netns() {
  const char* mode = std::getenv("WRC_BUS_ISOLATION");
  return mode != nullptr && std::string(mode) == "netns";
}

std::string BusTest::temp_path(const std::string& name) const {
  return (std::filesystem::path(temp_dir_) / name).string();
}

}  // namespace wrc::bus::test
