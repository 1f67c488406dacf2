// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Time sources of the bus layer: wall-clock microseconds for message headers, a monotonic
/// clock for deadlines, heartbeat ages and latencies.

#include <cstdint>

namespace wrc::bus {

/// Wall-clock time [us] since the Unix epoch, for header_t::utime.
std::int64_t wall_utime();

/// Monotonic time [s] since an arbitrary origin; use for deadlines and durations only.
double monotonic_seconds();

}  // namespace wrc::bus
