// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The one worker thread of wrc-geometryd: fits spline models (make_geometry, fit_spline_geometry,
/// encode_model) one job after the other, off the service loop. It never touches LCM: progress
/// and results go into a mutex-protected queue that the loop drains (take_events) and publishes.

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "core/geometry/geometry_spec.hpp"
#include "core/spline/spline_fit_options.hpp"
#include "wrc/geometry_table_t.hpp"
#include "wrc/spline_model_t.hpp"

namespace wrc::geometryd {

/// One model to fit.
struct FitJob {
  std::int64_t id = 0;       ///< the caller's job number, echoed in its events
  GeometrySpec spec;         ///< geometry input
  SplineFitOptions options;  ///< validated fit options
};

/// Something the worker has to report about a job.
struct FitEvent {
  enum class Kind { kProgress, kFinished, kFailed };
  Kind kind = Kind::kProgress;
  std::int64_t job = 0;      ///< FitJob::id
  long done = 0;             ///< [-] work units finished (FitProgress)
  long total = 0;            ///< [-] work units in all (0 = unknown)
  double elapsed = 0.0;      ///< [s] since the job started (geometry construction included)
  double remaining = -1.0;   ///< [s] linear estimate from done/total, -1 = unknown
  std::string stage;         ///< kProgress: the fit's current stage; kFailed: the reason
  spline_model_t model;      ///< kFinished: the complete model message (encode_model, coefficients inline)
  std::vector<geometry_table_t> tables;  ///< kFinished: the exact samples, left and right wheel (encode_table)
  double geometry_seconds = 0.0;  ///< kFinished: make_geometry [s]
};

class FitWorker {
 public:
  /// progress_interval [s]: least time between two progress events of one job (> 0).
  explicit FitWorker(double progress_interval = 0.2);
  /// Stops the thread; waits for a running fit to end (see stop()).
  ~FitWorker();
  FitWorker(const FitWorker&) = delete;
  FitWorker& operator=(const FitWorker&) = delete;

  /// Queues a job (jobs run in submission order).
  void submit(FitJob job);
  /// The events since the last call, in order.
  std::vector<FitEvent> take_events();
  /// Takes no more jobs (those queued are dropped) and returns whether a fit runs now, in one
  /// step: a job the thread has not taken yet is never started after it, so a false answer
  /// means the destructor will not wait.
  bool stop();
  /// [s] time spent fitting since the previous call (the running fit included up to now).
  double take_busy_time();

 private:
  void run();
  void post(FitEvent event);

  const double progress_interval_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<FitJob> jobs_;
  std::vector<FitEvent> events_;
  bool stop_ = false;
  bool fitting_ = false;
  double busy_since_ = 0.0;  // [s] monotonic start of the busy time not yet taken (while fitting)
  double busy_ = 0.0;        // [s] busy time of fits that ended, not yet taken
  std::thread thread_;       // last: starts after every member above is initialised
};

}  // namespace wrc::geometryd
