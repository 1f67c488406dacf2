// SPDX-License-Identifier: Apache-2.0
// Decoding cannot crash or balloon: every malformed message of issue 8 is reported as a reason,
// within an allocation budget of a small multiple of its size; the process's peak memory stays
// where it was.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <new>
#include <vector>

#include "../malformed/malformed_messages.hpp"
#include "bus/transport/allocation_budget.hpp"
#include "bus/transport/decode.hpp"

namespace {
using namespace wrc::bus;

long peak_rss_kib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

TEST(GuardedDecode, MalformedMessagesAreReasonsNotCrashes) {
  const long before = peak_rss_kib();
  for (const auto& m : test::malformed_messages()) {
    SCOPED_TRACE(m.name);
    std::optional<DecodeFailure> failure;
    if (m.channel_base == "HEARTBEAT") {
      wrc::heartbeat_t hb;
      failure = decode_bytes(m.bytes.data(), m.bytes.size(), hb);
    } else {
      wrc::contact_query_t q;
      failure = decode_bytes(m.bytes.data(), m.bytes.size(), q);
      if (!failure) {
        EXPECT_EQ(static_cast<std::size_t>(q.num_configurations), q.configurations.size());
      }
    }
    ASSERT_TRUE(failure.has_value()) << "decoded";
    EXPECT_FALSE(failure->reason.empty());
  }
  EXPECT_LT(peak_rss_kib() - before, 20 * 1024) << "decoding malformed messages raised the peak memory";
}

TEST(GuardedDecode, HugeCountIsRefusedByTheBudget) {
  auto bytes = test::encode_message(test::sample_query(1));
  const std::size_t count_offset = test::encode_message(test::sample_query(0)).size() - 4;
  test::put_int32(bytes, count_offset, 20000000);
  wrc::contact_query_t q;
  const auto failure = decode_bytes(bytes.data(), bytes.size(), q);
  ASSERT_TRUE(failure.has_value());
  EXPECT_EQ(failure->kind, DropKind::kUndecodable);
  EXPECT_NE(failure->reason.find("declares more elements than its"), std::string::npos) << failure->reason;
  EXPECT_TRUE(q.configurations.empty());
}

TEST(GuardedDecode, ValidMessagesDecodeWithTheirArrays) {
  const auto q = test::sample_query(32);
  const auto bytes = test::encode_message(q);
  wrc::contact_query_t back;
  EXPECT_FALSE(decode_bytes(bytes.data(), bytes.size(), back).has_value());
  EXPECT_EQ(back.configurations.size(), 32u);
  EXPECT_EQ(back.reply_channel, q.reply_channel);
}

TEST(AllocationBudget, LimitsNewInsideTheScopeOnly) {
  {
    AllocationBudget budget(1000);
    std::vector<char> fits(500);
    EXPECT_THROW(std::vector<char>(600), std::bad_alloc);
    EXPECT_TRUE(budget.exceeded());
    EXPECT_EQ(budget.remaining(), 500u);
    {
      AllocationBudget inner(10);
      EXPECT_THROW(std::vector<char>(100), std::bad_alloc);
    }
    std::vector<char> after_inner(400);
  }
  std::vector<char> unlimited(10 * 1000 * 1000);
  EXPECT_EQ(unlimited.size(), 10u * 1000 * 1000);
}

}  // namespace
