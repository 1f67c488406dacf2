// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Service side of request/reply over LCM: receives each request through the guarded path
/// (bus/transport/guarded_subscription.hpp: size, authentication, replay, bounded decoding), checks it,
/// calls the service's handler and publishes the signed reply (request id echoed) on the
/// request's reply channel. Undecodable, malformed or invalid requests are counted and logged,
/// never crash the process; a handler exception becomes an error reply. A re-sent request is
/// answered from a small cache instead of being computed again; the cache is keyed on the
/// sending process (the verified nonce of its authentication trailer, new at every start), its
/// reply channel and the request id, so a new client reusing a channel name and counting its ids
/// from the start again never gets another client's answer.

#include <lcm/lcm-cpp.hpp>

#include <deque>
#include <exception>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "bus/auth/signed_publish.hpp"
#include "bus/service/service_load.hpp"
#include "bus/transport/channels.hpp"
#include "bus/transport/clock.hpp"
#include "bus/transport/guarded_subscription.hpp"
#include "bus/transport/header_stamper.hpp"
#include "bus/transport/rejection_log.hpp"

namespace wrc::bus {

/// Kinds of error replies a server sends.
enum class RequestError { kBadRequest, kInternalError };

/// Counters of one server.
struct ServerCounters {
  std::int64_t received = 0;       ///< messages seen on the request channel
  std::int64_t answered = 0;       ///< replies published (error replies included)
  std::int64_t from_cache = 0;     ///< re-sent requests answered from the reply cache
  std::int64_t not_addressed = 0;  ///< requests for another instance, ignored
  std::int64_t rejected = 0;       ///< undecodable or invalid requests, handler failures
  std::int64_t refused = 0;        ///< requests ignored while not serving (a duplicate instance)
};

/// A request server for Request/Reply types with `request_id` and `reply_channel` (request) and
/// `request_id` (reply) fields and a `header` in both.
template <class Request, class Reply>
class RequestServer : public LoadSource {
 public:
  /// Computes the reply of a valid request; may throw (std::invalid_argument = bad request,
  /// anything else = internal error). The reply starts value-initialised (zeros, empty
  /// arrays); every num_x count the handler sets must equal the size of its array.
  using Handler = std::function<void(const Request&, Reply&)>;
  /// Checks a decoded request; returns an empty string when valid, else a one-line reason.
  using Validator = std::function<std::string(const Request&)>;
  /// Fills an error reply (status + message fields of the reply type).
  using ErrorFiller = std::function<void(const Request&, RequestError, const std::string&, Reply&)>;
  /// Returns false for requests meant for another instance (ignored, not an error).
  using AddressFilter = std::function<bool(const Request&)>;

  /// Subscribes to request_channel (full bus name). sender: header sender name.
  /// Throws std::runtime_error when the subscription fails or handler is empty.
  /// On a lane socket, reply_on() must name where the replies go before the first request.
  RequestServer(Inbox on, std::string request_channel, std::string sender, Handler handler)
      : reply_on_(on.lcm()),
        channel_(std::move(request_channel)),
        stamper_(std::move(sender)),
        rejections_(stamper_.sender() + " on " + channel_),
        handler_(std::move(handler)) {
    if (!handler_) throw std::runtime_error("request server on '" + channel_ + "' has no handler");
    subscription_ = std::make_unique<GuardedSubscription<Request>>(
        on, channel_, stamper_.sender() + " on " + channel_,
        [this](const Request& request, const ReceivedMessage& info) { on_request(request, info); });
    subscription_->set_drop_observer([this](DropKind) {
      ++counters_.received;
      ++counters_.rejected;
    });
  }
  RequestServer(const RequestServer&) = delete;
  RequestServer& operator=(const RequestServer&) = delete;

  /// Publishes the replies on other instead (see RequestClient::publish_on); it must outlive the server.
  void reply_on(lcm::LCM& other) { reply_on_ = &other; }
  /// Optional range/consistency check run before the handler.
  void set_validator(Validator validator) { validator_ = std::move(validator); }
  /// Optional: how to express errors in the reply type; without it, bad requests get no reply.
  void set_error_filler(ErrorFiller filler) { error_filler_ = std::move(filler); }
  /// Optional: which requests this instance answers.
  void set_address_filter(AddressFilter filter) { address_filter_ = std::move(filter); }
  /// While false, requests are ignored (counted as refused): a duplicate instance must not answer.
  void set_serving(bool serving) override { serving_ = serving; }

  /// Channel served.
  const std::string& channel() const { return channel_; }
  /// Counters since start.
  const ServerCounters& counters() const { return counters_; }

  void add_load(ServiceLoad& load) const override {
    load.requests_handled += counters_.answered;
    load.requests_rejected += counters_.rejected;
    latencies_.summarise(load);
  }
  double take_busy_time() override { return std::exchange(busy_time_, 0.0); }

 private:
  static constexpr std::size_t kCacheSize = 16;

  /// Who asked: the sending process (trailer nonce), its reply channel and its request id.
  struct CacheKey {
    std::uint64_t sender_nonce;
    std::string reply_channel;
    std::int64_t request_id;
    bool operator==(const CacheKey& o) const {
      return sender_nonce == o.sender_nonce && request_id == o.request_id && reply_channel == o.reply_channel;
    }
  };

  void on_request(const Request& request, const ReceivedMessage& info) {
    const double start = monotonic_seconds();
    const std::string& channel = *info.channel;
    ++counters_.received;
    if (address_filter_ && !address_filter_(request)) {
      ++counters_.not_addressed;
      return;
    }
    if (!serving_) {
      ++counters_.refused;
      return;
    }
    if (request.reply_channel.empty() || request.reply_channel.size() > kMaxChannelLength) {
      reject(channel, "reply channel '" + request.reply_channel.substr(0, 80) +
                          "' is empty or longer than 63 characters");
      return;
    }
    const CacheKey key{info.origin.nonce, request.reply_channel, request.request_id};
    for (auto& [cached_key, cached] : cache_) {
      if (cached_key == key) {
        ++counters_.from_cache;
        publish(request.reply_channel, cached, start);
        return;
      }
    }
    Reply reply{};
    std::string why;
    if (request.request_id <= 0) {
      why = "request_id " + std::to_string(request.request_id) + " is not positive";
    } else if (validator_) {
      why = validator_(request);
    }
    if (!why.empty()) {
      reject(channel, why);
      if (!error_filler_) return;
      error_filler_(request, RequestError::kBadRequest, why, reply);
    } else {
      try {
        stamp_receipt(reply, info);
        handler_(request, reply);
      } catch (const std::invalid_argument& e) {
        reject(channel, e.what());
        if (!error_filler_) return;
        reply = Reply();
        error_filler_(request, RequestError::kBadRequest, e.what(), reply);
      } catch (const std::exception& e) {
        reject(channel, std::string("handler failed: ") + e.what());
        if (!error_filler_) return;
        reply = Reply();
        error_filler_(request, RequestError::kInternalError, e.what(), reply);
      }
    }
    reply.request_id = request.request_id;
    publish(request.reply_channel, reply, start);
    if (cache_.size() == kCacheSize) cache_.pop_front();
    cache_.emplace_back(key, std::move(reply));
  }

  /// Replies that carry query_receipt_utime and service_wakeup_time (contact_reply_t) get when the
  /// query was received and how long it took to reach the handler.
  template <class R, class = void>
  struct CarriesReceipt : std::false_type {};
  template <class R>
  struct CarriesReceipt<R, std::void_t<decltype(R::query_receipt_utime), decltype(R::service_wakeup_time)>>
      : std::true_type {};
  static void stamp_receipt(Reply& reply, const ReceivedMessage& info) {
    if constexpr (CarriesReceipt<Reply>::value) {
      reply.query_receipt_utime = info.receipt_utime;
      const std::int64_t now = wall_utime();
      reply.service_wakeup_time = info.receipt_utime > 0 ? 1e-6 * static_cast<double>(now - info.receipt_utime) : 0.0;
    } else {
      (void)reply, (void)info;
    }
  }

  void publish(const std::string& reply_channel, Reply& reply, double start) {
    stamper_.stamp(reply.header);
    if (reply_on_ == nullptr || publish_signed(*reply_on_, reply_channel, reply) != 0) {
      rejections_.reject(reply_channel, "publishing the reply failed");
    }
    ++counters_.answered;
    const double elapsed = monotonic_seconds() - start;
    latencies_.add(elapsed);
    busy_time_ += elapsed;
  }

  void reject(const std::string& channel, const std::string& why) {
    ++counters_.rejected;
    rejections_.reject(channel, why);
  }

  lcm::LCM* reply_on_;  // where replies go
  std::string channel_;
  HeaderStamper stamper_;
  RejectionLog rejections_;
  Handler handler_;
  Validator validator_;
  ErrorFiller error_filler_;
  AddressFilter address_filter_;
  std::unique_ptr<GuardedSubscription<Request>> subscription_;
  bool serving_ = true;
  ServerCounters counters_;
  LatencyWindow latencies_;
  double busy_time_ = 0.0;  // [s] handler time since the last take_busy_time()
  std::deque<std::pair<CacheKey, Reply>> cache_;
};

}  // namespace wrc::bus
