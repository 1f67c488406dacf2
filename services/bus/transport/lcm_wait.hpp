// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Waiting on several inboxes at once: a process on a bus and on lanes of it
/// (bus/transport/lcm_url.hpp, lane_lcm_url) sleeps until any of them has a message.

#include <vector>

#include "bus/transport/inbox.hpp"

namespace wrc::bus {

/// Waits up to timeout_ms [ms] (0: not at all) until one of inboxes has a message, then handles
/// one message on each that has one (as lcm::LCM::handleTimeout(0) does). Returns the number of
/// messages handled (0 on timeout), -1 when polling or handling failed (errno tells; EINTR after a
/// signal). With one inbox it is that inbox's handle_timeout(timeout_ms).
int handle_any(const std::vector<Inbox>& inboxes, int timeout_ms);

}  // namespace wrc::bus
