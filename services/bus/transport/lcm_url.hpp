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

}  // namespace wrc::bus
