// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The LCM URL a wrc process opens. Every process on a udpm bus receives every datagram of the
/// multicast group (LCM filters channels after reading them), so a process that is descheduled
/// for a few milliseconds while a run's contact traffic flows (thousands of queries and replies a
/// second) overflows the kernel's default 208 KiB socket buffer and loses whatever arrives next,
/// e.g. a run's states (what was lost where: docs/performance.md). wrc therefore asks for a larger receive buffer whenever the user names no URL.

#include <string>

namespace wrc::bus {

/// [B] receive buffer wrc asks for on LCM's default bus (capped by the kernel's
/// net.core.rmem_max, which an administrator may raise).
inline constexpr long kWantedReceiveBufferBytes = 4L << 20;

/// The URL to open: `url`, else $LCM_DEFAULT_URL, else LCM's default bus (group 239.255.76.67,
/// port 7667, ttl=0); a udpm URL that sets no recv_buf_size gets recv_buf_size =
/// min(kWantedReceiveBufferBytes, net.core.rmem_max), so LCM never warns about a buffer the
/// kernel would refuse. Other providers (memq, file, tcpq) and URLs that set it are kept as given.
std::string effective_lcm_url(const std::string& url);

/// [-] lanes a bus may have: its port + 1 ... + kMaxLanes are kept for them.
inline constexpr int kMaxLanes = 8;

/// The URL of lane `lane` (1..kMaxLanes) of the bus at `url` (as effective_lcm_url gives it): the
/// same multicast group and options on port + lane (LCM's default port 7667 when the URL names
/// none). A lane is a multicast group of its own: only the processes that open it read its
/// datagrams, where every process of the bus reads every datagram of the bus (and a sender's
/// kernel delivers each copy within its send call). Empty for providers other than udpm (memq,
/// file, tcpq): their traffic stays on the bus. Throws std::invalid_argument for a lane outside
/// 1..kMaxLanes or a udpm URL whose port is not a number from 1 to 65535 - kMaxLanes.
std::string lane_lcm_url(const std::string& url, int lane);

}  // namespace wrc::bus
