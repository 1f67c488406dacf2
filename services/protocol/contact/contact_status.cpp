// SPDX-License-Identifier: Apache-2.0
#include "protocol/contact/contact_status.hpp"

#include "wrc/contact_reply_t.hpp"

namespace wrc::protocol {

namespace {

struct StatusEntry {
  std::int8_t code;
  const char* name;
  int severity;
};

// One row per status of contact_reply_t.lcm.
constexpr StatusEntry kStatuses[] = {
    {wrc::contact_reply_t::OK, "OK", 0},
    {wrc::contact_reply_t::NO_CONTACT, "NO_CONTACT", 1},
    {wrc::contact_reply_t::OUTSIDE_MODEL, "OUTSIDE_MODEL", 2},
    {wrc::contact_reply_t::IMPOSSIBLE_CONFIGURATION, "IMPOSSIBLE_CONFIGURATION", 3},
    {wrc::contact_reply_t::BAD_REQUEST, "BAD_REQUEST", 4},
    {wrc::contact_reply_t::INTERNAL_ERROR, "INTERNAL_ERROR", 5},
};

const StatusEntry* find(std::int8_t status) {
  for (const StatusEntry& e : kStatuses) {
    if (e.code == status) return &e;
  }
  return nullptr;
}

}  // namespace

const char* contact_status_name(std::int8_t status) {
  const StatusEntry* e = find(status);
  return e != nullptr ? e->name : "UNKNOWN";
}

int contact_status_severity(std::int8_t status) {
  const StatusEntry* e = find(status);
  return e != nullptr ? e->severity : 6;
}

}  // namespace wrc::protocol
