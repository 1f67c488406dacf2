// SPDX-License-Identifier: Apache-2.0
#include "geometryd/geometry_service.hpp"

#include <cstdio>
#include <exception>
#include <iostream>
#include <stdexcept>
#include <utility>

#include "bus/auth/signed_publish.hpp"
#include "bus/transport/clock.hpp"
#include "core/identity/geometry_key.hpp"
#include "protocol/geometry/fit_options_codec.hpp"
#include "protocol/geometry/spline_model_codec.hpp"
#include "protocol/geometry/track_codec.hpp"
#include "wrc/geometry_request_t.hpp"

namespace wrc::geometryd {

namespace {

constexpr std::size_t kKeyPrefix = 12;  // hex digits of a model key in log lines

std::string task_name(const GeometrySpec& spec, const SplineFitOptions& options) {
  return "spline fit " + spec.wheel + "/" + spec.rail + " " + std::to_string(options.intervals[0]) + "x" +
         std::to_string(options.intervals[1]) + "x" + std::to_string(options.intervals[2]);
}

/// Adds the time from construction to destruction to *sum [s].
class BusyTimer {
 public:
  explicit BusyTimer(double* sum) : sum_(sum), start_(bus::monotonic_seconds()) {}
  ~BusyTimer() { *sum_ += bus::monotonic_seconds() - start_; }
  BusyTimer(const BusyTimer&) = delete;
  BusyTimer& operator=(const BusyTimer&) = delete;
  double start() const { return start_; }

 private:
  double* sum_;
  double start_;
};

std::string seconds_text(double seconds) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f s", seconds);
  return buf;
}

}  // namespace

GeometryService::GeometryService(lcm::LCM& lcm, const bus::ChannelNames& names, const std::string& sender,
                                 const ModelCache& cache, FitWorker& worker)
    : lcm_(lcm),
      request_channel_(names.name(bus::channel::kGeometryRequest)),
      model_channel_(names.name(bus::channel::kSplineModel)),
      progress_channel_(names.name(bus::channel::kProgress)),
      table_channel_(names.name(bus::channel::kGeometryTable)),
      sender_(sender),
      cache_(cache),
      worker_(worker),
      model_stamper_(sender),
      progress_stamper_(sender),
      table_stamper_(sender),
      rejections_(sender + " on " + request_channel_) {
  subscription_ = std::make_unique<bus::GuardedSubscription<geometry_request_t>>(
      lcm_, request_channel_, sender + " on " + request_channel_,
      [this](const geometry_request_t& request, const bus::ReceivedMessage& info) { on_request(request, info); });
  subscription_->set_drop_observer([this](bus::DropKind) {
    ++counters_.received;
    ++counters_.dropped;
  });
}

GeometryService::~GeometryService() = default;

void GeometryService::reject(const std::string& channel, std::int64_t request_id, bool tell, const std::string& why) {
  rejections_.reject(channel, why);
  if (tell) publish_progress(request_id, "geometry request", 0, 0, 0.0, -1.0, "rejected: " + why);
}

void GeometryService::on_request(const geometry_request_t& request, const bus::ReceivedMessage& info) {
  const BusyTimer busy(&busy_time_);
  const double start = busy.start();
  const std::string& channel = *info.channel;
  ++counters_.received;
  if (!serving_) {
    ++counters_.refused;
    return;
  }
  GeometrySpec spec;
  SplineFitOptions options;
  std::string key;
  std::string why;
  if (request.request_id <= 0) {
    why = "request_id " + std::to_string(request.request_id) + " is not positive";
  } else if (request.reply_channel.size() > bus::kMaxChannelLength) {
    why = "reply_channel '" + request.reply_channel + "' is longer than 63 characters";
  } else {
    try {
      spec = protocol::from_message(request.track);
      options = protocol::from_message(request.fit);
      key = protocol::model_key(geometry_key(spec), options);
    } catch (const std::exception& e) {  // invalid_argument naming the field; ProfileError for a file
      why = e.what();
    }
  }
  if (!why.empty()) {
    reject(channel, request.request_id, true, why);
    return;
  }
  const Waiter waiter{request.request_id, request.reply_channel.empty() ? model_channel_ : request.reply_channel, start};
  const std::string short_key = key.substr(0, kKeyPrefix);

  const auto refuse_busy = [&] {
    ++counters_.busy;
    reject(channel, request.request_id, true, "busy (" + std::to_string(queued()) + " queued)");
  };
  if (auto it = job_of_key_.find(key); it != job_of_key_.end()) {
    Job& job = jobs_.at(it->second);
    for (const Waiter& w : job.waiters) {
      if (w.request_id == waiter.request_id && w.reply_channel == waiter.reply_channel) return;  // re-sent: waits already
    }
    if (job.waiters.size() >= kMaxWaitersPerFit) {
      refuse_busy();
      return;
    }
    job.waiters.push_back(waiter);
    ++counters_.joined;
    std::cerr << sender_ << ": request " << request.request_id << " waits for the fit of model " << short_key
              << " already under way\n";
    return;
  }

  if (!request.recompute) {
    std::string unusable;
    if (auto full = cache_.find(key, &unusable)) {
      try {
        spline_model_t answer = answer_message(*full, cache_.path(key));
        const bool inline_model = answer.file_path.empty();
        publish_tables(cache_.find_tables(key), waiter);
        publish_model(std::move(answer), waiter);
        ++counters_.from_cache;
        std::cerr << sender_ << ": request " << request.request_id << " answered from the cache: model " << short_key
                  << " in " << seconds_text(bus::monotonic_seconds() - start) << ", "
                  << (inline_model ? "inline" : "file " + cache_.path(key)) << "\n";
        return;
      } catch (const std::exception& e) {
        unusable = e.what();
      }
    }
    if (!unusable.empty()) std::cerr << sender_ << ": cache file of model " << short_key << " unusable, refitting: " << unusable << "\n";
  }

  const std::uint64_t owner = info.origin.nonce;
  const std::size_t waiting = queued();  // jobs_ holds at most kMaxQueuedFits + 1 fits: walks are short
  if (waiting >= kMaxQueuedFits || queued_of(owner) >= kMaxQueuedFitsPerSender) {
    refuse_busy();
    return;
  }
  const std::int64_t id = next_job_++;
  Job job;
  job.model_key = key;
  job.task = task_name(spec, options);
  job.waiters = {waiter};
  job.owner = owner;
  job.spec = std::move(spec);
  job.options = std::move(options);
  std::cerr << sender_ << ": request " << request.request_id << ": fitting model " << short_key << " (" << job.task
            << (request.recompute ? ", recompute" : "") << ")\n";
  const std::string task = job.task;
  const std::size_t before = waiting + (running_job_ != 0 ? 1 : 0);
  jobs_.emplace(id, std::move(job));
  job_of_key_.emplace(key, id);
  publish_progress(request.request_id, task, 0, 0, 0.0, -1.0,
                   "queued (" + std::to_string(before) + (before == 1 ? " fit" : " fits") + " before it)");
  start_next();
}

std::size_t GeometryService::queued() const {
  std::size_t n = 0;
  for (const auto& [id, job] : jobs_) n += !job.started;
  return n;
}

std::size_t GeometryService::queued_of(std::uint64_t owner) const {
  std::size_t n = 0;
  for (const auto& [id, job] : jobs_) n += !job.started && job.owner == owner;
  return n;
}

void GeometryService::start_next() {
  if (running_job_ != 0) return;
  // The owner after last_owner_ in nonce order (cyclic), then its lowest job id.
  Job* next = nullptr;
  std::int64_t next_id = 0;
  for (int pass = 0; pass < 2 && !next; ++pass) {
    for (auto& [id, job] : jobs_) {
      if (job.started || (pass == 0 && job.owner <= last_owner_)) continue;
      if (!next || job.owner < next->owner) {
        next = &job;
        next_id = id;
      }
    }
  }
  if (!next) return;
  next->started = true;
  running_job_ = next_id;
  last_owner_ = next->owner;
  worker_.submit(FitJob{next_id, next->spec, next->options});
}

void GeometryService::poll() {
  for (const FitEvent& event : worker_.take_events()) {
    const BusyTimer busy(&busy_time_);
    if (event.kind == FitEvent::Kind::kProgress) {
      const auto it = jobs_.find(event.job);
      if (it == jobs_.end()) continue;
      it->second.stage = event.stage;
      it->second.done = event.done;
      it->second.total = event.total;
      for (const Waiter& w : it->second.waiters)
        publish_progress(w.request_id, it->second.task, event.done, event.total, event.elapsed, event.remaining,
                         event.stage);
    } else {
      finish(event);
    }
  }
  start_next();
}

std::string GeometryService::activity() const {
  if (jobs_.empty()) {
    return "idle; " + std::to_string(counters_.fits) + " models fitted, " + std::to_string(counters_.from_cache) +
           " answered from the cache";
  }
  std::string out = "starting a fit";
  if (const auto it = jobs_.find(running_job_); it != jobs_.end()) {
    const Job& running = it->second;
    out = running.task;
    if (running.total > 0) {
      out += " (" + (running.stage.empty() ? std::string("started") : running.stage) + ", " +
             std::to_string(100 * running.done / running.total) + " %)";
    }
  }
  if (const std::size_t n = queued(); n > 0) out += ", " + std::to_string(n) + " more queued";
  return out;
}

void GeometryService::finish(const FitEvent& event) {
  const auto it = jobs_.find(event.job);
  if (it == jobs_.end()) return;
  Job job = std::move(it->second);
  jobs_.erase(it);
  if (event.job == running_job_) running_job_ = 0;
  job_of_key_.erase(job.model_key);
  const std::string short_key = job.model_key.substr(0, kKeyPrefix);
  std::string outcome = "done";
  if (event.kind == FitEvent::Kind::kFinished) {
    ++counters_.fits;
    const spline_model_t& full = event.model;
    try {
      cache_.store(full);  // always: the cache holds every model
      std::vector<geometry_table_t> tables;
      for (const geometry_table_t& t : event.tables) tables.push_back(cache_.store_table(t));
      spline_model_t answer = answer_message(full, cache_.path(job.model_key));
      const std::string where = answer.file_path.empty()
                                    ? std::string("inline")
                                    : "file " + answer.file_path + " (" + std::to_string(answer.file_size) + " B)";
      for (const Waiter& w : job.waiters) {
        publish_tables(tables, w);
        publish_model(answer, w);
      }
      std::cerr << sender_ << ": model " << short_key << " fitted in " << seconds_text(event.elapsed) << " (geometry "
                << seconds_text(event.geometry_seconds) << ", sampling " << seconds_text(full.sampling_seconds)
                << ", fitting " << seconds_text(full.fitting_seconds) << "), " << where << ", "
                << job.waiters.size() << (job.waiters.size() == 1 ? " request" : " requests") << " answered\n";
    } catch (const std::exception& e) {
      outcome = std::string("failed: ") + e.what();
    }
  } else {
    outcome = "failed: " + event.stage;
  }
  if (outcome != "done") {
    ++counters_.failed;
    counters_.failed_requests += static_cast<std::int64_t>(job.waiters.size());
    std::cerr << sender_ << ": model " << short_key << " (" << job.task << ") " << outcome << "\n";
  }
  for (const Waiter& w : job.waiters)
    publish_progress(w.request_id, job.task, event.total, event.total, event.elapsed, 0.0, outcome);
}

void GeometryService::publish_model(spline_model_t message, const Waiter& waiter) {
  message.request_id = waiter.request_id;
  model_stamper_.stamp(message.header);
  if (bus::publish_signed(lcm_, waiter.reply_channel, message) != 0)
    rejections_.reject(waiter.reply_channel, "publishing the model failed");
  ++counters_.answered;
  latencies_.add(bus::monotonic_seconds() - waiter.received);
}

void GeometryService::publish_tables(std::vector<geometry_table_t> tables, const Waiter& waiter) {
  for (geometry_table_t& t : tables) {
    t.request_id = waiter.request_id;
    table_stamper_.stamp(t.header);
    if (bus::publish_signed(lcm_, table_channel_, t) != 0) rejections_.reject(table_channel_, "publishing a geometry table failed");
  }
}

void GeometryService::publish_progress(std::int64_t request_id, const std::string& task, long done, long total,
                                       double elapsed, double remaining, const std::string& message) {
  progress_t p{};
  p.request_id = request_id;
  p.task = task;
  p.done = done;
  p.total = total;
  p.elapsed = elapsed;
  p.remaining = remaining;
  p.message = message;
  progress_stamper_.stamp(p.header);
  if (bus::publish_signed(lcm_, progress_channel_, p) != 0) rejections_.reject(progress_channel_, "publishing progress failed");
}

void GeometryService::add_load(bus::ServiceLoad& load) const {
  load.requests_handled += counters_.answered;
  load.requests_rejected += rejections_.count() + counters_.dropped + counters_.failed_requests;
  latencies_.summarise(load);
}

double GeometryService::take_busy_time() { return std::exchange(busy_time_, 0.0) + worker_.take_busy_time(); }

}  // namespace wrc::geometryd
