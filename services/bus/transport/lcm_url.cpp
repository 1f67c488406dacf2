// SPDX-License-Identifier: Apache-2.0
#include "bus/transport/lcm_url.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>

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

std::string lane_lcm_url(const std::string& url, int lane) {
  if (lane < 1 || lane > kMaxLanes)
    throw std::invalid_argument("lane " + std::to_string(lane) + " is not between 1 and " + std::to_string(kMaxLanes));
  const std::string scheme = "udpm://";
  if (url.rfind(scheme, 0) != 0) return {};
  const std::size_t options = std::min(url.find('?'), url.size());
  const std::size_t colon = url.find(':', scheme.size());
  const bool has_port = colon != std::string::npos && colon < options;
  const std::string host = url.substr(scheme.size(), (has_port ? colon : options) - scheme.size());
  long port = 7667;  // LCM 1.3.1's default port (lcm_udpm.c)
  if (has_port) {
    const std::string text = url.substr(colon + 1, options - colon - 1);
    std::size_t used = 0;
    try {
      port = std::stol(text, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != text.size() || text.empty()) throw std::invalid_argument("port '" + text + "' of '" + url + "' is not a number");
  }
  if (port < 1 || port > 65535 - kMaxLanes)
    throw std::invalid_argument("port " + std::to_string(port) + " of '" + url + "' leaves no room for lanes (1 to " +
                                std::to_string(65535 - kMaxLanes) + ")");
  return scheme + host + ":" + std::to_string(port + lane) + url.substr(options);
}

}  // namespace wrc::bus
