// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Periodic heartbeat of a service process: who it is (model, instance, pid, request channel),
/// its state (STARTING, READY, DRAINING, DUPLICATE) and why, its load, the geometry key and model
/// hash it computes with, the interface version it was built with, when it started, and the
/// messages it dropped (bus/transport/drop_counters.hpp). Signed like every message (bus/auth/signed_publish.hpp).

#include <lcm/lcm-cpp.hpp>

#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

#include "bus/service/service_load.hpp"
#include "bus/transport/header_stamper.hpp"
#include "wrc/heartbeat_t.hpp"

namespace wrc::bus {

/// [s] shortest heartbeat period a service may have and a monitor believes: below 10 ms the
/// heartbeats alone would load the bus and the hang checks would act on scheduling jitter.
inline constexpr double kMinHeartbeatPeriod = 0.01;
/// [s] longest: clients wait missed_periods (3) periods before they call a silent instance
/// dead, so a claimed period of an hour would hold every unaddressed query to a vanished (or
/// invented) instance for hours; 10 s bounds that wait to 30 s.
inline constexpr double kMaxHeartbeatPeriod = 10.0;

/// Identity of a service as shown in its heartbeat.
struct ServiceIdentity {
  std::string program;          ///< executable name, e.g. "wrc-pingd"
  std::string model;            ///< service kind / contact model, e.g. "pingd", "onepoint"
  std::string instance;         ///< instance name, unique per model on one bus
  std::string request_channel;  ///< full bus name of the channel it serves (may be empty)
};

/// Publishes heartbeat_t on the HEARTBEAT channel every period. Call tick() from the service
/// loop; it publishes when a period has passed. With start_keeper() a thread of its own re-sends
/// the last heartbeat (stamped anew) whenever the loop is late with one, as long as the loop
/// ticked within max_busy: a handler that works for a second (a burst of geometry answers, the
/// dynamics' contact retries) keeps the service alive, a loop that is stuck for good goes silent.
class HeartbeatPublisher {
 public:
  /// channel: full bus name of the heartbeat channel; period [s] > 0 (throws
  /// std::invalid_argument naming the value otherwise). Starts in state STARTING.
  HeartbeatPublisher(lcm::LCM& lcm, std::string channel, ServiceIdentity identity, double period);
  /// Stops the keeper thread, if any.
  ~HeartbeatPublisher();
  HeartbeatPublisher(const HeartbeatPublisher&) = delete;
  HeartbeatPublisher& operator=(const HeartbeatPublisher&) = delete;

  /// Changes the state and publishes at once (STARTING, READY, DRAINING, DUPLICATE of
  /// heartbeat_t); reason goes into state_reason (empty: nothing to say).
  void set_state(std::int8_t state, std::string reason = "");
  /// Load figures for the next heartbeats.
  void set_load(const ServiceLoad& load) { load_ = load; }
  /// Geometry key (core/identity/geometry_key.hpp) of the geometry the service computes with
  /// (empty = none).
  void set_geometry_key(std::string key) { geometry_key_ = std::move(key); }
  /// SHA-256 of the model data the service computes with: table or spline coefficients (empty =
  /// a model with no precomputed data).
  void set_model_hash(std::string hash) { model_hash_ = std::move(hash); }

  /// What the process is doing, asked for at every heartbeat (heartbeat_t::activity; one line).
  void set_activity_source(std::function<std::string()> source) { activity_source_ = std::move(source); }
  /// Publishes if a period has passed since the last heartbeat; returns true when it did. Every
  /// call tells the keeper the loop is alive.
  bool tick();
  /// Starts the keeper thread (once; later calls do nothing): while the last tick() is at most
  /// max_busy [s] old (> 0, else std::invalid_argument), no period passes without a heartbeat.
  void start_keeper(double max_busy);
  /// Publishes now and restarts the period.
  void publish_now();
  /// [s] until the next heartbeat is due (>= 0).
  double seconds_until_due() const;

  /// Current state.
  std::int8_t state() const { return state_; }
  /// Full bus name of the heartbeat channel.
  const std::string& channel() const { return channel_; }
  /// Who this process is.
  const ServiceIdentity& identity() const { return identity_; }
  /// [us] wall clock at construction (heartbeat_t::started_utime).
  std::int64_t started_utime() const { return started_utime_; }
  /// [s] heartbeat period.
  double period() const { return period_; }
  /// Heartbeats published so far (the keeper's included).
  std::int64_t published() const;
  /// Heartbeats the keeper re-sent because the loop was late.
  std::int64_t kept_alive() const;

 private:
  lcm::LCM& lcm_;
  std::string channel_;
  ServiceIdentity identity_;
  double period_;
  double started_;      // [s] monotonic start time
  std::int64_t started_utime_;  // [us] wall-clock start time
  std::int8_t state_ = wrc::heartbeat_t::STARTING;
  std::string state_reason_;
  ServiceLoad load_;
  std::string geometry_key_;
  std::string model_hash_;
  std::function<std::string()> activity_source_;

  /// The keeper thread's loop.
  void keep_alive();
  /// Publishes hb and counts it; mutex_ held.
  void send_locked(const wrc::heartbeat_t& hb, double now);

  // Shared with the keeper thread, under mutex_.
  mutable std::mutex mutex_;
  HeaderStamper stamper_;
  double last_sent_;                 // [s] monotonic time of the last heartbeat (the keeper's copies included)
  double last_fresh_;                // [s] monotonic time of the last heartbeat made by publish_now(): the
                                     //     loop's own are due a period after it, whatever the keeper sent
  double last_tick_ = 0.0;           // [s] monotonic time of the last tick()
  double max_busy_ = 0.0;            // [s] the keeper covers a loop at most this late
  wrc::heartbeat_t last_heartbeat_{};
  std::int64_t published_ = 0;
  std::int64_t kept_alive_ = 0;
  bool stop_keeper_ = false;
  std::condition_variable keeper_wakeup_;
  std::thread keeper_;
};

}  // namespace wrc::bus
