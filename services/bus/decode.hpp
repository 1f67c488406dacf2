#pragma once
/// @file
/// Checked decoding of raw LCM buffers. LCM 1.3.1's typed subscriptions print an error and drop
/// a message silently when it does not decode; decoding ourselves lets every failure be counted.

#include <lcm/lcm-cpp.hpp>

#include <string>

namespace wrc::bus {

/// Decodes rbuf into msg. Returns an empty string on success, otherwise a one-line reason:
/// wrong type (fingerprint mismatch), truncated/undecodable bytes, or trailing bytes.
template <class Message>
std::string decode_message(const lcm::ReceiveBuffer& rbuf, Message& msg) {
  const int size = static_cast<int>(rbuf.data_size);
  if (size < 8) return "message of " + std::to_string(size) + " bytes is too short for a " +
                       Message::getTypeName();
  const int used = msg.decode(rbuf.data, 0, size);
  if (used < 0) {
    const auto* bytes = static_cast<const unsigned char*>(rbuf.data);
    std::uint64_t fingerprint = 0;
    for (int i = 0; i < 8; ++i) fingerprint = (fingerprint << 8) | bytes[i];
    if (fingerprint != static_cast<std::uint64_t>(Message::getHash())) {
      return "fingerprint mismatch: not a " + std::string(Message::getTypeName()) +
             " (other type or other interface version)";
    }
    return "truncated or corrupt " + std::string(Message::getTypeName()) + " (" +
           std::to_string(size) + " bytes)";
  }
  if (used != size) {
    return std::string(Message::getTypeName()) + " has " + std::to_string(size - used) +
           " trailing bytes (" + std::to_string(size) + " received, " + std::to_string(used) +
           " decoded)";
  }
  return {};
}

}  // namespace wrc::bus
