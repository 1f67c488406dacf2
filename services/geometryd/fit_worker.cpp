// SPDX-License-Identifier: Apache-2.0
#include "geometryd/fit_worker.hpp"

#include <exception>
#include <stdexcept>
#include <utility>

#include "bus/transport/clock.hpp"
#include "core/spline/spline_geometry_fit.hpp"
#include "protocol/geometry/geometry_table_codec.hpp"
#include "protocol/geometry/spline_model_codec.hpp"

namespace wrc::geometryd {

using bus::monotonic_seconds;

FitWorker::FitWorker(double progress_interval) : progress_interval_(progress_interval) {
  if (!(progress_interval > 0.0))
    throw std::invalid_argument("fit worker: progress interval " + std::to_string(progress_interval) +
                                " s is not positive");
  thread_ = std::thread([this] { run(); });
}

FitWorker::~FitWorker() {
  stop();
  thread_.join();
}

bool FitWorker::stop() {
  bool running = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
    jobs_.clear();
    running = fitting_;
  }
  wake_.notify_all();
  return running;
}

void FitWorker::submit(FitJob job) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    jobs_.push_back(std::move(job));
  }
  wake_.notify_one();
}

std::vector<FitEvent> FitWorker::take_events() {
  std::lock_guard<std::mutex> lock(mutex_);
  return std::exchange(events_, {});
}

double FitWorker::take_busy_time() {
  std::lock_guard<std::mutex> lock(mutex_);
  double busy = std::exchange(busy_, 0.0);
  if (fitting_) {
    const double now = monotonic_seconds();
    busy += now - busy_since_;
    busy_since_ = now;
  }
  return busy;
}

void FitWorker::post(FitEvent event) {
  std::lock_guard<std::mutex> lock(mutex_);
  events_.push_back(std::move(event));
}

void FitWorker::run() {
  for (;;) {
    FitJob job;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [this] { return stop_ || !jobs_.empty(); });
      if (stop_) return;
      job = std::move(jobs_.front());
      jobs_.pop_front();
      fitting_ = true;
      busy_since_ = monotonic_seconds();
    }
    const double start = monotonic_seconds();
    double last_post = -1.0;  // [s] monotonic time of the job's last progress event
    long last_total = 0;  // total of the last progress callback
    auto progress = [&](long done, long total, const std::string& stage) {
      last_total = total;
      const double now = monotonic_seconds();
      if (last_post >= 0.0 && now - last_post < progress_interval_) return;
      last_post = now;
      FitEvent e;
      e.job = job.id;
      e.done = done;
      e.total = total;
      e.elapsed = now - start;
      e.remaining = done > 0 && total > 0 ? e.elapsed * static_cast<double>(total - done) / static_cast<double>(done) : -1.0;
      e.stage = stage;
      post(std::move(e));
    };
    FitEvent result;
    result.job = job.id;
    try {
      const WheelsetGeometry geometry = make_geometry(job.spec);
      result.geometry_seconds = monotonic_seconds() - start;
      const SplineFit fit = fit_spline_geometry(geometry, job.options, progress);
      result.model = protocol::encode_model(fit, job.spec, job.options);
      for (const auto& grid : fit.samples) result.tables.push_back(protocol::encode_table(*grid, job.spec, result.model.model_key));
      result.kind = FitEvent::Kind::kFinished;
    } catch (const std::exception& e) {
      result.kind = FitEvent::Kind::kFailed;
      result.stage = e.what();
    }
    result.elapsed = monotonic_seconds() - start;
    result.total = last_total > 0 ? last_total : 1;
    result.done = result.total;
    result.remaining = 0.0;
    std::lock_guard<std::mutex> lock(mutex_);
    events_.push_back(std::move(result));
    fitting_ = false;
    busy_ += monotonic_seconds() - busy_since_;
  }
}

}  // namespace wrc::geometryd
