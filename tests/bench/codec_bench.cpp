// SPDX-License-Identifier: Apache-2.0
// What a wrc process spends on one contact query and its reply besides the network, in-process:
//   StringLimits : the string-limit check alone (visit_strings through its std::function visitor)
//   DecodeBytes  : decode_bytes() in full (LCM decode under the allocation budget, string limits,
//                  the re-encoding check)
//   EncodeSigned : encode_signed() (string limits, LCM encode, HMAC-SHA-256 trailer)
// for a one-configuration contact_query_t and a two-patch contact_reply_t. Compare StringLimits
// with DecodeBytes to see what the visitor costs on the hot path. Run: build/tests/bench_codec
#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

#include "bench_bus_key.hpp"
#include "bus/auth/message_auth.hpp"
#include "bus/auth/signed_publish.hpp"
#include "bus/transport/decode.hpp"
#include "bus/transport/string_limits.hpp"
#include "wrc/contact_query_t.hpp"
#include "wrc/contact_reply_t.hpp"

namespace {

wrc::contact_query_t query_message() {
  wrc::contact_query_t q{};
  q.header.sender = "wrc-dynamicsd/default:12345";
  q.client_id = "wrc-dynamicsd-12345";
  q.reply_channel = "CONTACT_REPLY_12345";
  q.model = "spline";
  q.instance = "default";
  q.geometry_key = std::string(64, 'a');
  q.num_configurations = 1;
  q.configurations.resize(1);
  return q;
}

wrc::contact_reply_t reply_message() {
  wrc::contact_reply_t r{};
  r.header.sender = "wrc-contactd/spline:23456";
  r.model = "spline";
  r.instance = "default";
  r.geometry_key = std::string(64, 'a');
  r.model_hash = std::string(64, 'b');
  r.num_configurations = 1;
  r.results.resize(1);
  r.results[0].num_patches = 2;
  r.results[0].patches.resize(2);
  return r;
}

template <class Message>
void StringLimits(benchmark::State& state, Message m) {
  for (auto _ : state) benchmark::DoNotOptimize(wrc::bus::string_limit_violation(m));
}

template <class Message>
void DecodeBytes(benchmark::State& state, Message m) {
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(m.getEncodedSize()));
  m.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  Message back;
  for (auto _ : state) benchmark::DoNotOptimize(wrc::bus::decode_bytes(bytes.data(), bytes.size(), back));
  state.counters["bytes"] = static_cast<double>(bytes.size());
}

template <class Message>
void EncodeSigned(benchmark::State& state, Message m) {
  wrc::bench::use_temporary_bus_key();
  std::vector<std::uint8_t> bytes;
  for (auto _ : state) {
    wrc::bus::encode_signed("CONTACT", m, bytes);
    benchmark::DoNotOptimize(bytes.data());
  }
}

BENCHMARK_CAPTURE(StringLimits, query, query_message());
BENCHMARK_CAPTURE(DecodeBytes, query, query_message());
BENCHMARK_CAPTURE(EncodeSigned, query, query_message());
BENCHMARK_CAPTURE(StringLimits, reply, reply_message());
BENCHMARK_CAPTURE(DecodeBytes, reply, reply_message());
BENCHMARK_CAPTURE(EncodeSigned, reply, reply_message());

}  // namespace

BENCHMARK_MAIN();
