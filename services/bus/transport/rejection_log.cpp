// SPDX-License-Identifier: Apache-2.0
#include "bus/transport/rejection_log.hpp"

#include <iostream>

#include "bus/transport/clock.hpp"

namespace wrc::bus {

void RejectionLog::reject(const std::string& channel, const std::string& reason) {
  ++count_;
  const double now = monotonic_seconds();
  if (window_start_ < 0.0 || now - window_start_ >= 1.0) {
    if (suppressed_ > 0) {
      std::cerr << who_ << ": " << suppressed_ << " further rejections not logged\n";
    }
    window_start_ = now;
    logged_in_window_ = 0;
    suppressed_ = 0;
  }
  if (logged_in_window_ < burst_) {
    ++logged_in_window_;
    std::cerr << who_ << ": rejected message on " << channel << ": " << reason << " (rejection #"
              << count_ << ")\n";
  } else {
    ++suppressed_;
  }
}

}  // namespace wrc::bus
