// SPDX-License-Identifier: Apache-2.0
#include "bus/transport/lcm_url.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>

namespace wrc::bus {
namespace {

// LCM 1.3.1's default group and port (lcm_udpm.c), with ttl=0 as its default too.
constexpr const char* kDefaultBus = "udpm://239.255.76.67:7667?ttl=0";

// [B] the kernel's cap on a socket receive buffer; 0 when it cannot be read.
long receive_buffer_cap() {
  std::ifstream in("/proc/sys/net/core/rmem_max");
  long rmem_max = 0;
  if (!(in >> rmem_max) || rmem_max <= 0) return 0;
  return rmem_max;
}

}  // namespace

std::string effective_lcm_url(const std::string& url) {
  std::string chosen = url;
  if (chosen.empty()) {
    const char* env = std::getenv("LCM_DEFAULT_URL");
    chosen = env != nullptr && *env != '\0' ? env : kDefaultBus;
  }
  if (chosen.rfind("udpm://", 0) != 0 || chosen.find("recv_buf_size=") != std::string::npos) return chosen;
  const long cap = receive_buffer_cap();
  if (cap == 0) return chosen;
  const char separator = chosen.find('?') == std::string::npos ? '?' : '&';
  return chosen + separator + "recv_buf_size=" + std::to_string(std::min(kWantedReceiveBufferBytes, cap));
}

}  // namespace wrc::bus
