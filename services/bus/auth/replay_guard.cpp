// SPDX-License-Identifier: Apache-2.0
#include "bus/auth/replay_guard.hpp"

#include <algorithm>

namespace wrc::bus {

namespace {

bool test_bit(const std::uint64_t* bits, std::uint64_t i) { return ((bits[i / 64] >> (i % 64)) & 1u) != 0; }
void set_bit(std::uint64_t* bits, std::uint64_t i) { bits[i / 64] |= std::uint64_t{1} << (i % 64); }

/// Moves every bit `by` places towards older sequences (bit i becomes bit i + by).
void shift(std::uint64_t* bits, std::size_t words, std::uint64_t by) {
  if (by >= 64 * words) {
    std::fill(bits, bits + words, 0);
    return;
  }
  const std::size_t word_shift = by / 64;
  const unsigned bit_shift = static_cast<unsigned>(by % 64);
  for (std::size_t w = words; w-- > 0;) {
    std::uint64_t v = 0;
    if (w >= word_shift) {
      v = bits[w - word_shift] << bit_shift;
      if (bit_shift != 0 && w >= word_shift + 1) v |= bits[w - word_shift - 1] >> (64 - bit_shift);
    }
    bits[w] = v;
  }
}

}  // namespace

ReplayCheck ReplayGuard::admit(const MessageOrigin& origin, std::int64_t now_utime) {
  const std::int64_t age = now_utime - origin.utime;
  if (age > kMaxAge || age < -kMaxAge) return ReplayCheck::kStale;
  auto it = senders_.find(origin.nonce);
  if (it == senders_.end()) {
    if (senders_.size() >= kMaxSenders) make_room(now_utime);
    Sender fresh;
    fresh.highest = origin.sequence;
    set_bit(fresh.seen, 0);
    fresh.last_utime = now_utime;
    senders_.emplace(origin.nonce, fresh);
    return ReplayCheck::kFresh;
  }
  Sender& s = it->second;
  constexpr std::size_t words = kWindow / 64;
  if (origin.sequence > s.highest) {
    shift(s.seen, words, origin.sequence - s.highest);
    s.highest = origin.sequence;
    set_bit(s.seen, 0);
  } else {
    const std::uint64_t back = s.highest - origin.sequence;
    if (back >= kWindow || test_bit(s.seen, back)) return ReplayCheck::kReplayed;
    set_bit(s.seen, back);
  }
  s.last_utime = now_utime;
  return ReplayCheck::kFresh;
}

void ReplayGuard::make_room(std::int64_t now_utime) {
  auto oldest = senders_.end();
  for (auto it = senders_.begin(); it != senders_.end();) {
    if (now_utime - it->second.last_utime > kMaxAge) {
      it = senders_.erase(it);
      continue;
    }
    if (oldest == senders_.end() || it->second.last_utime < oldest->second.last_utime) oldest = it;
    ++it;
  }
  if (senders_.size() >= kMaxSenders && oldest != senders_.end()) senders_.erase(oldest);
}

}  // namespace wrc::bus
