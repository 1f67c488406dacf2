// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Which contact queries this instance answers, so that two instances of one model never both
/// answer one query:
///  - a query whose `instance` field is set is answered by that instance only (the normal case:
///    a client picks one READY instance of the model from the heartbeats and addresses it);
///  - a query with an empty `instance` ("any") is answered by the LEADER of the model only: the
///    instance with the smallest name among the instances of the model that this process hears
///    alive and READY on HEARTBEAT, itself included. Every instance hears the same heartbeats, so
///    exactly one answers; only while an instance is appearing or dying can the views differ for
///    a moment, and then a reply is duplicated (the client drops it by request id) or missing (the
///    client's retry covers it).

#include <lcm/lcm-cpp.hpp>

#include <string>

#include "bus/service/heartbeat_monitor.hpp"
#include "wrc/contact_query_t.hpp"

namespace wrc::contactd {

class InstanceFilter {
 public:
  /// heartbeat_channel: full bus name of HEARTBEAT. Listens on lcm (dispatched by the service loop).
  InstanceFilter(lcm::LCM& lcm, const std::string& heartbeat_channel, std::string model, std::string instance)
      : monitor_(lcm, heartbeat_channel), model_(std::move(model)), instance_(std::move(instance)) {}

  /// True when this instance answers query.
  bool answers(const wrc::contact_query_t& query) const;
  /// True when this instance answers queries addressed to any instance (now).
  bool is_leader() const;

 private:
  bus::HeartbeatMonitor monitor_;
  std::string model_;
  std::string instance_;
};

}  // namespace wrc::contactd
