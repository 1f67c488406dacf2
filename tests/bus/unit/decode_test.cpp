// SPDX-License-Identifier: Apache-2.0
// Checked decoding: wrong type, truncated bytes and trailing bytes are reported, never thrown.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "bus/transport/decode.hpp"
#include "wrc/heartbeat_t.hpp"
#include "wrc/ping_request_t.hpp"

namespace {

template <class T>
std::vector<unsigned char> encode(const T& msg) {
  std::vector<unsigned char> bytes(msg.getEncodedSize());
  msg.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

lcm::ReceiveBuffer buffer(std::vector<unsigned char>& bytes) {
  lcm::ReceiveBuffer rbuf{};
  rbuf.data = bytes.data();
  rbuf.data_size = static_cast<uint32_t>(bytes.size());
  return rbuf;
}

wrc::ping_request_t sample_request() {
  wrc::ping_request_t req{};
  req.request_id = 7;
  req.reply_channel = "PING_REPLY.x";
  req.num_payload = 3;
  req.payload = {1, 2, 3};
  return req;
}

// A well-formed message decodes with an empty reason and the right content.
TEST(Decode, AcceptsWellFormedMessage) {
  auto bytes = encode(sample_request());
  wrc::ping_request_t out{};
  EXPECT_EQ(wrc::bus::decode_message(buffer(bytes), out), "");
  EXPECT_EQ(out.request_id, 7);
  EXPECT_EQ(out.payload.size(), 3u);
}

// Another type on the channel is reported as a fingerprint mismatch.
TEST(Decode, ReportsWrongType) {
  wrc::heartbeat_t hb{};
  auto bytes = encode(hb);
  wrc::ping_request_t out{};
  EXPECT_NE(wrc::bus::decode_message(buffer(bytes), out).find("fingerprint mismatch"), std::string::npos);
}

// Cut-off bytes and appended bytes are both reported.
TEST(Decode, ReportsTruncatedAndTrailingBytes) {
  auto bytes = encode(sample_request());
  auto cut = std::vector<unsigned char>(bytes.begin(), bytes.end() - 5);
  wrc::ping_request_t out{};
  EXPECT_NE(wrc::bus::decode_message(buffer(cut), out).find("truncated"), std::string::npos);
  auto tiny = std::vector<unsigned char>{1, 2, 3};
  EXPECT_NE(wrc::bus::decode_message(buffer(tiny), out).find("too short"), std::string::npos);
  bytes.push_back(0);
  EXPECT_NE(wrc::bus::decode_message(buffer(bytes), out).find("trailing"), std::string::npos);
}

// A NUL byte inside a string decodes with LCM's decoder but cannot be encoded again (its encoder
// stops at the first NUL): such a message is refused at decoding, so no handler ever holds a value
// it cannot answer with (wrc-dynamicsd used to exit on re-encoding a run id with a NUL in it).
TEST(Decode, RefusesAStringWithANulByte) {
  auto bytes = encode(sample_request());
  const std::string text = "PING_REPLY.x";
  const auto at = std::search(bytes.begin(), bytes.end(), text.begin(), text.end());
  ASSERT_NE(at, bytes.end());
  wrc::ping_request_t out{};
  ASSERT_EQ(wrc::bus::decode_message(buffer(bytes), out), "");  // intact: accepted
  *(at + 4) = 0;                                                 // "PING\0REPLY.x"
  wrc::ping_request_t bad{};
  const std::string why = wrc::bus::decode_message(buffer(bytes), bad);
  EXPECT_NE(why.find("ping_request_t (" + std::to_string(bytes.size()) + " bytes) does not encode back"),
            std::string::npos)
      << why;
  EXPECT_EQ(bad.reply_channel, "");  // nothing of it stays behind
  EXPECT_EQ(bad.request_id, 0);
}
}  // namespace
