// SPDX-License-Identifier: Apache-2.0
#pragma once
// The datagram generator of the signed campaign over every channel (every_channel_campaign_test.cpp).
// A target is one channel with the message type its subscribers decode and templates: valid LCM
// encodings (no trailer) with the offsets of their typed fields (numbers, counts, strings, enums,
// request ids), found by encoding a changed copy. Each datagram is one template of one target
// (chosen by weight), mutated one way and sent one way:
//  - mutations: random bytes, bit flips, an int32 overwritten anywhere, truncation, extension,
//    bytes replaced in place, a huge or wrong declared count or string length, a NUL inside a
//    string, NaN / infinity / extreme values in a number, an out-of-range enum, or another
//    channel's message (wrong type);
//  - sending: signed with the bus key (most, so that they reach the decoders), unsigned, signed
//    with another key or for another channel or altered after signing, signed 60 s off the clock
//    (stale), or an earlier signed datagram of the channel sent again (replayed).
// The campaign tallies per channel what every subscriber must drop, by the kinds the heartbeat
// reports; decoding is predicted with the receivers' own decode_bytes(). Deterministic for a seed
// (apart from what the templates themselves hold).
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "bus/auth/bus_key.hpp"
#include "bus/auth/message_auth.hpp"
#include "bus/transport/decode.hpp"
#include "bus/transport/drop_counters.hpp"

namespace wrc::bus::test {

/// A typed field of a template's encoding.
struct FieldPoint {
  enum Kind { kNumber, kCount, kString, kEnum, kId };
  Kind kind;
  std::size_t offset;      ///< first byte: the double, the int32 count, the string's int32 length, the int8, the int64
  std::size_t length = 0;  ///< kString: its characters
};

/// A valid encoding and its typed fields.
struct Template {
  std::string name;
  std::vector<std::uint8_t> bytes;
  std::vector<FieldPoint> points;
  std::optional<std::size_t> id_offset;  ///< int64 set anew for every datagram (request id, selection number)
};

/// Builds a Template from a message: each field is located by encoding a copy in which only that
/// field changed (the first byte that differs).
template <class T>
class TemplateBuilder {
 public:
  TemplateBuilder(std::string name, T message) : message_(std::move(message)) {
    out_.name = std::move(name);
    out_.bytes = encode(message_);
  }
  /// A double field.
  TemplateBuilder& number(const std::function<double&(T&)>& field) {
    return add(FieldPoint::kNumber, [&](T& m) {
      double& v = field(m);
      v = v >= 0.0 ? -v - 1.0 : -v + 1.0;  // the sign bit: the double's first byte differs
    });
  }
  /// A string field (its characters must not be 254 + 256 k long: the length's last byte changes).
  TemplateBuilder& string(const std::function<std::string&(T&)>& field) {
    std::size_t chars = field(message_).size();
    add(FieldPoint::kString, [&](T& m) { field(m) += "x"; }, 3);
    out_.points.back().length = chars;
    return *this;
  }
  /// An int32 count: grow adds one element to its array (and counts it).
  TemplateBuilder& count(const std::function<void(T&)>& grow) { return add(FieldPoint::kCount, grow, 3); }
  /// An int8 field with a few valid values (enum, boolean).
  TemplateBuilder& enumeration(const std::function<std::int8_t&(T&)>& field) {
    return add(FieldPoint::kEnum, [&](T& m) { field(m) = static_cast<std::int8_t>(field(m) ^ 0x40); });
  }
  /// The int64 request id (or selection number) that every datagram gets anew; also a field.
  TemplateBuilder& id(const std::function<std::int64_t&(T&)>& field) {
    add(FieldPoint::kId, [&](T& m) { field(m) = -field(m) - 1; });
    out_.id_offset = out_.points.back().offset;
    return *this;
  }
  Template build() const { return out_; }

 private:
  static std::vector<std::uint8_t> encode(const T& m) {
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(m.getEncodedSize()));
    m.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
    return bytes;
  }
  TemplateBuilder& add(FieldPoint::Kind kind, const std::function<void(T&)>& change, std::size_t back = 0);

  T message_;
  Template out_;
};

template <class T>
TemplateBuilder<T>& TemplateBuilder<T>::add(FieldPoint::Kind kind, const std::function<void(T&)>& change,
                                            std::size_t back) {
  T changed = message_;
  change(changed);
  const auto a = out_.bytes;
  const auto b = encode(changed);
  std::size_t i = 0;
  while (i < a.size() && i < b.size() && a[i] == b[i]) ++i;
  if (i < back || i >= a.size()) throw std::logic_error(out_.name + ": a field point could not be located");
  out_.points.push_back({kind, i - back});
  return *this;
}

/// What the subscribers of a channel do with a signed payload: nothing (it decodes) or the drop.
using DecodePrediction = std::optional<DropKind> (*)(const std::uint8_t* data, std::size_t size);

template <class T>
std::optional<DropKind> predict_decode(const std::uint8_t* data, std::size_t size) {
  T message{};
  if (auto failure = decode_bytes(data, size, message)) return failure->kind;
  return std::nullopt;
}

/// One channel of the campaign.
struct Target {
  std::string channel;  ///< full bus name
  DecodePrediction predict = nullptr;
  std::vector<Template> templates;
  int weight = 1;  ///< relative share of the datagrams
};

/// Per channel: what was sent and what each of its subscribers must drop.
struct ChannelTally {
  std::int64_t sent = 0;
  std::int64_t signed_valid = 0;   ///< signed with the bus key, fresh, first sight: reach decoding
  std::int64_t malformed = 0;      ///< of those, the ones decoding refuses (wrong type, undecodable, trailing bytes)
  std::int64_t decodable = 0;      ///< of those, the ones reaching the handler
  std::int64_t unsigned_ = 0;      ///< no trailer
  std::int64_t bad_signature = 0;  ///< another key, another channel, altered after signing
  std::int64_t replayed = 0;       ///< stale (60 s off) or sent before
};

/// Drops a process must report (the heartbeat's four counts).
struct DropExpectation {
  std::int64_t unsigned_ = 0, bad_signature = 0, replayed = 0, malformed = 0;
  std::int64_t decodable = 0;  ///< messages its handlers got: a handler failure adds to malformed, at most this many
};

class Campaign {
 public:
  /// key: the bus key of the receivers; datagrams signed with it carry the process's nonce
  /// (bus_auth(), installed with that key).
  Campaign(std::vector<Target> targets, std::uint64_t seed, const BusKey& key);
  ~Campaign();

  struct Datagram {
    const std::string* channel;
    std::vector<std::uint8_t> bytes;  ///< trailer included when signed
  };
  /// The next datagram (and its tally).
  Datagram next();

  const std::map<std::string, ChannelTally>& tally() const { return tally_; }
  /// Datagrams per mutation and per way of sending, for the log.
  const std::map<std::string, std::int64_t>& kinds() const { return kinds_; }
  /// What a process subscribed subscriptions[channel] times to each channel must have dropped.
  DropExpectation expected(const std::map<std::string, int>& subscriptions) const;

 private:
  std::size_t uniform(std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(random_() % n); }
  void mutate(const Target& target, const Template& t, std::vector<std::uint8_t>& bytes);
  const FieldPoint* pick(const Template& t, std::initializer_list<FieldPoint::Kind> kinds);

  std::vector<Target> targets_;
  int total_weight_ = 0;
  std::mt19937_64 random_;
  std::unique_ptr<MessageAuth> other_key_;  ///< another bus key
  std::unique_ptr<MessageAuth> stale_;      ///< the bus key, another nonce, signing 60 s off the clock
  std::uint64_t stale_sequence_ = 1;
  std::int64_t serial_ = 0;
  std::int64_t id_base_;
  std::map<std::string, std::vector<std::vector<std::uint8_t>>> recent_;  ///< signed datagrams per channel, for replays
  std::map<std::string, ChannelTally> tally_;
  std::map<std::string, std::int64_t> kinds_;
};

}  // namespace wrc::bus::test
