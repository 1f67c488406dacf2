// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The request side of wrc-geometryd: geometry_request_t on GEOMETRY_REQUEST (decoded from the
/// raw buffer, validated), answered with spline_model_t from the model cache at once or after a
/// fit by the worker, progress_t on PROGRESS meanwhile. Lives on the service loop's thread: it
/// is the only user of LCM; poll() (the loop's idle hook) publishes what the worker reported.
///
/// Rules: an undecodable message is counted and logged, nothing else. An invalid request
/// (request_id <= 0, reply channel too long, a field from_message rejects, a profile that
/// cannot be read) is counted, logged and answered with a progress_t of its request_id,
/// done = total = 0, message "rejected: <reason>". A valid one is answered from
/// <cache>/<model_key>.splinemodel unless recompute is set or the file is missing or unusable;
/// otherwise a fit is queued, unless one of the same model_key is queued or running already:
/// then the request waits for that one. The queue is bounded (kMaxQueuedFits in all,
/// kMaxQueuedFitsPerSender per sender, kMaxWaitersPerFit per fit): beyond, the request is
/// answered at once with "rejected: busy (N queued)"; a queued request hears "queued (N before
/// it)" at once. Fits start one at a time, in turn across senders. Every fitted model is stored in the cache; the answer
/// (request_id echoed, header stamped) is inline when small enough, else the file reference,
/// on reply_channel or SPLINE_MODEL, after the references to the two geometry tables (the exact
/// samples of each wheel, stored next to the model) on GEOMETRY_TABLE. Progress of a fit: at most every 0.2 s, then "done" or
/// "failed: <reason>" with done == total.

#include <lcm/lcm-cpp.hpp>

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bus/service/service_load.hpp"
#include "bus/transport/channels.hpp"
#include "bus/transport/guarded_subscription.hpp"
#include "bus/transport/header_stamper.hpp"
#include "bus/transport/rejection_log.hpp"
#include "geometryd/fit_worker.hpp"
#include "geometryd/model_cache.hpp"
#include "wrc/geometry_request_t.hpp"
#include "wrc/progress_t.hpp"
#include "wrc/spline_model_t.hpp"

namespace wrc::geometryd {

/// Fits waiting (queued, not yet started) in all [-]: beyond it a request for a new model is
/// answered at once with "rejected: busy (N queued)". At about a second a default fit, the last
/// waits half a minute.
inline constexpr std::size_t kMaxQueuedFits = 32;
/// Fits waiting of one sender (the signing nonce of its requests) [-]: one sender cannot fill
/// the queue, and the fits start in turn across senders (round robin), so another sender's
/// request waits for at most the fit running and one of every other sender's.
inline constexpr std::size_t kMaxQueuedFitsPerSender = 4;
/// Requests waiting for one fit [-] (a request for a model queued or fitting joins it).
inline constexpr std::size_t kMaxWaitersPerFit = 64;

/// Counters of the service since start.
struct GeometryCounters {
  std::int64_t received = 0;    ///< messages seen on GEOMETRY_REQUEST
  std::int64_t answered = 0;    ///< models published (one per request answered)
  std::int64_t from_cache = 0;  ///< requests answered from a cache file without fitting
  std::int64_t joined = 0;      ///< requests that waited for a fit of the same model already queued or running
  std::int64_t fits = 0;        ///< fits finished
  std::int64_t failed = 0;      ///< fits that threw (or whose model could not be stored)
  std::int64_t failed_requests = 0;  ///< requests answered "failed: " (heartbeat: rejected, a handler failure)
  std::int64_t dropped = 0;     ///< messages the guarded receive path dropped (unsigned, undecodable, ...)
  std::int64_t refused = 0;     ///< requests ignored while not serving (a duplicate instance)
  std::int64_t busy = 0;        ///< requests answered "rejected: busy" (a bound of the queue reached)
};

class GeometryService : public bus::LoadSource {
 public:
  /// Subscribes to GEOMETRY_REQUEST (names applies the prefix). sender: header sender name
  /// (bus::sender_name). @throws std::runtime_error when the subscription fails.
  GeometryService(lcm::LCM& lcm, const bus::ChannelNames& names, const std::string& sender, const ModelCache& cache,
                  FitWorker& worker);
  ~GeometryService() override;
  GeometryService(const GeometryService&) = delete;
  GeometryService& operator=(const GeometryService&) = delete;

  /// Publishes what the worker reported since the last call (progress, models, failures).
  void poll();

  /// Full bus name of the request channel.
  const std::string& request_channel() const { return request_channel_; }
  const GeometryCounters& counters() const { return counters_; }
  /// Requests rejected (undecodable or invalid).
  std::int64_t rejected() const { return rejections_.count() + counters_.dropped; }
  /// What the service is doing, one line for its heartbeat (heartbeat_t::activity): the fit
  /// running (its progress_t task), its stage and fraction done, and how many wait behind it; or
  /// idle with its counts.
  std::string activity() const;

  void add_load(bus::ServiceLoad& load) const override;
  double take_busy_time() override;
  void set_serving(bool serving) override { serving_ = serving; }

 private:
  /// A request waiting for a job.
  struct Waiter {
    std::int64_t request_id = 0;
    std::string reply_channel;  // full bus name
    double received = 0.0;      // [s] monotonic
  };
  /// A fit queued or running, and who waits for it.
  struct Job {
    std::string model_key;
    std::string task;  // progress_t.task
    std::vector<Waiter> waiters;
    std::string stage;       // last progress report: stage, units done of total (0 = none yet)
    long done = 0, total = 0;
    std::uint64_t owner = 0;  // signing nonce of the request that queued it
    bool started = false;     // handed to the worker
    GeometrySpec spec;        // what the worker gets when it starts
    SplineFitOptions options;
  };

  void on_request(const geometry_request_t& request, const bus::ReceivedMessage& info);
  /// Counts and logs why; when tell, answers request_id with a "rejected: " progress.
  void reject(const std::string& channel, std::int64_t request_id, bool tell, const std::string& why);
  void publish_progress(std::int64_t request_id, const std::string& task, long done, long total, double elapsed,
                        double remaining, const std::string& message);
  /// Publishes message (complete or reference) for waiter.
  void publish_model(spline_model_t message, const Waiter& waiter);
  /// Publishes the table references on GEOMETRY_TABLE with waiter's request id.
  void publish_tables(std::vector<geometry_table_t> tables, const Waiter& waiter);
  void finish(const FitEvent& event);
  /// Fits queued, not started: in all, and of owner.
  std::size_t queued() const;
  std::size_t queued_of(std::uint64_t owner) const;
  /// When no fit runs, hands the next queued one to the worker: the lowest job id of the owner
  /// after the last one started (in nonce order, cyclic).
  void start_next();

  lcm::LCM& lcm_;
  const std::string request_channel_;
  const std::string model_channel_;
  const std::string progress_channel_;
  const std::string table_channel_;
  const std::string sender_;
  const ModelCache& cache_;
  FitWorker& worker_;
  bus::HeaderStamper model_stamper_;
  bus::HeaderStamper progress_stamper_;
  bus::HeaderStamper table_stamper_;
  bus::RejectionLog rejections_;
  bool serving_ = true;
  std::map<std::int64_t, Job> jobs_;                 // by job id
  std::map<std::string, std::int64_t> job_of_key_;   // model_key -> job id
  std::int64_t next_job_ = 1;
  std::int64_t running_job_ = 0;  // the job the worker fits (0: none)
  std::uint64_t last_owner_ = 0;  // owner of the job started last
  GeometryCounters counters_;
  bus::LatencyWindow latencies_;  // request to answer [s]
  double busy_time_ = 0.0;        // [s] handler and publishing time since take_busy_time()
  std::unique_ptr<bus::GuardedSubscription<geometry_request_t>> subscription_;  // last: dispatches into the above
};

}  // namespace wrc::geometryd
