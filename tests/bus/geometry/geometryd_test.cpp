// SPDX-License-Identifier: Apache-2.0
// wrc-geometryd as a real process on a real udpm bus (private network namespace,
// clients/lib/netns.sh): a request gets progress and then the spline model (request id echoed,
// resolvable, decodable, with the model key of its geometry and options); the same request again
// is answered from the cache; heartbeats keep coming during a default-size fit, and a request for
// a model being fitted waits for that fit instead of starting another; invalid requests are
// answered with a "rejected: " progress naming the field, garbage is counted, and the service
// keeps answering; `wrc launch` starts it and `wrc status` lists it. Every test has a cache
// directory of its own under its temporary directory, removed afterwards when the test passed.
#include <signal.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "bus/transport/clock.hpp"
#include "bus_fixture.hpp"
#include "core/identity/geometry_key.hpp"
#include "core/spline/wheel_sample.hpp"
#include "small_fit_options.hpp"
#include "geometryd/geometry_service.hpp"
#include "geometryd/geometryd_options.hpp"
#include "geometryd/model_cache.hpp"
#include "protocol/geometry/fit_options_codec.hpp"
#include "protocol/geometry/geometry_table_codec.hpp"
#include "protocol/geometry/spline_model_codec.hpp"
#include "protocol/geometry/spline_model_file.hpp"
#include "protocol/geometry/track_codec.hpp"
#include "wrc/geometry_request_t.hpp"
#include "wrc/geometry_table_t.hpp"
#include "wrc/heartbeat_t.hpp"
#include "wrc/progress_t.hpp"
#include "wrc/spline_model_t.hpp"

namespace wrc::bus::test {
namespace {

namespace fs = std::filesystem;
using protocol::decode_model;
using protocol::resolve_model;

constexpr double kPeriod = 0.2;  // [s] heartbeat period of the services started here

/// Heartbeats of wrc-geometryd as they arrive.
struct Beat {
  double at = 0.0;  // [s] monotonic arrival time
  wrc::heartbeat_t message;
};

class GeometryServiceTest : public BusTest {
 protected:
  void SetUp() override {
    BusTest::SetUp();
    cache_dir_ = temp_path("cache/models");  // missing: the service creates it
    log_ = temp_path("geometryd.log");
    reply_channel_ = names_.name(channel::kSplineModel, make_client_id("gtest"));
    subscriptions_.push_back(lcm_->subscribe(regex_escape(names_.name(channel::kProgress)),
                                             &GeometryServiceTest::on_progress, this));
    subscriptions_.push_back(lcm_->subscribe(regex_escape(reply_channel_), &GeometryServiceTest::on_model, this));
    subscriptions_.push_back(lcm_->subscribe(regex_escape(names_.name(channel::kSplineModel)),
                                             &GeometryServiceTest::on_model, this));
    subscriptions_.push_back(lcm_->subscribe(regex_escape(names_.name(channel::kHeartbeat)),
                                             &GeometryServiceTest::on_heartbeat, this));
    subscriptions_.push_back(lcm_->subscribe(regex_escape(names_.name(channel::kGeometryTable)),
                                             &GeometryServiceTest::on_table, this));
  }
  void TearDown() override {
    if (service_ && service_->running()) {
      service_->signal(SIGTERM);
      int status = -1;
      EXPECT_TRUE(service_->wait(5.0, &status)) << "wrc-geometryd did not stop on SIGTERM";
      EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status << "\n" << read_text(log_);
    }
    service_.reset();
    for (auto* s : subscriptions_) lcm_->unsubscribe(s);
    BusTest::TearDown();  // the cache and the logs
  }

  void on_progress(const lcm::ReceiveBuffer*, const std::string&, const wrc::progress_t* p) {
    progress_[p->request_id].push_back(*p);
  }
  void on_model(const lcm::ReceiveBuffer*, const std::string& channel, const wrc::spline_model_t* m) {
    models_[m->request_id] = *m;
    model_channels_[m->request_id] = channel;
    model_arrival_[m->request_id] = monotonic_seconds();
  }
  void on_table(const lcm::ReceiveBuffer*, const std::string&, const wrc::geometry_table_t* t) {
    tables_[t->request_id].push_back(*t);
  }
  void on_heartbeat(const lcm::ReceiveBuffer*, const std::string&, const wrc::heartbeat_t* h) {
    if (h->model == "geometryd") beats_.push_back({monotonic_seconds(), *h});
  }

  /// Starts wrc-geometryd (instance t, heartbeat period kPeriod, the test's cache) and waits for READY.
  void start_service() {
    service_ = std::make_unique<ChildProcess>(
        WRC_GEOMETRYD_PATH,
        std::vector<std::string>{"--instance", "t", "--heartbeat-period", std::to_string(kPeriod), "--cache-dir", cache_dir_},
        log_);
    ASSERT_TRUE(wait_ready("geometryd", "t", 5.0)) << read_text(log_);
  }

  wrc::geometry_request_t make_request(std::int64_t id, const SplineFitOptions& options, bool recompute = false,
                                       bool default_channel = false) const {
    wrc::geometry_request_t r{};
    r.request_id = id;
    r.reply_channel = default_channel ? std::string() : reply_channel_;
    r.track = protocol::to_message(GeometrySpec{});
    r.fit = protocol::to_message(options);
    r.recompute = recompute;
    return r;
  }
  void send(wrc::geometry_request_t request) { publish_signed(*lcm_, names_.name(channel::kGeometryRequest), request); }

  /// Waits for the model answering request id; nothing after timeout [s].
  std::optional<wrc::spline_model_t> wait_model(std::int64_t id, double timeout) {
    if (!handle_until([&] { return models_.count(id) > 0 || process_gone(service_->pid()); }, timeout)) return {};
    if (!models_.count(id)) return {};
    return models_.at(id);
  }
  /// Waits for the progress of request id whose message starts with prefix.
  std::optional<wrc::progress_t> wait_progress(std::int64_t id, const std::string& prefix, double timeout) {
    auto find = [&]() -> std::optional<wrc::progress_t> {
      for (const auto& p : progress_[id])
        if (p.message.rfind(prefix, 0) == 0) return p;
      return {};
    };
    handle_until([&] { return find().has_value(); }, timeout);
    return find();
  }

  std::string cache_dir_;
  std::string log_;
  std::string reply_channel_;
  std::unique_ptr<ChildProcess> service_;
  std::vector<lcm::Subscription*> subscriptions_;
  std::map<std::int64_t, std::vector<wrc::progress_t>> progress_;
  std::map<std::int64_t, wrc::spline_model_t> models_;
  std::map<std::int64_t, std::string> model_channels_;
  std::map<std::int64_t, double> model_arrival_;
  std::map<std::int64_t, std::vector<wrc::geometry_table_t>> tables_;
  std::vector<Beat> beats_;
};

// (a) a small model: progress, then the model with request id echoed, resolvable and decodable,
// with the model key of its geometry and options, stored in the cache (0700 directory made by
// the service); (b) the same request again is answered from the cache, faster, same model_hash,
// also on the default channel SPLINE_MODEL; recompute fits again.
TEST_F(GeometryServiceTest, FitsASmallModelThenAnswersFromTheCache) {
  start_service();
  const SplineFitOptions options = small_fit_options();
  const std::string key = protocol::model_key(geometry_key(GeometrySpec{}), options);

  double t0 = monotonic_seconds();
  send(make_request(11, options));
  const auto fitted = wait_model(11, 20.0);
  ASSERT_TRUE(fitted) << read_text(log_);
  const double fit_answer = model_arrival_.at(11) - t0;
  EXPECT_EQ(model_channels_.at(11), reply_channel_);
  EXPECT_EQ(fitted->model_key, key);
  EXPECT_EQ(fitted->geometry_key, geometry_key(GeometrySpec{}));
  EXPECT_FALSE(fitted->header.sender.empty());
  EXPECT_GT(fitted->header.utime, 0);
  spline_model_t full;
  ASSERT_NO_THROW(full = resolve_model(*fitted));
  EXPECT_EQ(full.request_id, 11);
  std::shared_ptr<const SplineContactGeometry> model;
  ASSERT_NO_THROW(model = decode_model(full));
  EXPECT_EQ(model->data_hash(), fitted->model_hash);
  EXPECT_TRUE(fs::is_regular_file(fs::path(cache_dir_) / (key + geometryd::kModelFileExtension)));
  EXPECT_EQ(fs::status(cache_dir_).permissions() & fs::perms::all, fs::perms::owner_all);

  const auto final_progress = wait_progress(11, "done", 2.0);
  ASSERT_TRUE(final_progress) << read_text(log_);
  EXPECT_GT(final_progress->total, 0);
  EXPECT_EQ(final_progress->done, final_progress->total);
  EXPECT_EQ(final_progress->task, "spline fit S1002/UIC60 4x1x1");
  ASSERT_GE(progress_[11].size(), 2u) << "no progress before the final one";
  for (std::size_t i = 1; i < progress_[11].size(); ++i)
    EXPECT_GE(progress_[11][i].elapsed, progress_[11][i - 1].elapsed);

  t0 = monotonic_seconds();
  send(make_request(12, options));
  const auto cached = wait_model(12, 5.0);
  ASSERT_TRUE(cached) << read_text(log_);
  const double cache_answer = model_arrival_.at(12) - t0;
  EXPECT_EQ(cached->model_hash, fitted->model_hash);
  EXPECT_EQ(cached->model_key, key);
  EXPECT_NO_THROW(decode_model(resolve_model(*cached)));
  EXPECT_LT(cache_answer, fit_answer);
  EXPECT_TRUE(progress_[12].empty()) << "a cache hit fits nothing";

  send(make_request(13, options, false, true));  // no reply channel: SPLINE_MODEL
  ASSERT_TRUE(wait_model(13, 5.0)) << read_text(log_);
  EXPECT_EQ(model_channels_.at(13), names_.name(channel::kSplineModel));
  EXPECT_EQ(models_.at(13).model_hash, fitted->model_hash);

  send(make_request(14, options, true));  // recompute
  ASSERT_TRUE(wait_model(14, 20.0)) << read_text(log_);
  EXPECT_EQ(models_.at(14).model_hash, fitted->model_hash) << "the fit is deterministic";
  EXPECT_TRUE(wait_progress(14, "done", 2.0));

  const std::string text = read_text(log_);
  EXPECT_NE(text.find("request 12 answered from the cache"), std::string::npos) << text;
  EXPECT_NE(text.find("request 13 answered from the cache"), std::string::npos) << text;
  EXPECT_NE(text.find("request 14: fitting model " + key.substr(0, 12) + " (spline fit S1002/UIC60 4x1x1, recompute)"),
            std::string::npos)
      << text;
  std::printf("small model: answer after a fit %.3f s, from the cache %.4f s (%s)\n", fit_answer, cache_answer,
              fitted->file_path.empty() ? "inline" : "file");
}

// The exact samples behind a fit are published on GEOMETRY_TABLE before the model, one table per
// wheel, as checked files in the cache: the table's values are the exact geometry at its grid
// points (against sample_wheel, to 1e-15 m: the same computation), its z column is what the model
// was fitted to (over the continuous region's samples, the largest |z_model - z_table| is the
// model's published fit_max_error for z), and a cache hit republishes the same tables.
TEST_F(GeometryServiceTest, PublishesTheExactSamplesAsGeometryTables) {
  start_service();
  const SplineFitOptions options = small_fit_options();
  send(make_request(21, options));
  const auto fitted = wait_model(21, 20.0);
  ASSERT_TRUE(fitted) << read_text(log_);
  ASSERT_EQ(tables_[21].size(), 2u) << read_text(log_);
  const auto model = decode_model(resolve_model(*fitted));
  const WheelsetGeometry geometry = make_geometry(GeometrySpec{});
  for (const wrc::geometry_table_t& reference : tables_[21]) {
    EXPECT_EQ(reference.num_values, 0);  // the values are in the file
    EXPECT_EQ(reference.model_key, fitted->model_key);
    const wrc::geometry_table_t t = protocol::resolve_table(reference);
    const WheelSide side = t.wheel == wrc::geometry_table_t::LEFT ? WheelSide::kLeft : WheelSide::kRight;
    ASSERT_EQ(t.column_names[kFieldZ], "z");
    const int columns = t.num_columns;
    double worst_fit = 0;
    int checked = 0;
    const int valid = columns - 3, jump_distance = columns - 1;
    for (int j = 0; j < t.roll_count; ++j)
      for (int k = 0; k < t.yaw_count; ++k)
        for (int i = 0; i < t.y_count; ++i) {
          WheelsetPose p;
          p.y = t.y_min + (t.y_max - t.y_min) * i / (t.y_count - 1);
          p.roll = t.roll_count > 1 ? t.roll_min + (t.roll_max - t.roll_min) * j / (t.roll_count - 1) : t.roll_min;
          p.yaw = t.yaw_count > 1 ? t.yaw_min + (t.yaw_max - t.yaw_min) * k / (t.yaw_count - 1) : t.yaw_min;
          p.z = 0.46;
          const double* row = &t.values[static_cast<size_t>(((j * t.yaw_count + k) * t.y_count + i) * columns)];
          SplineEvaluation e;
          model->evaluate(side, p, SplineDerivatives::kValue, e);
          if (row[valid] == 1.0 && row[jump_distance] >= options.jump_band && row[kFieldFlangeClearance] > 0.0)
            worst_fit = std::max(worst_fit, std::abs(e.value[kFieldZ] - row[kFieldZ]));
          if ((i + j + k) % 7 != 0) continue;
          const WheelSample exact = sample_wheel(geometry, side, p, model->s_split(), options.clearance_cap, 0.01, options.search);
          EXPECT_NEAR(row[kFieldZ], exact.fields[kFieldZ], 1e-15);
          EXPECT_NEAR(row[kFieldSWheel], exact.fields[kFieldSWheel], 1e-15);
          ++checked;
        }
    EXPECT_GT(checked, 10);
    const double published = fitted->wheels[static_cast<int>(side)].fit_max_error[kFieldZ];
    EXPECT_GT(published, 0.0);
    EXPECT_NEAR(worst_fit, published, 1e-12);
  }
  send(make_request(22, options));
  ASSERT_TRUE(wait_model(22, 5.0)) << read_text(log_);
  ASSERT_EQ(tables_[22].size(), 2u);
  EXPECT_EQ(tables_[22][0].table_hash, tables_[21][0].table_hash);
  EXPECT_EQ(tables_[22][1].file_hash, tables_[21][1].file_hash);
}

// (c) heartbeats keep coming (READY, gaps below two periods) during a default-size fit (~1.5 s);
// progress comes at most every 0.2 s with a linear estimate of the remaining time; a second
// request for the same model waits for that fit (one fit, both answered, one log line).
TEST_F(GeometryServiceTest, HeartbeatsKeepComingDuringADefaultFit) {
  start_service();
  const SplineFitOptions options;  // the default model
  const double t0 = monotonic_seconds();
  send(make_request(21, options));
  handle_until([] { return false; }, 0.3);
  send(make_request(22, options));
  const auto first = wait_model(21, 30.0);
  ASSERT_TRUE(first) << read_text(log_);
  const auto second = wait_model(22, 2.0);
  ASSERT_TRUE(second) << read_text(log_);
  const double t1 = model_arrival_.at(21);
  EXPECT_EQ(second->model_hash, first->model_hash);
  EXPECT_NO_THROW(decode_model(resolve_model(*first)));
  handle_until([] { return false; }, 2 * kPeriod);  // the heartbeat after the answer

  double max_gap = 0.0;
  int during = 0;
  double previous = -1.0;
  for (const Beat& b : beats_) {
    if (b.at < t0 - kPeriod) continue;
    if (previous >= 0.0) max_gap = std::max(max_gap, b.at - previous);
    previous = b.at;
    if (b.at > t0 && b.at < t1) {
      ++during;
      EXPECT_EQ(b.message.state, wrc::heartbeat_t::READY);
    }
  }
  EXPECT_LT(max_gap, 2 * kPeriod) << "heartbeat gap during the fit";
  // What the heartbeats say it is doing: the fit with its stage while it runs, idle afterwards.
  int fitting = 0;
  for (const Beat& b : beats_)
    if (b.at > t0 + kPeriod && b.at < t1 - kPeriod)
      fitting += b.message.activity.rfind("spline fit S1002/UIC60 10x2x2 (", 0) == 0 ? 1 : 0;
  EXPECT_GE(fitting, 1) << "no heartbeat named the running fit";
  ASSERT_FALSE(beats_.empty());
  EXPECT_EQ(beats_.back().message.activity, "idle; 1 models fitted, 0 answered from the cache");
  EXPECT_GE(during, static_cast<int>((t1 - t0) / kPeriod) - 1) << "fit took " << (t1 - t0) << " s";

  const auto& progress = progress_[21];
  ASSERT_TRUE(wait_progress(21, "done", 2.0));
  ASSERT_GE(progress.size(), 4u);
  // At once: queued, with nothing before it; then the worker's reports, at most every 0.2 s.
  EXPECT_EQ(progress[0].message, "queued (0 fits before it)");
  bool estimated = false;
  for (std::size_t i = 0; i + 1 < progress.size(); ++i) {
    const auto& p = progress[i];
    EXPECT_EQ(p.task, "spline fit S1002/UIC60 10x2x2");
    EXPECT_LE(p.done, p.total);
    if (i > 1) {
      EXPECT_GE(p.elapsed - progress[i - 1].elapsed, 0.19) << "progress too often";
    }
    estimated = estimated || p.remaining > 0.0;
  }
  EXPECT_TRUE(estimated) << "no remaining-time estimate";
  EXPECT_TRUE(wait_progress(22, "done", 1.0)) << "the waiting request gets the final progress too";

  const std::string text = read_text(log_);
  EXPECT_NE(text.find("request 22 waits for the fit of model"), std::string::npos) << text;
  const auto fitted_line = text.find(" fitted in ");
  ASSERT_NE(fitted_line, std::string::npos) << text;
  EXPECT_EQ(text.find(" fitted in ", fitted_line + 1), std::string::npos) << "fitted twice:\n" << text;
  EXPECT_NE(text.find("2 requests answered"), std::string::npos) << text;
  const double t2 = monotonic_seconds();
  send(make_request(23, options));
  const auto cached = wait_model(23, 5.0);
  ASSERT_TRUE(cached) << read_text(log_);
  EXPECT_EQ(cached->model_hash, first->model_hash);
  std::printf("default model from the cache: %.4f s\n", model_arrival_.at(23) - t2);
  std::printf("%s\n", text.substr(text.rfind('\n', fitted_line) + 1, text.find('\n', fitted_line) - text.rfind('\n', fitted_line) - 1).c_str());
  std::printf("default model: answered after %.3f s (%s, %lld B on disk), heartbeat max gap %.3f s\n", t1 - t0,
              first->file_path.empty() ? "inline" : "file", static_cast<long long>(first->file_size), max_gap);
}

// `wrc fit --service`: the front end asks the running service, follows its progress (the bar,
// one line per 10 % off a terminal) and names the model; the service's cache keeps it and answers
// the same command again from there.
TEST_F(GeometryServiceTest, FitCommandPrecomputesOnTheService) {
  start_service();
  const SplineFitOptions options = small_fit_options();
  const std::string key = protocol::model_key(geometry_key(GeometrySpec{}), options);
  const std::string command = std::string(WRC_CLI_PATH) +
                              " fit --service --knots 4x1x1 --degree 3x1x1 --samples 3x3 --sample-step 5e-4 2>&1";
  int status = -1;
  const std::string first = run_command(command, &status);
  ASSERT_EQ(status, 0) << first;
  EXPECT_NE(first.find("spline model " + key.substr(0, 12) + ", model hash "), std::string::npos) << first;
  EXPECT_NE(first.find("fit on wrc-geometryd: done in "), std::string::npos) << first;
  EXPECT_NE(first.find(" %"), std::string::npos) << "no progress line:\n" << first;
  const std::string file = (fs::path(cache_dir_) / (key + ".splinemodel")).string();
  EXPECT_NE(first.find("model inline in the answer ("), std::string::npos) << "a small model travels inline\n" << first;
  EXPECT_TRUE(fs::exists(file)) << "the cache keeps every model";
  const std::string again = run_command(command, &status);
  ASSERT_EQ(status, 0) << again;
  // The service answers first and logs after, so its line may follow the command's exit.
  EXPECT_TRUE(handle_until([&] { return read_text(log_).find("from the cache") != std::string::npos; }, 5.0))
      << read_text(log_);
}

// A flood of distinct valid requests from one sender (the test, about 1000 per second, each for a
// model of its own) while `wrc fit --service` asks for another model: the flooder holds at most
// kMaxQueuedFitsPerSender fits queued and hears "rejected: busy (N queued)" beyond, with N never
// above kMaxQueuedFits; the fits start in turn across senders, so the command's fit follows the
// one running and is answered within its --wait of 15 s (printed: how long it took, how many
// flood requests were sent, queued and refused).
TEST_F(GeometryServiceTest, AFloodFromOneSenderLeavesAnotherSendersFitWithinItsWait) {
  start_service();
  const std::string out = temp_path("fit.log");
  ChildProcess fit(WRC_CLI_PATH, {"fit", "--service", "--knots", "5x2x2", "--wait", "15"}, out);
  std::int64_t sent = 0;
  const double t0 = monotonic_seconds();
  int status = -1;
  bool ended = false;
  while (!ended && monotonic_seconds() < t0 + 30.0) {
    for (int k = 0; k < 20; ++k) {
      SplineFitOptions o = small_fit_options();
      o.sample_step_y = 5e-4 * (1.0 + 1e-6 * static_cast<double>(++sent));  // a model of its own
      send(make_request(100000 + sent, o));
    }
    handle_until([] { return false; }, 0.02);
    ended = fit.wait(0.0, &status);
  }
  const double took = monotonic_seconds() - t0;
  ASSERT_TRUE(ended) << read_text(out) << read_text(log_);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << read_text(out) << read_text(log_).substr(0, 4000);
  EXPECT_NE(read_text(out).find("spline model "), std::string::npos) << read_text(out);
  std::size_t queued = 0, busy = 0, largest = 0;
  for (const auto& [id, list] : progress_) {
    if (id <= 100000 || list.empty()) continue;
    const std::string first = list.front().message;
    if (first.rfind("queued (", 0) == 0) ++queued;
    if (first.rfind("rejected: busy (", 0) == 0) {
      ++busy;
      largest = std::max<std::size_t>(largest, std::stoul(first.substr(16)));
    }
  }
  std::printf("[ measured ] the other sender's fit answered after %.2f s while %lld flood requests were sent: %zu "
              "queued, %zu refused busy (at most %zu queued)\n",
              took, static_cast<long long>(sent), queued, busy, largest);
  EXPECT_GT(sent, 1000);
  EXPECT_GT(busy, 0u);
  EXPECT_LE(largest, geometryd::kMaxQueuedFits);
  EXPECT_TRUE(wait_ready("geometryd", "t", 5.0)) << read_text(log_);
}

// A client whose request was being fitted when wrc-geometryd stopped (killed here) sends it to
// the next service once, and when that one stops too, gives up saying why: the second service
// gets the request once, and no third is asked.
TEST_F(GeometryServiceTest, AClientSendsARequestToTheNextServiceOnceAndSaysWhyItGaveUp) {
  start_service();
  const std::string out = temp_path("fit.log");
  // 12.5 times the default's samples in y: a fit of several seconds.
  ChildProcess fit(WRC_CLI_PATH, {"fit", "--service", "--sample-step", "4e-5", "--wait", "60"}, out);
  ASSERT_TRUE(handle_until([&] { return read_text(log_).find(": fitting model ") != std::string::npos; }, 20.0))
      << read_text(out) << read_text(log_);
  service_->signal(SIGKILL);
  ASSERT_TRUE(service_->wait(5.0));
  ASSERT_TRUE(handle_until([&] { return read_text(out).find("sending it once more") != std::string::npos; }, 10.0))
      << read_text(out);
  log_ = temp_path("geometryd-2.log");
  start_service();
  ASSERT_TRUE(handle_until([&] { return read_text(log_).find(": fitting model ") != std::string::npos; }, 10.0))
      << read_text(out) << read_text(log_);
  service_->signal(SIGKILL);
  ASSERT_TRUE(service_->wait(5.0));
  int status = -1;
  ASSERT_TRUE(fit.wait(10.0, &status)) << read_text(out);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) != 0) << status;
  const std::string text = read_text(out);
  EXPECT_NE(text.find("wrc-geometryd stopped twice while it had this request; not sending it again"),
            std::string::npos)
      << text;
  const std::string second = read_text(log_);
  const auto at = second.find(": fitting model ");
  EXPECT_EQ(second.find(": fitting model ", at + 1), std::string::npos) << second;
}

// A fit that outlasts --wait: the command gives up after its wait, and says so with the wait as
// typed ("--wait 1 s", not "1.000000 s"). The fit asks for 2.5 times the default's samples in y
// and 7.7 times in roll and yaw (a default fit samples for about 1 s here: this one for about 20 s).
TEST_F(GeometryServiceTest, AFitOutlastingItsWaitIsGivenUpNamingTheWait) {
  start_service();
  const std::string out = temp_path("fit.log");
  ChildProcess fit(WRC_CLI_PATH, {"fit", "--service", "--sample-step", "4e-5", "--samples", "25x25", "--wait", "1"}, out);
  int status = -1;
  ASSERT_TRUE(fit.wait(30.0, &status)) << read_text(out);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) != 0) << status;
  const std::string text = read_text(out);
  EXPECT_NE(text.find("no spline model from wrc-geometryd within --wait 1 s"), std::string::npos) << text;
}

// SIGTERM during a fit: a DRAINING heartbeat and a clean exit, without waiting for the fit. The
// fit asked for samples 12.5 times more finely in y than the default (whose fit alone takes about
// 0.7 s here), so it runs for several seconds; the service must be gone within a deadline of 5 s
// and say that it did not wait. The time it took is printed.
TEST_F(GeometryServiceTest, StopsPromptlyDuringAFit) {
  start_service();
  SplineFitOptions slow;
  slow.sample_step_y /= 12.5;
  send(make_request(51, slow));
  // The fit runs (its own progress, not the "queued" answer that comes first).
  ASSERT_TRUE(wait_progress(51, "sampling", 5.0)) << read_text(log_);
  service_->signal(SIGTERM);
  int status = -1;
  const double t0 = monotonic_seconds();
  ASSERT_TRUE(service_->wait(5.0, &status)) << read_text(log_);
  std::cout << "[ measured ] SIGTERM to exit during a fit: " << monotonic_seconds() - t0 << " s\n";
  handle_until([] { return false; }, 0.1);
  for (const wrc::progress_t& p : progress_[51])  // it did not wait: no progress told of the fit's end
    EXPECT_EQ(std::string(p.message).rfind("done", 0), std::string::npos) << p.message;
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
  handle_until([] { return false; }, 0.1);
  ASSERT_FALSE(beats_.empty());
  EXPECT_EQ(beats_.back().message.state, wrc::heartbeat_t::DRAINING);
  const std::string text = read_text(log_);
  EXPECT_NE(text.find("a fit is still running; exiting without waiting for it"), std::string::npos) << text;
}

// (d) invalid requests get a "rejected: " progress naming the field (done = total = 0);
// (e) garbage, truncated and wrong-type messages are counted; a fit that throws is answered
// "failed: <reason>"; the service stays READY and answers.
TEST_F(GeometryServiceTest, RejectsInvalidRequestsAndSurvivesGarbage) {
  start_service();
  // First the malformed messages: the log shows at most 5 rejections a second.
  const std::string channel = names_.name(channel::kGeometryRequest);
  wrc::heartbeat_t other_type{};
  publish_signed(*lcm_, channel, other_type);
  auto truncated = make_request(35, small_fit_options());
  std::vector<unsigned char> bytes(static_cast<std::size_t>(truncated.getEncodedSize()));
  truncated.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  publish_signed_bytes(channel, {bytes.begin(), bytes.begin() + static_cast<long>(bytes.size() - 9)});
  const unsigned char garbage[] = {0xde, 0xad, 0xbe, 0xef};
  publish_signed_bytes(channel, {garbage, garbage + sizeof garbage});

  struct Case {
    std::int64_t id;
    std::function<void(wrc::geometry_request_t&)> spoil;
    std::string expected;
  };
  const std::vector<Case> cases{
      {31, [](auto& r) { r.fit.intervals[0] = 0; }, "intervals in y = 0"},
      {32, [](auto& r) { r.fit.knot_placement = 7; }, "knot_placement = 7"},
      {33, [](auto& r) { r.fit.roll_samples = 1; }, "roll_samples = 1"},
      {34, [](auto& r) { r.track.wheel_profile.content_hash = "00"; }, "content of profile 'S1002'"},
      {38, [](auto& r) { r.track.gauge = std::nan(""); }, "gauge"},
      {0, [](auto&) {}, "request_id 0 is not positive"},
  };
  for (const auto& c : cases) {
    auto r = make_request(c.id, small_fit_options());
    c.spoil(r);
    send(r);
    const auto p = wait_progress(c.id, "rejected: ", 3.0);
    ASSERT_TRUE(p) << c.expected << "\n" << read_text(log_);
    EXPECT_NE(p->message.find(c.expected), std::string::npos) << p->message;
    EXPECT_EQ(p->done, 0);
    EXPECT_EQ(p->total, 0);
    EXPECT_EQ(models_.count(c.id), 0u);
  }

  // A fit that throws (a gauge of 1.6 m, valid but wider than the wheelset: no tread contact)
  // fails; the service stays up.
  auto wide = make_request(37, small_fit_options());
  wide.track.gauge = 1.6;
  send(wide);
  const auto failed = wait_progress(37, "failed: ", 10.0);
  ASSERT_TRUE(failed) << read_text(log_);
  EXPECT_NE(failed->message.find("no tread contact point"), std::string::npos) << failed->message;
  EXPECT_EQ(failed->done, failed->total);
  EXPECT_EQ(models_.count(37), 0u);

  send(make_request(36, small_fit_options()));
  ASSERT_TRUE(wait_model(36, 20.0)) << read_text(log_);
  EXPECT_EQ(models_.count(35), 0u);
  ASSERT_TRUE(handle_until(
      [&] {
        auto s = monitor_->find("geometryd", "t", monotonic_seconds());
        return s && s->last.requests_rejected >= 10 && s->last.requests_handled >= 1;
      },
      3.0))
      << "the heartbeat does not report the 9 rejections, the failed fit and the answer";
  const auto status = monitor_->find("geometryd", "t", monotonic_seconds());
  EXPECT_TRUE(status->available());
  EXPECT_EQ(status->last.requests_rejected, 10);
  EXPECT_EQ(status->last.requests_handled, 1);
  const std::string text = read_text(log_);
  EXPECT_NE(text.find("fingerprint mismatch"), std::string::npos) << text;
  EXPECT_NE(text.find("truncated or corrupt geometry_request_t"), std::string::npos) << text;
  EXPECT_NE(text.find("too short"), std::string::npos) << text;
}

// `wrc launch geometry` (default profile) starts wrc-geometryd; `wrc status` lists it.
TEST_F(GeometryServiceTest, LaunchStartsItAndStatusListsIt) {
  ::setenv("WRC_CACHE_DIR", cache_dir_.c_str(), 1);  // the profile line has no --cache-dir
  const std::string log = temp_path("launch.log");
  const auto launcher = launch({"geometry"}, log);
  ASSERT_TRUE(wait_ready("geometryd", "0", 10.0)) << read_text(log);
  int status = -1;
  const std::string out = run_command(std::string(WRC_CLI_PATH) + " status --duration 1.2 --format csv", &status);
  EXPECT_EQ(status, 0);
  EXPECT_NE(out.find("geometryd,0,"), std::string::npos) << out;
  EXPECT_NE(out.find(",READY,1,"), std::string::npos) << out;
  EXPECT_NE(out.find("," + names_.name(channel::kGeometryRequest) + ",\"idle; "), std::string::npos) << out;
  EXPECT_TRUE(fs::is_directory(cache_dir_)) << "the service did not use $WRC_CACHE_DIR";
  launcher->signal(SIGINT);
  ASSERT_TRUE(launcher->wait(10.0, &status)) << read_text(log);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << read_text(log);
  ::unsetenv("WRC_CACHE_DIR");
}

// ---- options, in-process --------------------------------------------------------------------------

TEST(GeometrydOptions, CacheDirDefaultsAndUnknownOptions) {
  const char* saved[3] = {std::getenv("WRC_CACHE_DIR"), std::getenv("XDG_CACHE_HOME"), std::getenv("HOME")};
  const std::string keep[3] = {saved[0] ? saved[0] : "", saved[1] ? saved[1] : "", saved[2] ? saved[2] : ""};
  ::setenv("WRC_CACHE_DIR", "/w", 1);
  ::setenv("XDG_CACHE_HOME", "/x", 1);
  ::setenv("HOME", "/h", 1);
  EXPECT_EQ(geometryd::default_cache_dir(), "/w");
  ::setenv("WRC_CACHE_DIR", "", 1);
  EXPECT_EQ(geometryd::default_cache_dir(), "/x/wrc/models");
  ::unsetenv("XDG_CACHE_HOME");
  EXPECT_EQ(geometryd::default_cache_dir(), "/h/.cache/wrc/models");
  EXPECT_EQ(geometryd::GeometrydOptions::parse({}).cache_dir, "/h/.cache/wrc/models");
  EXPECT_EQ(geometryd::GeometrydOptions::parse({"--cache-dir", "/c"}).cache_dir, "/c");
  EXPECT_EQ(geometryd::GeometrydOptions::parse({"--cache-dir=/d"}).cache_dir, "/d");
  try {
    geometryd::GeometrydOptions::parse({"--model", "spline"});
    ADD_FAILURE() << "an unknown option was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("unknown option --model"), std::string::npos) << e.what();
  }
  EXPECT_THROW(geometryd::GeometrydOptions::parse({"--cache-dir"}), std::invalid_argument);
  const char* names[3] = {"WRC_CACHE_DIR", "XDG_CACHE_HOME", "HOME"};
  for (int i = 0; i < 3; ++i) {
    if (saved[i]) {
      ::setenv(names[i], keep[i].c_str(), 1);
    } else {
      ::unsetenv(names[i]);
    }
  }
}

}  // namespace
}  // namespace wrc::bus::test
