// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The statuses of a contact reply (contact_reply_t.lcm) by name and severity: the one table used
/// by the contact service (worst-of over a batch, logs) and by `wrc query` (error lines).

#include <cstdint>

namespace wrc::protocol {

/// Name of a contact_reply_t status: "OK", "BAD_REQUEST", "NO_CONTACT", "IMPOSSIBLE_CONFIGURATION",
/// "INTERNAL_ERROR", "OUTSIDE_MODEL"; "UNKNOWN" for any other code.
const char* contact_status_name(std::int8_t status);

/// Severity rank for "worst of" over a batch: OK 0 < NO_CONTACT 1 < OUTSIDE_MODEL 2 <
/// IMPOSSIBLE_CONFIGURATION 3 < BAD_REQUEST 4 < INTERNAL_ERROR 5; unknown codes rank highest (6).
int contact_status_severity(std::int8_t status);

}  // namespace wrc::protocol
