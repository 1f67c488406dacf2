// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Client side of request/reply over LCM: every request carries a request id and a reply
/// channel; the reply echoes the id. Requests are signed (bus/auth/signed_publish.hpp), replies
/// arrive through the guarded path (bus/transport/guarded_subscription.hpp). Ids start at a random
/// multiple of 2^32 per client (a per-client nonce) and count up from there. A call waits for its reply with a per-attempt timeout,
/// re-sends the same request (same id) on timeout, and ignores stale or duplicate replies,
/// counting them. Request types need `int64_t request_id` and `string reply_channel` fields,
/// reply types `int64_t request_id`.

#include <lcm/lcm-cpp.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "bus/auth/signed_publish.hpp"
#include "bus/transport/channels.hpp"
#include "bus/transport/clock.hpp"
#include "bus/transport/guarded_subscription.hpp"
#include "bus/transport/header_stamper.hpp"
#include "bus/transport/lcm_wait.hpp"
#include "bus/transport/rejection_log.hpp"

namespace wrc::bus {

/// How long to wait and how often to try.
struct CallPolicy {
  double timeout = 0.2;  ///< [s] wait for a reply per attempt, > 0
  int retries = 3;       ///< [-] re-sends after the first attempt, >= 0
};

/// Counters of one client, for logs, heartbeats and run summaries.
struct ClientCounters {
  std::int64_t calls = 0;              ///< calls made
  std::int64_t sent = 0;               ///< requests published, retries included
  std::int64_t retries = 0;            ///< re-sends after a timeout
  std::int64_t failed_calls = 0;       ///< calls that got no reply in any attempt
  std::int64_t replies = 0;            ///< replies accepted
  std::int64_t stale_replies = 0;      ///< replies to an id that is not pending (older calls)
  std::int64_t duplicate_replies = 0;  ///< second replies to the last completed call
  std::int64_t rejected_replies = 0;   ///< replies that did not decode
};

/// Outcome of one call: the reply when one arrived, and how many attempts it took.
template <class Reply>
struct CallResult {
  std::optional<Reply> reply;  ///< the reply; empty when every attempt timed out
  int attempts = 0;            ///< [-] attempts made for this call (1 = no retry; call_any sends all its requests in each)
  double round_trip = 0.0;     ///< [s] from the first send to the accepted reply
  double send_time = 0.0;      ///< [s] stamping, encoding, signing and sending of the attempt answered
  std::int64_t sent_utime = 0;      ///< [us] wall clock at the end of that attempt's send calls
  std::int64_t receipt_utime = 0;   ///< [us] when LCM received the reply (ReceivedMessage::receipt_utime)
  std::int64_t handled_utime = 0;   ///< [us] wall clock when the reply had been verified and decoded
  explicit operator bool() const { return reply.has_value(); }
};

/// A unique client id for reply channels: "<program>-<pid>-<n>".
std::string make_client_id(const std::string& program);

/// Synchronous request/reply client on one LCM instance. Not thread-safe; while waiting it
/// dispatches every subscription of the LCM object (heartbeat monitors keep working).
template <class Request, class Reply>
class RequestClient {
 public:
  /// request_channel and reply_channel are full bus names (prefix applied, see ChannelNames).
  /// sender: header sender name. Throws std::runtime_error if the subscription fails.
  /// On a lane socket (replies read in the caller's thread, woken by the kernel itself),
  /// publish_on() must name where the requests go before the first call.
  RequestClient(Inbox on, std::string request_channel, std::string reply_channel, std::string sender)
      : request_channel_(std::move(request_channel)),
        reply_channel_(std::move(reply_channel)),
        stamper_(std::move(sender)),
        last_id_(first_request_id()),
        dispatched_{on},
        publish_on_(on.lcm()) {
    subscription_ = std::make_unique<GuardedSubscription<Reply>>(
        on, reply_channel_, "request client on " + reply_channel_,
        [this](const Reply& reply, const ReceivedMessage& info) { on_reply(reply, info); }, 100);
    subscription_->set_drop_observer([this](DropKind) { ++counters_.rejected_replies; });
  }
  RequestClient(const RequestClient&) = delete;
  RequestClient& operator=(const RequestClient&) = delete;

  /// Sends request (request_id, reply_channel and header are filled in here) and waits for the
  /// reply, re-sending after each timeout up to policy.retries times. Throws
  /// std::invalid_argument for a non-positive timeout or negative retries, std::runtime_error
  /// when LCM fails.
  CallResult<Reply> call(Request& request, const CallPolicy& policy) { return call_any(&request, 1, policy); }

  /// One call sent as count requests at once (each attempt publishes all of them, with one
  /// request id): they differ only in who is to answer (e.g. the instance each addresses), and
  /// the first reply is the call's. count >= 1. Otherwise as call().
  CallResult<Reply> call_any(Request* requests, std::size_t count, const CallPolicy& policy) {
    if (count == 0) throw std::invalid_argument("a call needs at least one request");
    check_policy(policy);
    ++counters_.calls;
    pending_id_ = ++last_id_;
    for (std::size_t k = 0; k < count; ++k) {
      requests[k].request_id = pending_id_;
      requests[k].reply_channel = reply_channel_;
    }
    answer_.reset();
    CallResult<Reply> result;
    const double start = monotonic_seconds();
    for (int attempt = 0; attempt <= policy.retries && !answer_; ++attempt) {
      if (attempt > 0) ++counters_.retries;
      const double send_start = monotonic_seconds();
      for (std::size_t k = 0; k < count; ++k) {
        stamper_.stamp(requests[k].header);
        if (publish_signed(*publish_on_, request_channel_, requests[k]) != 0) {
          throw std::runtime_error("publish on '" + request_channel_ + "' failed");
        }
        ++counters_.sent;
      }
      ++result.attempts;
      result.send_time = monotonic_seconds() - send_start;
      result.sent_utime = wall_utime();
      wait_until([this] { return answer_.has_value(); }, monotonic_seconds() + policy.timeout);
    }
    pending_id_ = 0;
    if (answer_) {
      completed_id_ = requests[0].request_id;
      ++counters_.replies;
      result.round_trip = monotonic_seconds() - start;
      result.receipt_utime = answer_receipt_utime_;
      result.handled_utime = answer_handled_utime_;
      result.reply = std::move(answer_);
      answer_.reset();
    } else {
      ++counters_.failed_calls;
    }
    return result;
  }

  /// count calls at once: each request gets an id of its own, all are published, and the client
  /// waits until each has its reply or the attempt's timeout has passed; then the unanswered ones
  /// are re-sent (same ids), up to policy.retries times. One result per request, in order (empty
  /// where every attempt timed out; attempts, send time and round trip are those of the whole
  /// call). count >= 1. Otherwise as call().
  std::vector<CallResult<Reply>> call_each(Request* requests, std::size_t count, const CallPolicy& policy) {
    if (count == 0) throw std::invalid_argument("a call needs at least one request");
    check_policy(policy);
    std::vector<CallResult<Reply>> results(count);
    each_pending_.clear();
    for (std::size_t k = 0; k < count; ++k) {
      ++counters_.calls;
      requests[k].request_id = ++last_id_;
      requests[k].reply_channel = reply_channel_;
      each_pending_.push_back(requests[k].request_id);
    }
    each_answers_.assign(count, std::nullopt);
    each_receipt_utime_.assign(count, 0);
    each_handled_utime_.assign(count, 0);
    each_handled_seconds_.assign(count, 0.0);
    const double start = monotonic_seconds();
    std::size_t answered = 0;
    for (int attempt = 0; attempt <= policy.retries && answered < count; ++attempt) {
      const double send_start = monotonic_seconds();
      for (std::size_t k = 0; k < count; ++k) {
        if (each_answers_[k]) continue;
        if (attempt > 0) ++counters_.retries;
        stamper_.stamp(requests[k].header);
        if (publish_signed(*publish_on_, request_channel_, requests[k]) != 0) {
          each_pending_.clear();
          throw std::runtime_error("publish on '" + request_channel_ + "' failed");
        }
        ++counters_.sent;
        ++results[k].attempts;
        results[k].sent_utime = wall_utime();
      }
      const double send_time = monotonic_seconds() - send_start;
      for (std::size_t k = 0; k < count; ++k)
        if (!each_answers_[k]) results[k].send_time = send_time;
      wait_until([&] { return each_answered() == count; }, monotonic_seconds() + policy.timeout);
      answered = each_answered();
    }
    each_pending_.clear();
    for (std::size_t k = 0; k < count; ++k) {
      if (!each_answers_[k]) {
        ++counters_.failed_calls;
        continue;
      }
      ++counters_.replies;
      results[k].round_trip = each_handled_seconds_[k] - start;
      results[k].receipt_utime = each_receipt_utime_[k];
      results[k].handled_utime = each_handled_utime_[k];
      results[k].reply = std::move(each_answers_[k]);
    }
    each_completed_.clear();
    for (std::size_t k = 0; k < count; ++k) each_completed_.push_back(requests[k].request_id);
    return results;
  }

  /// While waiting, dispatches other's subscriptions too (a client on a lane of the bus keeps
  /// the bus's heartbeat monitors and commands working; bus/transport/lcm_url.hpp). other must
  /// outlive the client.
  void also_dispatch(Inbox other) { dispatched_.push_back(other); }
  /// Publishes the requests on other instead (an object that subscribes to nothing has no
  /// receive socket, so its own requests do not come back to it). other must outlive the client.
  void publish_on(lcm::LCM& other) { publish_on_ = &other; }

  /// Directs later requests to another channel (hot swap between services).
  void set_request_channel(std::string channel) { request_channel_ = std::move(channel); }
  /// Current request channel.
  const std::string& request_channel() const { return request_channel_; }
  /// Channel the replies arrive on.
  const std::string& reply_channel() const { return reply_channel_; }
  /// Counters since construction.
  const ClientCounters& counters() const { return counters_; }

 private:
  void check_policy(const CallPolicy& policy) const {
    if (!(policy.timeout > 0.0) || !std::isfinite(policy.timeout)) {
      throw std::invalid_argument("call timeout " + std::to_string(policy.timeout) +
                                  " s is not a positive number");
    }
    if (policy.retries < 0) {
      throw std::invalid_argument("call retries " + std::to_string(policy.retries) + " is negative");
    }
    if (publish_on_ == nullptr) throw std::logic_error("a request client on a lane has nowhere to publish");
  }

  std::size_t each_answered() const {
    std::size_t n = 0;
    for (const std::optional<Reply>& a : each_answers_) n += a ? 1 : 0;
    return n;
  }

  /// Reads replies (and every dispatched subscription) until done() or the deadline [s].
  template <class Done>
  void wait_until(Done done, double deadline) {
    // What is queued already is read first, whatever the deadline: a reply that is there is
    // taken, and a call with a timeout below the round trip still reads every subscription of
    // the LCM object once per attempt. Without this, a caller retrying such calls in a loop (the
    // dynamics' contact client) would publish without ever reading: its queues overflowed, the
    // heartbeats of the services it needs were lost, and no reply was ever seen.
    for (int handled = 0; !done() && handled < kMaxDrain; ++handled) {
      const int rc = handle_any(dispatched_, 0);
      if (rc < 0 && errno != EINTR) throw std::runtime_error("LCM handle failed while waiting for a reply");
      if (rc <= 0) break;
    }
    while (!done()) {
      const double remaining = deadline - monotonic_seconds();
      if (remaining <= 0.0) return;
      const int ms = static_cast<int>(std::ceil(remaining * 1e3));
      const int rc = handle_any(dispatched_, ms);
      if (rc < 0 && errno != EINTR) throw std::runtime_error("LCM handle failed while waiting for a reply");
      if (rc < 0) return;  // interrupted by a signal: let the caller look at its shutdown flag
    }
  }

  /// [-] most queued messages read before the deadline is looked at (a flood cannot hold a call).
  static constexpr int kMaxDrain = 10000;

  /// A random positive multiple of 2^32 below 2^62: ids of two clients do not meet.
  static std::int64_t first_request_id() {
    return static_cast<std::int64_t>((MessageAuth::random_nonce() % ((std::uint64_t{1} << 30) - 1)) + 1) << 32;
  }

  void on_reply(const Reply& reply, const ReceivedMessage& info) {
    for (std::size_t k = 0; k < each_pending_.size(); ++k) {
      if (reply.request_id != each_pending_[k]) continue;
      if (each_answers_[k]) {
        ++counters_.duplicate_replies;
      } else {
        each_answers_[k] = reply;
        each_receipt_utime_[k] = info.receipt_utime;
        each_handled_utime_[k] = wall_utime();
        each_handled_seconds_[k] = monotonic_seconds();
      }
      return;
    }
    if (std::find(each_completed_.begin(), each_completed_.end(), reply.request_id) != each_completed_.end()) {
      ++counters_.duplicate_replies;
      return;
    }
    if (pending_id_ != 0 && reply.request_id == pending_id_ && !answer_) {
      answer_ = reply;
      answer_receipt_utime_ = info.receipt_utime;
      answer_handled_utime_ = wall_utime();
    } else if ((completed_id_ != 0 && reply.request_id == completed_id_) ||
               (pending_id_ != 0 && reply.request_id == pending_id_)) {
      ++counters_.duplicate_replies;
    } else {
      ++counters_.stale_replies;
    }
  }

  std::string request_channel_;
  std::string reply_channel_;
  HeaderStamper stamper_;
  std::unique_ptr<GuardedSubscription<Reply>> subscription_;
  ClientCounters counters_;
  std::int64_t last_id_;           // the first call gets last_id_ + 1, then +1 per call
  std::int64_t pending_id_ = 0;    // id of the call in progress, 0 = none
  std::int64_t completed_id_ = 0;  // id of the last call that got its reply
  std::optional<Reply> answer_;
  std::int64_t answer_receipt_utime_ = 0;  // [us] of answer_
  std::int64_t answer_handled_utime_ = 0;  // [us] of answer_
  // call_each: the ids in progress, their replies and when they came, and the ids of the last
  // call_each (a later reply to one is a duplicate)
  std::vector<std::int64_t> each_pending_;
  std::vector<std::optional<Reply>> each_answers_;
  std::vector<std::int64_t> each_receipt_utime_;   // [us]
  std::vector<std::int64_t> each_handled_utime_;   // [us]
  std::vector<double> each_handled_seconds_;       // [s] monotonic
  std::vector<std::int64_t> each_completed_;
  std::vector<Inbox> dispatched_;      // read while waiting: the client's own inbox first
  lcm::LCM* publish_on_;               // where requests go
};

}  // namespace wrc::bus
