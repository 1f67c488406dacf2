// SPDX-License-Identifier: Apache-2.0
#include "bus/transport/clock.hpp"

#include <chrono>

namespace wrc::bus {

std::int64_t wall_utime() {
  using namespace std::chrono;
  return duration_cast<microseconds>(system_clock::now().time_since_epoch()).count();
}

double monotonic_seconds() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

}  // namespace wrc::bus
