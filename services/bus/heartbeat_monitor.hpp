#pragma once
/// @file
/// Listens to heartbeats and keeps the table of services on the bus: alive while heartbeats
/// arrive, dead after `missed_periods` (default 3) periods without one.

#include <lcm/lcm-cpp.hpp>

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bus/rejection_log.hpp"
#include "wrc/heartbeat_t.hpp"

namespace wrc::bus {

/// What the monitor knows about one service (model + instance).
struct ServiceStatus {
  wrc::heartbeat_t last;         ///< last heartbeat received
  double last_seen = 0.0;        ///< [s] monotonic time it arrived
  double first_seen = 0.0;       ///< [s] monotonic time of the first heartbeat
  std::int64_t heartbeats = 0;   ///< heartbeats received
  bool alive = false;            ///< heartbeats still arriving (not yet missed_periods late)
  /// Alive, READY and built with this interface version: may be sent requests.
  bool available() const {
    return alive && last.state == wrc::heartbeat_t::READY &&
           last.interface_version == wrc::heartbeat_t::INTERFACE_VERSION;
  }
};

/// Heartbeat listener. Dispatch happens in the owner's LCM handle loop.
class HeartbeatMonitor {
 public:
  /// channel: full bus name of the heartbeat channel. missed_periods > 0.
  HeartbeatMonitor(lcm::LCM& lcm, std::string channel, double missed_periods = 3.0);
  ~HeartbeatMonitor();
  HeartbeatMonitor(const HeartbeatMonitor&) = delete;
  HeartbeatMonitor& operator=(const HeartbeatMonitor&) = delete;

  /// Every service ever heard of, alive flags evaluated at monotonic time now [s], sorted by
  /// model then instance.
  std::vector<ServiceStatus> services(double now) const;
  /// One service, if heard of.
  std::optional<ServiceStatus> find(const std::string& model, const std::string& instance,
                                    double now) const;
  /// Heartbeats that did not decode.
  std::int64_t rejected() const { return rejections_.count(); }

 private:
  void on_heartbeat(const lcm::ReceiveBuffer* rbuf, const std::string& channel);
  ServiceStatus evaluate(ServiceStatus status, double now) const;

  lcm::LCM& lcm_;
  std::string channel_;
  double missed_periods_;
  lcm::Subscription* subscription_ = nullptr;
  RejectionLog rejections_;
  std::map<std::pair<std::string, std::string>, ServiceStatus> table_;
};

}  // namespace wrc::bus
