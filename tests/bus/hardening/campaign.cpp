// SPDX-License-Identifier: Apache-2.0
#include "campaign.hpp"

#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "bus/auth/bus_auth.hpp"
#include "bus/transport/clock.hpp"

namespace wrc::bus::test {
namespace {

void put_be(std::vector<std::uint8_t>& bytes, std::size_t offset, std::uint64_t value, int width) {
  for (int i = 0; i < width; ++i)
    bytes[offset + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(value >> (8 * (width - 1 - i)));
}

std::uint64_t double_bits(double v) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &v, sizeof bits);
  return bits;
}

}  // namespace

Campaign::Campaign(std::vector<Target> targets, std::uint64_t seed, const BusKey& key)
    : targets_(std::move(targets)), random_(seed), id_base_(static_cast<std::int64_t>(seed % 1000) << 40) {
  for (const Target& t : targets_) {
    if (t.templates.empty() || t.predict == nullptr || t.weight <= 0)
      throw std::logic_error("campaign target " + t.channel + " has no template, prediction or weight");
    total_weight_ += t.weight;
    tally_[t.channel];
  }
  BusKey other = key;
  for (auto& b : other.bytes) b = static_cast<std::uint8_t>(b ^ 0x5a);
  other_key_ = std::make_unique<MessageAuth>(other, MessageAuth::random_nonce());
  stale_ = std::make_unique<MessageAuth>(key, MessageAuth::random_nonce());
}

Campaign::~Campaign() = default;

const FieldPoint* Campaign::pick(const Template& t, std::initializer_list<FieldPoint::Kind> kinds) {
  std::vector<const FieldPoint*> fitting;
  for (const FieldPoint& p : t.points)
    for (FieldPoint::Kind k : kinds)
      if (p.kind == k) fitting.push_back(&p);
  return fitting.empty() ? nullptr : fitting[uniform(fitting.size())];
}

void Campaign::mutate(const Target& target, const Template& t, std::vector<std::uint8_t>& bytes) {
  static const std::int32_t kInteresting[] = {-1, 0, 1, -100, INT32_MAX, INT32_MIN, 20000000, 65536, 33, 1 << 24};
  static const double kNumbers[] = {std::numeric_limits<double>::quiet_NaN(),
                                    -std::numeric_limits<double>::quiet_NaN(),
                                    std::numeric_limits<double>::infinity(),
                                    -std::numeric_limits<double>::infinity(),
                                    std::numeric_limits<double>::max(),
                                    -std::numeric_limits<double>::max(),
                                    std::numeric_limits<double>::denorm_min(),
                                    std::numeric_limits<double>::min(),
                                    0.0,
                                    -0.0,
                                    1e300,
                                    -1e-300};
  auto random_byte = [&] { return static_cast<std::uint8_t>(random_()); };
  const int kind = static_cast<int>(uniform(11));
  const FieldPoint* p = nullptr;
  switch (kind) {
    case 0:  // random bytes of random length
      bytes.resize(uniform(400));
      for (auto& b : bytes) b = random_byte();
      kinds_["random bytes"]++;
      return;
    case 1:  // bit flips
      break;
    case 2:  // an int32 anywhere overwritten with an interesting value
      if (bytes.size() >= 12) {
        put_be(bytes, 8 + uniform(bytes.size() - 11), static_cast<std::uint32_t>(kInteresting[uniform(std::size(kInteresting))]), 4);
        kinds_["int32 overwritten"]++;
        return;
      }
      break;
    case 3:  // truncated
      bytes.resize(uniform(bytes.size()));
      kinds_["truncated"]++;
      return;
    case 4:  // extended
      for (std::size_t k = 1 + uniform(64); k > 0; --k) bytes.push_back(random_byte());
      kinds_["extended"]++;
      return;
    case 5:  // bytes replaced in place
      for (std::size_t k = 1 + uniform(16); k > 0; --k) bytes[uniform(bytes.size())] = random_byte();
      kinds_["bytes replaced"]++;
      return;
    case 6:  // a declared count or string length (both int32): huge, negative, zero, one off
      if ((p = pick(t, {FieldPoint::kCount, FieldPoint::kString})) != nullptr) {
        std::uint32_t declared = 0;
        for (std::size_t k = 0; k < 4; ++k) declared = (declared << 8) | bytes[p->offset + k];
        std::uint32_t v = static_cast<std::uint32_t>(kInteresting[uniform(std::size(kInteresting))]);
        if (uniform(3) == 0) v = declared + (uniform(2) == 0 ? 1u : ~0u);
        put_be(bytes, p->offset, v, 4);
        kinds_[p->kind == FieldPoint::kCount ? "count" : "string length"]++;
        return;
      }
      break;
    case 7:  // a NUL byte inside a string
      if ((p = pick(t, {FieldPoint::kString})) != nullptr && p->length > 0) {
        bytes[p->offset + 4 + uniform(p->length)] = 0;
        kinds_["NUL in a string"]++;
        return;
      }
      break;
    case 8:  // NaN, infinity, extreme values in a number
      if ((p = pick(t, {FieldPoint::kNumber})) != nullptr) {
        put_be(bytes, p->offset, double_bits(kNumbers[uniform(std::size(kNumbers))]), 8);
        kinds_["number NaN/inf/extreme"]++;
        return;
      }
      break;
    case 9:  // an out-of-range enum (or boolean, or int8 count), or an extreme id
      if ((p = pick(t, {FieldPoint::kEnum, FieldPoint::kId})) != nullptr) {
        if (p->kind == FieldPoint::kEnum) {
          static const std::uint8_t kBytes[] = {0x80, 0xff, 0x05, 0x11, 0x7f, 0x02, 0x03};
          bytes[p->offset] = kBytes[uniform(std::size(kBytes))];
          kinds_["enum out of range"]++;
        } else {
          static const std::uint64_t kIds[] = {0, ~std::uint64_t{0}, std::uint64_t{1} << 63,
                                               (std::uint64_t{1} << 63) - 1};
          put_be(bytes, p->offset, kIds[uniform(std::size(kIds))], 8);
          kinds_["id extreme"]++;
        }
        return;
      }
      break;
    default: {  // another channel's message: the wrong type
      const Target& other = targets_[uniform(targets_.size())];
      const Template& o = other.templates[uniform(other.templates.size())];
      bytes = o.bytes;
      kinds_[&other == &target ? "own type (unchanged)" : "wrong type"]++;
      return;
    }
  }
  for (std::size_t k = 1 + uniform(8); k > 0; --k) bytes[uniform(bytes.size())] ^= static_cast<std::uint8_t>(1u << uniform(8));
  kinds_["bit flips"]++;
}

Campaign::Datagram Campaign::next() {
  int w = static_cast<int>(uniform(static_cast<std::size_t>(total_weight_)));
  std::size_t index = 0;
  while (w >= targets_[index].weight) w -= targets_[index++].weight;
  const Target& target = targets_[index];
  const Template& t = target.templates[uniform(target.templates.size())];
  ChannelTally& tally = tally_[target.channel];
  ++tally.sent;
  ++serial_;
  Datagram d{&target.channel, t.bytes};
  if (t.id_offset) put_be(d.bytes, *t.id_offset, static_cast<std::uint64_t>(id_base_ + serial_), 8);
  mutate(target, t, d.bytes);

  const std::size_t how = uniform(100);
  std::vector<std::vector<std::uint8_t>>& recent = recent_[target.channel];
  if (how < 80) {  // signed with the bus key: reaches decoding
    const auto prediction = target.predict(d.bytes.data(), d.bytes.size());
    bus_auth().sign(target.channel, d.bytes);
    ++tally.signed_valid;
    ++(prediction ? tally.malformed : tally.decodable);
    if (recent.size() < 16) {
      recent.push_back(d.bytes);
    } else {
      recent[uniform(recent.size())] = d.bytes;
    }
    kinds_["sent signed"]++;
  } else if (how < 88) {
    ++tally.unsigned_;
    kinds_["sent unsigned"]++;
  } else if (how < 94) {
    switch (uniform(3)) {
      case 0:
        other_key_->sign(target.channel, d.bytes);
        kinds_["sent signed with another key"]++;
        break;
      case 1:  // signed for another channel
        bus_auth().sign(target.channel + "X", d.bytes);
        kinds_["sent signed for another channel"]++;
        break;
      default: {  // altered after signing: a byte of the message, the stamp or the MAC (not the magic)
        bus_auth().sign(target.channel, d.bytes);
        d.bytes[uniform(d.bytes.size() - 4)] ^= static_cast<std::uint8_t>(1u << uniform(8));
        kinds_["sent altered after signing"]++;
        break;
      }
    }
    ++tally.bad_signature;
  } else if (how < 97 || recent.empty()) {
    const std::int64_t off = (uniform(2) == 0 ? -1 : 1) * std::int64_t{60'000'000};
    stale_->sign(target.channel, d.bytes, stale_sequence_++, wall_utime() + off);
    ++tally.replayed;
    kinds_["sent stale"]++;
  } else {
    d.bytes = recent[uniform(recent.size())];
    ++tally.replayed;
    kinds_["sent again (replay)"]++;
  }
  return d;
}

DropExpectation Campaign::expected(const std::map<std::string, int>& subscriptions) const {
  DropExpectation e;
  for (const auto& [channel, n] : subscriptions) {
    const auto it = tally_.find(channel);
    if (it == tally_.end()) continue;
    const ChannelTally& c = it->second;
    e.unsigned_ += n * c.unsigned_;
    e.bad_signature += n * c.bad_signature;
    e.replayed += n * c.replayed;
    e.malformed += n * c.malformed;
    e.decodable += n * c.decodable;
  }
  return e;
}

}  // namespace wrc::bus::test
