// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The one receive path of every wrc subscription. For each datagram, in this order:
///  1. size: at most max_bytes (default kDefaultMaxMessageBytes), at least a trailer;
///  2. authentication: the trailer's HMAC under the bus key (bus/auth/message_auth.hpp), then
///     freshness and first sight of (nonce, sequence) (bus/auth/replay_guard.hpp);
///  3. decoding inside an allocation budget, every exception caught (bus/transport/decode.hpp);
///  4. the handler, its exceptions caught too.
/// A message failing a step is dropped, counted by kind and logged rate-limited
/// (bus/transport/drop_counters.hpp); it never reaches the handler and never ends the process.
/// Used through RequestServer, RequestClient, HeartbeatMonitor, or directly for other channels.

#include <lcm/lcm-cpp.hpp>

#include <cstdint>
#include <exception>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>

#include "bus/auth/bus_auth.hpp"
#include "bus/auth/replay_guard.hpp"
#include "bus/transport/channels.hpp"
#include "bus/transport/clock.hpp"
#include "bus/transport/decode.hpp"
#include "bus/transport/drop_counters.hpp"
#include "bus/transport/inbox.hpp"

namespace wrc::bus {

/// [B] largest message a subscription accepts unless told otherwise (inline spline models are
/// up to 60 kB; bigger data travel as files, see docs/deployment.md).
inline constexpr std::size_t kDefaultMaxMessageBytes = 1 << 20;

/// What the receive path knows about an accepted message besides its content.
struct ReceivedMessage {
  const std::string* channel = nullptr;  ///< channel it arrived on
  MessageOrigin origin;                  ///< sender nonce, sequence and signing time (verified)
  std::size_t bytes = 0;                 ///< [B] datagram size, trailer included
  std::int64_t receipt_utime = 0;        ///< [us] when LCM received it (lcm::ReceiveBuffer::recv_utime, wall clock)
};

/// A subscription to one channel (exact name, not a pattern) delivering decoded, authenticated
/// messages of one type. Dispatch happens where the owner reads its inbox (an LCM object's handle
/// loop, or a lane socket read in the owner's thread).
template <class Message>
class GuardedSubscription {
 public:
  using Handler = std::function<void(const Message&, const ReceivedMessage&)>;
  /// Told of each drop (e.g. a request server counting rejected requests).
  using DropObserver = std::function<void(DropKind)>;

  /// who: component named in drop log lines. queue_capacity: LCM's per-subscription queue (a lane
  /// socket queues in the kernel's receive buffer). Throws std::runtime_error when the
  /// subscription fails, std::logic_error without a bus key.
  GuardedSubscription(Inbox on, std::string channel, std::string who, Handler handler,
                      int queue_capacity = 1000, std::size_t max_bytes = kDefaultMaxMessageBytes)
      : on_(on), channel_(std::move(channel)), who_(std::move(who)), handler_(std::move(handler)),
        max_bytes_(max_bytes), auth_(bus_auth()) {
    if (!handler_) throw std::runtime_error("subscription to '" + channel_ + "' has no handler");
    if (on_.lane() != nullptr) {
      on_.lane()->subscribe(channel_, [this](const lcm::ReceiveBuffer& b, const std::string& c) { on_datagram(&b, c); });
      return;
    }
    subscription_ = on_.lcm()->subscribe(regex_escape(channel_), &GuardedSubscription::on_datagram, this);
    if (subscription_ == nullptr) throw std::runtime_error("cannot subscribe to '" + channel_ + "'");
    subscription_->setQueueCapacity(queue_capacity);
  }
  ~GuardedSubscription() {
    if (on_.lane() != nullptr) {
      on_.lane()->unsubscribe(channel_);
    } else {
      on_.lcm()->unsubscribe(subscription_);
    }
  }
  GuardedSubscription(const GuardedSubscription&) = delete;
  GuardedSubscription& operator=(const GuardedSubscription&) = delete;

  void set_drop_observer(DropObserver observer) { drop_observer_ = std::move(observer); }
  /// Channel subscribed to.
  const std::string& channel() const { return channel_; }
  /// Messages delivered to the handler.
  std::int64_t delivered() const { return delivered_; }
  /// Messages dropped by this subscription (all kinds).
  std::int64_t dropped() const { return dropped_; }
  /// Sender nonces its replay guard remembers.
  std::size_t senders() const { return replay_.senders(); }

 private:
  void on_datagram(const lcm::ReceiveBuffer* rbuf, const std::string& channel) {
    const auto* data = static_cast<const std::uint8_t*>(rbuf->data);
    const std::size_t size = rbuf->data_size;
    if (size > max_bytes_) {
      drop(DropKind::kOversize, channel,
           std::to_string(size) + " bytes, more than the " + std::to_string(max_bytes_) + " accepted");
      return;
    }
    ReceivedMessage info;
    info.channel = &channel;
    info.bytes = size;
    info.receipt_utime = rbuf->recv_utime;
    std::size_t payload = 0;
    switch (auth_.verify(channel, data, size, &payload, &info.origin)) {
      case TrailerCheck::kMissing:
        drop(DropKind::kUnsigned, channel, std::to_string(size) + " bytes without an authentication trailer");
        return;
      case TrailerCheck::kBadSignature:
        drop(DropKind::kBadSignature, channel, "the MAC does not verify under this bus key (other key, or altered)");
        return;
      case TrailerCheck::kValid:
        break;
    }
    switch (replay_.admit(info.origin, wall_utime())) {
      case ReplayCheck::kStale:
        drop(DropKind::kStale, channel,
             "signed " + std::to_string((wall_utime() - info.origin.utime) / 1000) +
                 " ms ago by this clock, outside +-" + std::to_string(ReplayGuard::kMaxAge / 1000000) + " s");
        return;
      case ReplayCheck::kReplayed:
        drop(DropKind::kReplayed, channel, "sequence " + std::to_string(info.origin.sequence) +
                                               " of this sender was seen before");
        return;
      case ReplayCheck::kFresh:
        break;
    }
    Message message{};
    if (auto failure = decode_bytes(data, payload, message)) {
      drop(failure->kind, channel, failure->reason);
      return;
    }
    try {
      handler_(message, info);
      ++delivered_;
    } catch (const std::exception& e) {
      drop(DropKind::kHandlerFailed, channel, std::string(Message::getTypeName()) + ": " + e.what());
    } catch (...) {
      drop(DropKind::kHandlerFailed, channel, std::string(Message::getTypeName()) + ": unknown exception");
    }
  }

  void drop(DropKind kind, const std::string& channel, const std::string& reason) {
    ++dropped_;
    record_drop(kind, who_, channel, reason);
    if (drop_observer_) drop_observer_(kind);
  }

  Inbox on_;
  std::string channel_;
  std::string who_;
  Handler handler_;
  std::size_t max_bytes_;
  MessageAuth& auth_;
  ReplayGuard replay_;
  DropObserver drop_observer_;
  lcm::Subscription* subscription_ = nullptr;
  std::int64_t delivered_ = 0;
  std::int64_t dropped_ = 0;
};

}  // namespace wrc::bus
