// SPDX-License-Identifier: Apache-2.0
#include <unistd.h>

#include <atomic>
#include <string>

#include "bus/transport/request_client.hpp"

namespace wrc::bus {

std::string make_client_id(const std::string& program) {
  static std::atomic<int> counter{0};
  return program + "-" + std::to_string(::getpid()) + "-" + std::to_string(++counter);
}

}  // namespace wrc::bus
