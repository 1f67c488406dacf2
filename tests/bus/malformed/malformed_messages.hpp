// SPDX-License-Identifier: Apache-2.0
#pragma once
// The malformed messages of issue 8, built from valid encodings with one field overwritten:
// negative, zero and huge string lengths, array counts of -1, INT32_MAX and 20 000 000, counts
// beyond the bytes, truncations. Shared by the in-process decoder tests and the tests against
// running services (which sign them so that they reach the decoder).
#include <cstdint>
#include <string>
#include <vector>

#include "wrc/contact_query_t.hpp"
#include "wrc/heartbeat_t.hpp"

namespace wrc::bus::test {

struct MalformedMessage {
  std::string name;                 ///< what was overwritten
  std::string channel_base;         ///< HEARTBEAT or CONTACT_QUERY (+ ".onepoint")
  std::vector<std::uint8_t> bytes;  ///< LCM encoding, no trailer
};

template <class T>
std::vector<std::uint8_t> encode_message(const T& message) {
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(message.getEncodedSize()));
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

inline void put_int32(std::vector<std::uint8_t>& bytes, std::size_t offset, std::int32_t value) {
  const auto v = static_cast<std::uint32_t>(value);
  for (int i = 0; i < 4; ++i) bytes[offset + i] = static_cast<std::uint8_t>(v >> (24 - 8 * i));
}

/// A plausible heartbeat and a plausible one-configuration query.
inline wrc::heartbeat_t sample_heartbeat() {
  wrc::heartbeat_t hb{};
  hb.header.sender = "wrc-contactd/x:1";
  hb.model = "onepoint";
  hb.instance = "0";
  hb.state = wrc::heartbeat_t::READY;
  hb.period = 3600.0;
  hb.interface_version = wrc::heartbeat_t::INTERFACE_VERSION;
  return hb;
}

inline wrc::contact_query_t sample_query(int configurations) {
  wrc::contact_query_t q{};
  q.header.sender = "fuzz";
  q.request_id = 1;
  q.reply_channel = "CONTACT_REPLY.fuzz";
  q.model = "onepoint";
  q.shear_modulus = 8.2e10;
  q.poisson_ratio = 0.28;
  q.friction = 0.3;
  q.fastsim_elements = 10;
  q.fastsim_strips = 10;
  q.num_configurations = configurations;
  q.configurations.resize(static_cast<std::size_t>(configurations));
  for (auto& c : q.configurations) {
    c.z = 0.0;
    c.spin_rate = 65.0;
    c.speed = 30.0;
    c.normal_load_left = c.normal_load_right = 1e5;
  }
  return q;
}

/// Every case of the issue, in encodings without a trailer.
inline std::vector<MalformedMessage> malformed_messages() {
  // The first field after the 8-byte fingerprint is header_t: utime, seq (8 bytes each), then
  // the length of the sender string.
  constexpr std::size_t kSenderLength = 8 + 16;
  std::vector<MalformedMessage> out;
  for (std::int32_t length : {-100, 0, -1, INT32_MAX, 20000000}) {
    auto hb = encode_message(sample_heartbeat());
    put_int32(hb, kSenderLength, length);
    out.push_back({"heartbeat sender length " + std::to_string(length), "HEARTBEAT", hb});
    auto q = encode_message(sample_query(1));
    put_int32(q, kSenderLength, length);
    out.push_back({"query sender length " + std::to_string(length), "CONTACT_QUERY.onepoint", q});
  }
  // num_configurations is the last field before the configurations: in an encoding without
  // configurations it is the last 4 bytes.
  const std::size_t count_offset = encode_message(sample_query(0)).size() - 4;
  for (std::int32_t count : {-1, INT32_MAX, 20000000, 2, 33, -2147483647 - 1}) {
    auto q = encode_message(sample_query(1));
    put_int32(q, count_offset, count);
    out.push_back({"num_configurations " + std::to_string(count), "CONTACT_QUERY.onepoint", q});
  }
  auto truncated = encode_message(sample_query(2));
  truncated.resize(truncated.size() - 9);
  out.push_back({"query truncated by 9 bytes", "CONTACT_QUERY.onepoint", truncated});
  auto longer = encode_message(sample_query(1));
  longer.insert(longer.end(), {1, 2, 3});
  out.push_back({"query with 3 trailing bytes", "CONTACT_QUERY.onepoint", longer});
  out.push_back({"4 bytes", "CONTACT_QUERY.onepoint", {0xde, 0xad, 0xbe, 0xef}});
  out.push_back({"empty", "HEARTBEAT", {}});
  return out;
}

}  // namespace wrc::bus::test
