// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// What a wrc process waits on and reads messages from: an LCM object (the bus, read in LCM's
/// receive thread) or a lane read in the caller's own thread (bus/transport/lane_socket.hpp).
/// Subscriptions, request clients and servers and the service loop take either through this one
/// handle; it owns nothing, and what it refers to must outlive it.

#include <lcm/lcm-cpp.hpp>

#include "bus/transport/lane_socket.hpp"

namespace wrc::bus {

class Inbox {
 public:
  // Converting on purpose: every place that takes an LCM object takes a lane socket as well.
  Inbox(lcm::LCM& lcm) : lcm_(&lcm) {}          // NOLINT(google-explicit-constructor)
  Inbox(LaneSocket& lane) : lane_(&lane) {}     // NOLINT(google-explicit-constructor)

  /// The LCM object, or nullptr for a lane socket.
  lcm::LCM* lcm() const { return lcm_; }
  /// The lane socket, or nullptr for an LCM object.
  LaneSocket* lane() const { return lane_; }
  /// The descriptor that is readable when a message waits (for poll()).
  int fileno() const { return lcm_ != nullptr ? lcm_->getFileno() : lane_->fileno(); }
  /// Waits up to timeout_ms [ms] for a message and handles it (lcm::LCM::handleTimeout, or
  /// LaneSocket::handle_timeout): > 0 handled, 0 none in time, < 0 failed (errno tells).
  int handle_timeout(int timeout_ms) const {
    return lcm_ != nullptr ? lcm_->handleTimeout(timeout_ms) : lane_->handle_timeout(timeout_ms);
  }

 private:
  lcm::LCM* lcm_ = nullptr;
  LaneSocket* lane_ = nullptr;
};

}  // namespace wrc::bus
