// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Fills the common header_t of outgoing messages: time, sequence number, sender.

#include <cstdint>
#include <string>

#include "wrc/header_t.hpp"

namespace wrc::bus {

/// One stamper per sending stream (one channel of one process): seq counts from 0 without gaps,
/// so that receivers can detect lost messages.
class HeaderStamper {
 public:
  /// sender: "<program>/<instance>:<pid>" (see sender_name()).
  explicit HeaderStamper(std::string sender) : sender_(std::move(sender)) {}

  /// Sets utime [us] to now, seq to the next number and sender.
  void stamp(wrc::header_t& header);
  /// The sender name written into headers.
  const std::string& sender() const { return sender_; }

 private:
  std::string sender_;
  std::int64_t next_seq_ = 0;
};

/// "<program>/<instance>:<pid>" of this process (instance omitted when empty).
std::string sender_name(const std::string& program, const std::string& instance);

}  // namespace wrc::bus
