// SPDX-License-Identifier: Apache-2.0
#pragma once
// Helpers for single-process bus tests over memq://.
#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include <functional>

#include "bus/transport/clock.hpp"

namespace wrc::bus::test {

/// Handles messages until pred() is true or timeout [s] passes; returns pred().
inline bool handle_until(lcm::LCM& lcm, const std::function<bool()>& pred, double timeout = 2.0) {
  const double deadline = monotonic_seconds() + timeout;
  while (!pred() && monotonic_seconds() < deadline) lcm.handleTimeout(10);
  return pred();
}

/// Handles whatever is queued.
inline void drain(lcm::LCM& lcm) {
  while (lcm.handleTimeout(0) > 0) {
  }
}

}  // namespace wrc::bus::test
