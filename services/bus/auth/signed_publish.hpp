// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Publishing a wrc message: its LCM encoding followed by the authentication trailer
/// (bus/auth/message_auth.hpp) under the process's bus key (bus/auth/bus_auth.hpp). Every message a wrc
/// process sends goes through publish_signed().

#include <lcm/lcm-cpp.hpp>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "bus/auth/bus_auth.hpp"
#include "bus/transport/string_limits.hpp"

namespace wrc::bus {

/// Signs the encoding of message under this process's key into bytes (cleared first). A free-text
/// string over its limit (bus/transport/string_limits.hpp) is sent cut to it.
/// @throws std::invalid_argument naming the field when an identifier is over its limit.
template <class Message>
void encode_signed(const std::string& channel, const Message& message, std::vector<std::uint8_t>& bytes) {
  if (string_limit_violation(message)) {
    Message cut = message;
    if (const auto why = clip_text(cut))
      throw std::invalid_argument(std::string("sending a ") + Message::getTypeName() + " on " + channel + ": " + *why);
    encode_signed(channel, cut, bytes);
    return;
  }
  const int size = message.getEncodedSize();
  bytes.resize(static_cast<std::size_t>(size));
  if (message.encode(bytes.data(), 0, size) != size) {
    throw std::runtime_error(std::string("encoding a ") + Message::getTypeName() + " for " + channel + " failed");
  }
  bus_auth().sign(channel, bytes);
}

/// Publishes message on channel, signed. Returns LCM's publish result (0 = handed to the bus).
/// Throws std::logic_error when no bus key is loaded.
template <class Message>
int publish_signed(lcm::LCM& lcm, const std::string& channel, const Message& message) {
  thread_local std::vector<std::uint8_t> bytes;  // reused: no allocation per message
  encode_signed(channel, message, bytes);
  return lcm.publish(channel, bytes.data(), static_cast<unsigned>(bytes.size()));
}

}  // namespace wrc::bus
