// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The heartbeat activity of a process that answers requests (heartbeat_t::activity): what it
/// serves and how many requests it answered per second since the previous heartbeat.

#include <cstdint>
#include <functional>
#include <string>

namespace wrc::bus {

class ServingActivity {
 public:
  /// what: e.g. "onepoint queries"; answered: the server's count of answered requests.
  ServingActivity(std::string what, std::function<std::int64_t()> answered);
  /// "serving <what>, <rate> per second" [1/s] over the time since the previous call (or since
  /// construction).
  std::string operator()();

 private:
  std::string what_;
  std::function<std::int64_t()> answered_;
  std::int64_t last_answered_ = 0;
  double last_time_;
};

}  // namespace wrc::bus
