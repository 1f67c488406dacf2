// SPDX-License-Identifier: Apache-2.0
// Bus baseline: round-trip latency between two processes on a real udpm bus.
//   BareLcm    : plain lcm-cpp, typed subscribe on both sides (the floor)
//   BusLayer   : wrc::bus::RequestClient -> wrc-pingd (RequestServer + ServiceLoop)
//   Interleaved: both alternately in one loop (same machine noise for both); reports the ratio
// Each reports median and p99 of the single round trips [us]. Run on a private bus:
//   clients/lib/netns.sh build/tests/bench_bus
// (`bench_bus --bare-echo` is the bare echo process it starts itself.)

#include <benchmark/benchmark.h>
#include <lcm/lcm-cpp.hpp>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "bare_client.hpp"
#include "bench_bus_key.hpp"
#include "bus/process/build_paths.hpp"
#include "bus/process/shutdown_signal.hpp"
#include "bus/process/spawn_child.hpp"
#include "bus/process/stop_children.hpp"
#include "bus/service/percentile.hpp"
#include "bus/transport/channels.hpp"
#include "bus/transport/clock.hpp"
#include "bus/transport/request_client.hpp"
#include "wrc/ping_reply_t.hpp"
#include "wrc/ping_request_t.hpp"

namespace {

constexpr const char* kBarePing = "BENCH_BARE_PING";
constexpr const char* kBarePong = "BENCH_BARE_PONG";

// ---- the bare echo process: plain LCM, typed handler, no checks --------------------------------
struct BareEcho {
  lcm::LCM& lcm;
  void on_ping(const lcm::ReceiveBuffer*, const std::string&, const wrc::ping_request_t* req) {
    wrc::ping_reply_t reply{};
    reply.request_id = req->request_id;
    lcm.publish(kBarePong, &reply);
  }
};

int run_bare_echo() {
  wrc::bus::ShutdownSignal::install();
  lcm::LCM lcm("");
  if (!lcm.good()) return 1;
  BareEcho echo{lcm};
  lcm.subscribe(kBarePing, &BareEcho::on_ping, &echo);
  while (!wrc::bus::ShutdownSignal::requested()) lcm.handleTimeout(100);
  return 0;
}

// ---- set-up shared by the benchmarks ------------------------------------------------------------
pid_t spawn(const std::vector<std::string>& words) { return wrc::bus::spawn_tied_child(words, SIGKILL); }

struct Bench {
  using Client = wrc::bus::RequestClient<wrc::ping_request_t, wrc::ping_reply_t>;
  std::unique_ptr<lcm::LCM> lcm;
  std::unique_ptr<wrc::bench::BareClient<wrc::ping_request_t, wrc::ping_reply_t>> bare;
  std::unique_ptr<Client> layer;
  std::vector<pid_t> children;

  Bench() {
    wrc::bench::use_temporary_bus_key();
    lcm = std::make_unique<lcm::LCM>("");
    if (!lcm->good()) throw std::runtime_error("LCM not usable (run through clients/lib/netns.sh)");
    const auto pingd = wrc::bus::find_service_executable("wrc-pingd", wrc::bus::build_dir());
    if (!pingd) throw std::runtime_error("wrc-pingd is not built");
    children.push_back(spawn({"/proc/self/exe", "--bare-echo"}));
    children.push_back(spawn({*pingd, "--instance", "bench"}));
    wrc::ping_request_t ping{};
    ping.reply_channel = kBarePong;
    bare = std::make_unique<wrc::bench::BareClient<wrc::ping_request_t, wrc::ping_reply_t>>(*lcm, kBarePing,
                                                                                          kBarePong, ping);
    const wrc::bus::ChannelNames names;
    const std::string id = wrc::bus::make_client_id("bench");
    layer = std::make_unique<Client>(*lcm, names.name(wrc::bus::channel::kPing),
                                     names.name(wrc::bus::channel::kPingReply, id), id);
    // wait until both echo processes answer (they are starting up)
    const double deadline = wrc::bus::monotonic_seconds() + 10.0;
    bool bare_ok = false, layer_ok = false;
    while ((!bare_ok || !layer_ok) && wrc::bus::monotonic_seconds() < deadline) {
      if (!bare_ok) bare_ok = bare->round_trip();
      wrc::ping_request_t req{};
      if (!layer_ok) layer_ok = static_cast<bool>(layer->call(req, {0.1, 0}));
    }
    if (!bare_ok || !layer_ok) throw std::runtime_error("echo processes do not answer");
  }
  ~Bench() { wrc::bus::stop_children(children, 5.0); }
};

Bench& bench() {
  static Bench instance;
  return instance;
}

using wrc::bus::percentile;

void report(benchmark::State& state, const std::string& prefix, const std::vector<double>& us) {
  state.counters[prefix + "median_us"] = percentile(us, 0.5);
  state.counters[prefix + "p99_us"] = percentile(us, 0.99);
}

bool layer_round_trip() {
  wrc::ping_request_t req{};
  return static_cast<bool>(bench().layer->call(req, {1.0, 0}));
}

void BareLcm(benchmark::State& state) {
  std::vector<double> us;
  for (auto _ : state) {
    const double t0 = wrc::bus::monotonic_seconds();
    if (!bench().bare->round_trip()) state.SkipWithError("bare round trip timed out");
    us.push_back((wrc::bus::monotonic_seconds() - t0) * 1e6);
  }
  report(state, "", us);
}

void BusLayer(benchmark::State& state) {
  std::vector<double> us;
  for (auto _ : state) {
    const double t0 = wrc::bus::monotonic_seconds();
    if (!layer_round_trip()) state.SkipWithError("layer round trip timed out");
    us.push_back((wrc::bus::monotonic_seconds() - t0) * 1e6);
  }
  report(state, "", us);
}

void Interleaved(benchmark::State& state) {
  std::vector<double> bare_us, layer_us;
  for (auto _ : state) {
    double t0 = wrc::bus::monotonic_seconds();
    if (!bench().bare->round_trip()) state.SkipWithError("bare round trip timed out");
    bare_us.push_back((wrc::bus::monotonic_seconds() - t0) * 1e6);
    t0 = wrc::bus::monotonic_seconds();
    if (!layer_round_trip()) state.SkipWithError("layer round trip timed out");
    layer_us.push_back((wrc::bus::monotonic_seconds() - t0) * 1e6);
  }
  report(state, "bare_", bare_us);
  report(state, "layer_", layer_us);
  state.counters["layer_over_bare"] = percentile(layer_us, 0.5) / percentile(bare_us, 0.5);
}

BENCHMARK(BareLcm)->Iterations(20000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BusLayer)->Iterations(20000)->Unit(benchmark::kMicrosecond);
BENCHMARK(Interleaved)->Iterations(20000)->Unit(benchmark::kMicrosecond);

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "--bare-echo") return run_bare_echo();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  try {
    bench();
  } catch (const std::exception& e) {
    std::cerr << "bench_bus: " << e.what() << "\n";
    return 1;
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
