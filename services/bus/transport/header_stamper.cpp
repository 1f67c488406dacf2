// SPDX-License-Identifier: Apache-2.0
#include "bus/transport/header_stamper.hpp"

#include <unistd.h>

#include "bus/transport/clock.hpp"

namespace wrc::bus {

void HeaderStamper::stamp(wrc::header_t& header) {
  header.utime = wall_utime();
  header.seq = next_seq_++;
  header.sender = sender_;
}

std::string sender_name(const std::string& program, const std::string& instance) {
  std::string name = program;
  if (!instance.empty()) name += "/" + instance;
  return name + ":" + std::to_string(::getpid());
}

}  // namespace wrc::bus
