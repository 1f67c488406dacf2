// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Waiting on several LCM objects at once: a process on a bus and on lanes of it
/// (bus/transport/lcm_url.hpp, lane_lcm_url) sleeps until any of them has a message.

#include <lcm/lcm-cpp.hpp>

#include <vector>

namespace wrc::bus {

/// Waits up to timeout_ms [ms] (0: not at all) until one of lcms has a message, then handles one
/// message on each that has one (as lcm::LCM::handleTimeout(0) does). Returns the number of
/// messages handled (0 on timeout), -1 when polling or handling failed (errno tells; EINTR after a
/// signal). With one object it is that object's handleTimeout(timeout_ms).
int handle_any(const std::vector<lcm::LCM*>& lcms, int timeout_ms);

}  // namespace wrc::bus
