// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Guarded decoding of LCM-encoded bytes: never a crash, never more memory than a small multiple
/// of the message size. LCM's generated decoders throw from std::string on a negative or zero
/// string length and resize arrays to whatever count the message declares; here every decode
/// runs inside an AllocationBudget (bus/transport/allocation_budget.hpp) of kDecodeBudgetFactor times the
/// size plus kDecodeBudgetSlack, and every exception becomes a reason. Used by the guarded
/// receive path (bus/transport/guarded_subscription.hpp) for every subscription of every process.

#include <lcm/lcm-cpp.hpp>

#include <cstdint>
#include <cstring>
#include <exception>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include "bus/transport/allocation_budget.hpp"
#include "bus/transport/drop_counters.hpp"
#include "bus/transport/string_limits.hpp"

namespace wrc::bus {

/// [-] a message of n bytes may allocate at most kDecodeBudgetFactor * n + kDecodeBudgetSlack
/// bytes while it is decoded. An LCM element takes at least one byte on the wire and at most
/// 32 bytes in memory (an empty string: 5 bytes encoded, one std::string), so 16 covers
/// every honest message with room to spare.
inline constexpr std::size_t kDecodeBudgetFactor = 16;
/// [B] allowance for the fixed allocations of small messages.
inline constexpr std::size_t kDecodeBudgetSlack = 4096;

/// Why bytes did not decode.
struct DecodeFailure {
  DropKind kind;       ///< kWrongType, kUndecodable or kTrailingBytes
  std::string reason;  ///< one line naming the type and what was wrong
};

/// Decodes data[0..size) into msg. Returns nothing on success (every byte used, every string
/// within its limit, and the message encodes back to exactly these bytes), else why not.
template <class Message>
std::optional<DecodeFailure> decode_bytes(const void* data, std::size_t size, Message& msg) {
  const std::string type = Message::getTypeName();
  if (size < 8) {
    return DecodeFailure{DropKind::kUndecodable, std::to_string(size) + " bytes are too short for a " + type};
  }
  const auto* bytes = static_cast<const unsigned char*>(data);
  std::uint64_t fingerprint = 0;
  for (int i = 0; i < 8; ++i) fingerprint = (fingerprint << 8) | bytes[i];
  if (fingerprint != static_cast<std::uint64_t>(Message::getHash())) {
    return DecodeFailure{DropKind::kWrongType,
                         "fingerprint mismatch: not a " + type + " (other type or other interface version)"};
  }
  if (size > static_cast<std::size_t>(INT32_MAX)) {
    return DecodeFailure{DropKind::kUndecodable, type + " of " + std::to_string(size) + " bytes is too large"};
  }
  const int length = static_cast<int>(size);
  int used = -1;
  std::string failure;
  try {
    AllocationBudget budget(kDecodeBudgetFactor * size + kDecodeBudgetSlack);
    used = msg.decode(data, 0, length);
  } catch (const std::bad_alloc&) {
    failure = "declares more elements than its " + std::to_string(size) + " bytes can hold";
  } catch (const std::exception& e) {
    failure = std::string("inconsistent lengths (") + e.what() + ")";
  } catch (...) {
    failure = "decoder failed";
  }
  if (!failure.empty() || used < 0) {
    msg = Message();  // nothing of a half-decoded message stays behind
    const std::string what = type + " (" + std::to_string(size) + " bytes)";
    return DecodeFailure{DropKind::kUndecodable,
                         failure.empty() ? "truncated or corrupt " + what : what + ": " + failure};
  }
  if (used != length) {
    return DecodeFailure{DropKind::kTrailingBytes, type + " has " + std::to_string(length - used) +
                                                       " trailing bytes (" + std::to_string(size) + " received, " +
                                                       std::to_string(used) + " decoded)"};
  }
  // Every string within its limit (bus/transport/string_limits.hpp), before anything else reads it.
  if (auto why = string_limit_violation(msg)) {
    msg = Message();
    return DecodeFailure{DropKind::kUndecodable, type + " (" + std::to_string(size) + " bytes): " + *why};
  }
  // What was read must encode back to the same bytes: LCM's decoder keeps a NUL byte inside a
  // string, but its encoder stops at the first NUL (strlen), so such a message could be read but
  // not answered, echoed in a status or logged to an LCM log. Refused here, every field of every
  // type is one that re-encodes.
  thread_local std::vector<unsigned char> again;  // reused: no allocation per received message
  again.resize(size);
  if (msg.encode(again.data(), 0, length) != length || std::memcmp(again.data(), bytes, size) != 0) {
    msg = Message();
    return DecodeFailure{DropKind::kUndecodable, type + " (" + std::to_string(size) +
                                                     " bytes) does not encode back to the bytes received "
                                                     "(a string with a NUL byte?)"};
  }
  return std::nullopt;
}

/// decode_bytes() of a whole receive buffer (no trailer). Returns an empty string on success,
/// otherwise the one-line reason.
template <class Message>
std::string decode_message(const lcm::ReceiveBuffer& rbuf, Message& msg) {
  auto failure = decode_bytes(rbuf.data, rbuf.data_size, msg);
  return failure ? failure->reason : std::string();
}

}  // namespace wrc::bus
