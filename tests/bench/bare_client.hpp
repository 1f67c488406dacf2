// SPDX-License-Identifier: Apache-2.0
#pragma once
// Pieces shared by the benchmarks that compare the bus layer with plain LCM (bench_bus,
// bench_contact_service): the bare request/reply client and stopping the processes they start.

#include <lcm/lcm-cpp.hpp>
#include <signal.h>
#include <sys/types.h>
#include <sys/wait.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "bus/transport/clock.hpp"
#include "wrc/contact_reply_t.hpp"
#include "wrc/ping_reply_t.hpp"

namespace wrc::bench {

/// Evaluation time a reply reports [s] (pings report none).
inline double compute_time_of(const wrc::contact_reply_t& reply) { return reply.compute_time; }
inline double compute_time_of(const wrc::ping_reply_t&) { return 0.0; }

/// Plain LCM request/reply with an id check: a typed subscription, no bus layer. The floor
/// against which the request/reply layer is measured.
template <class Request, class Reply>
class BareClient {
 public:
  /// Sends `request` (request_id overwritten per call) on channel `out`, waits for replies on `in`.
  BareClient(lcm::LCM& lcm, const char* out, const char* in, Request request)
      : lcm_(lcm), out_(out), request_(std::move(request)) {
    lcm_.subscribe(in, &BareClient::on_reply, this);
  }
  /// Compute time reported in the last reply [s] (0 for pings).
  double compute_time() const { return compute_time_; }
  /// One round trip; false on a 1 s timeout.
  bool round_trip() {
    request_.request_id = ++id_;
    got_ = false;
    lcm_.publish(out_, &request_);
    const double deadline = wrc::bus::monotonic_seconds() + 1.0;
    while (!got_ && wrc::bus::monotonic_seconds() < deadline) lcm_.handleTimeout(1000);
    return got_;
  }

 private:
  void on_reply(const lcm::ReceiveBuffer*, const std::string&, const Reply* reply) {
    if (reply->request_id == id_) {
      got_ = true;
      compute_time_ = compute_time_of(*reply);
    }
  }
  lcm::LCM& lcm_;
  const char* out_;
  Request request_;
  std::int64_t id_ = 0;
  bool got_ = false;
  double compute_time_ = 0.0;
};

}  // namespace wrc::bench
