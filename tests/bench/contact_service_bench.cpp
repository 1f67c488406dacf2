// SPDX-License-Identifier: Apache-2.0
// Contact service round trip against its floors, measured interleaved in one run (same machine
// noise for all):
//   bare_ping     : plain lcm-cpp echo of an empty ping_request_t (the bus baseline of bus_bench)
//   bare_contact  : plain lcm-cpp echo with the contact message types and sizes (query of one
//                   configuration in, reply with two patches out; no checks, no computation)
//   bare_compute  : the bare echo that also evaluates the query with the model (no bus layer, no
//                   adapter): the floor of a service round trip that waits for the computation
//   service       : wrc::bus::RequestClient -> wrc-contactd --model onepoint, one configuration,
//                   both wheels, FASTSIM 20x20
//   in_process    : ContactModel::evaluate of the same query in this process
//   *_eval        : the evaluation time measured inside the echo (the model) and the service (the
//                   model and its message adapter)
// Every iteration runs the measurements in a new random order (fixed seed): a process that has
// just answered is warmer (caches, scheduler) than one that has waited, and no round trip may
// profit from always coming right after its own process's last answer.
// Goal: median(service) <= median(bare) + median(in_process) + 0.1 median(bare), checked
// against both bare floors (goal_ping, goal_contact; 1 = met). PerModel/<i> measures each of the
// four services against bare_contact the same way (service_over_bare: the spline model's goal is
// at most 1.2; wrc-geometryd is started for it with a cache directory of its own).
// Run on a private bus (WRC_BENCH_SERVICES=1 starts the one-point service alone: every process
// on an LCM bus receives every message, so fewer listeners mean less noise; WRC_BENCH_PIN=1 puts
// this process on CPU 0 and the echo and services on CPU 1, so that the echo and the service run
// under the same conditions in every run):
//   clients/lib/netns.sh build/tests/bench_contact_service
// (`bench_contact_service --bare-echo` is the echo process it starts itself.)

#include <benchmark/benchmark.h>
#include <lcm/lcm-cpp.hpp>
#include <sched.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <numeric>
#include <random>
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
#include "core/models/contact_model_factory.hpp"
#include "core/profile/profile_factory.hpp"
#include "core/spline/spline_geometry_fit.hpp"
#include "wrc/contact_query_t.hpp"
#include "wrc/contact_reply_t.hpp"
#include "wrc/ping_reply_t.hpp"
#include "wrc/ping_request_t.hpp"

namespace {

constexpr const char* kBarePing = "BENCH_BARE_PING";
constexpr const char* kBarePong = "BENCH_BARE_PONG";
constexpr const char* kBareQuery = "BENCH_BARE_CONTACT_QUERY";
constexpr const char* kBareReply = "BENCH_BARE_CONTACT_REPLY";
constexpr const char* kComputeQuery = "BENCH_BARE_COMPUTE_QUERY";
constexpr const char* kComputeReply = "BENCH_BARE_COMPUTE_REPLY";

wrc::contact_query_t bench_query() {
  wrc::contact_query_t q{};
  q.model = "onepoint";
  q.instance = "bench";
  q.formulation = wrc::contact_query_t::RIGID;
  q.shear_modulus = 8.2e10;
  q.poisson_ratio = 0.28;
  q.friction = 0.3;
  q.fastsim_elements = 20;
  q.fastsim_strips = 20;
  wrc::wheelset_configuration_t c{};
  c.y = 0.002;
  c.z = 0.46;
  c.yaw = 0.0005;
  c.y_dot = 0.01;
  c.spin_rate = 30.0 / 0.46;
  c.speed = 30.0;
  c.normal_load_left = 154715.0 / 2.0;
  c.normal_load_right = 154715.0 / 2.0;
  q.num_configurations = 1;
  q.configurations = {c};
  return q;
}

wrc::ContactQuery library_query(const wrc::contact_query_t& q) {
  const auto& c = q.configurations[0];
  wrc::ContactQuery out;
  out.pose.y = c.y;
  out.pose.z = c.z;
  out.pose.yaw = c.yaw;
  out.y_dot = c.y_dot;
  out.spin_rate = c.spin_rate;
  out.speed = c.speed;
  out.normal_load = {c.normal_load_left, c.normal_load_right};
  out.fastsim_elements = q.fastsim_elements;
  out.fastsim_strips = q.fastsim_strips;
  return out;
}

// ---- the bare echo process: plain LCM, typed handlers, no checks, no computation ----------------
// The model as wrc-contactd builds it by default (S1002 on UIC60, default options).
// The spline model's data: the default fit, which wrc-geometryd computes for the service the same
// way (deterministic: each sample line is computed on its own).
std::unique_ptr<const wrc::ContactModel> make_model(const std::string& name) {
  auto geometry = std::make_shared<const wrc::WheelsetGeometry>(
      wrc::make_profile("S1002", wrc::ProfileSide::kWheel), wrc::make_profile("UIC60", wrc::ProfileSide::kRail));
  wrc::ContactModelData data;
  if (wrc::contact_model_entry(name).needs_data)
    data.splines = wrc::fit_spline_geometry(*geometry, wrc::SplineFitOptions{}).model;
  return wrc::make_contact_model(name, geometry, wrc::ContactModelOptions{}, data);
}

struct BareEcho {
  lcm::LCM& lcm;
  wrc::contact_reply_t canned{};
  std::unique_ptr<const wrc::ContactModel> model;
  void on_compute(const lcm::ReceiveBuffer*, const std::string&, const wrc::contact_query_t* req) {
    const double t0 = wrc::bus::monotonic_seconds();
    benchmark::DoNotOptimize(model->evaluate(library_query(*req)));
    canned.compute_time = wrc::bus::monotonic_seconds() - t0;
    canned.request_id = req->request_id;
    lcm.publish(kComputeReply, &canned);
  }
  void on_ping(const lcm::ReceiveBuffer*, const std::string&, const wrc::ping_request_t* req) {
    wrc::ping_reply_t reply{};
    reply.request_id = req->request_id;
    lcm.publish(kBarePong, &reply);
  }
  void on_query(const lcm::ReceiveBuffer*, const std::string&, const wrc::contact_query_t* req) {
    canned.request_id = req->request_id;
    lcm.publish(kBareReply, &canned);
  }
};

int run_bare_echo() {
  wrc::bus::ShutdownSignal::install();
  lcm::LCM lcm("");
  if (!lcm.good()) return 1;
  BareEcho echo{lcm, {}, nullptr};
  echo.canned.model = "onepoint";
  echo.canned.instance = "bench";
  echo.canned.num_configurations = 1;
  echo.canned.results.resize(1);
  echo.canned.results[0].num_patches = 2;  // the size of a real one-point reply: one patch per wheel
  echo.canned.results[0].patches.resize(2);
  lcm.subscribe(kBarePing, &BareEcho::on_ping, &echo);
  lcm.subscribe(kBareQuery, &BareEcho::on_query, &echo);
  echo.model = make_model("onepoint");
  lcm.subscribe(kComputeQuery, &BareEcho::on_compute, &echo);
  while (!wrc::bus::ShutdownSignal::requested()) lcm.handleTimeout(100);
  return 0;
}

using wrc::bench::BareClient;

// With WRC_BENCH_PIN=1 this process runs on CPU 0 and every child on CPU 1: no run depends on
// where the scheduler happened to put the processes (needs two CPUs).
bool pinned() {
  const char* pin = std::getenv("WRC_BENCH_PIN");
  return pin != nullptr && std::string(pin) == "1";
}

void pin_to(pid_t pid, int cpu) {
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(cpu, &set);
  if (sched_setaffinity(pid, sizeof set, &set) != 0) throw std::runtime_error("cannot pin a process to CPU " + std::to_string(cpu));
}

pid_t spawn(const std::vector<std::string>& words) {
  const pid_t pid = wrc::bus::spawn_tied_child(words, SIGKILL);
  if (pinned()) pin_to(pid, 1);
  return pid;
}

// One contact service process with its client, the same model in this process and its query.
struct ModelService {
  using Client = wrc::bus::RequestClient<wrc::contact_query_t, wrc::contact_reply_t>;
  std::string name;
  std::unique_ptr<Client> client;
  std::unique_ptr<const wrc::ContactModel> model;
  wrc::contact_query_t query;
};

constexpr const char* kModels[] = {"onepoint", "interp", "multipoint", "spline"};

struct Bench {
  std::unique_ptr<lcm::LCM> lcm;
  std::unique_ptr<BareClient<wrc::ping_request_t, wrc::ping_reply_t>> bare_ping;
  std::unique_ptr<BareClient<wrc::contact_query_t, wrc::contact_reply_t>> bare_contact;
  std::unique_ptr<BareClient<wrc::contact_query_t, wrc::contact_reply_t>> bare_compute;
  std::vector<ModelService> services;  // in the order of kModels; services[0] is onepoint
  std::vector<pid_t> children;
  std::string cache_dir;  // wrc-geometryd's, removed at the end

  Bench() {
    if (pinned()) pin_to(0, 0);
    wrc::bench::use_temporary_bus_key();
    lcm = std::make_unique<lcm::LCM>("");
    if (!lcm->good()) throw std::runtime_error("LCM not usable (run through clients/lib/netns.sh)");
    const auto contactd = wrc::bus::find_service_executable("wrc-contactd", wrc::bus::build_dir());
    if (!contactd) throw std::runtime_error("wrc-contactd is not built");
    children.push_back(spawn({"/proc/self/exe", "--bare-echo"}));
    const wrc::bus::ChannelNames names;
    const char* limit = std::getenv("WRC_BENCH_SERVICES");
    const std::size_t count = limit ? std::strtoul(limit, nullptr, 10) : std::size(kModels);
    for (const char* model : kModels) {
      if (services.size() == count) break;
      if (wrc::contact_model_entry(model).needs_data) {
        // Its model comes from wrc-geometryd, with a cache of this run's own.
        const auto geometryd = wrc::bus::find_service_executable("wrc-geometryd", wrc::bus::build_dir());
        if (!geometryd) throw std::runtime_error("wrc-geometryd is not built");
        char cache[] = "/tmp/wrc-bench-models-XXXXXX";
        if (::mkdtemp(cache) == nullptr) throw std::runtime_error("cannot create a cache directory");
        cache_dir = cache;
        children.push_back(spawn({*geometryd, "--instance", "bench", "--cache-dir", cache}));
      }
      children.push_back(spawn({*contactd, "--model", model, "--instance", "bench"}));
      ModelService m;
      m.name = model;
      m.model = make_model(model);
      m.query = bench_query();
      m.query.model = model;
      const std::string id = wrc::bus::make_client_id(std::string("bench-") + model);
      m.client = std::make_unique<ModelService::Client>(*lcm, names.name(wrc::bus::channel::kContactQuery, model),
                                                        names.name(wrc::bus::channel::kContactReply, id), id);
      services.push_back(std::move(m));
    }
    wrc::ping_request_t ping{};
    ping.reply_channel = kBarePong;
    bare_ping = std::make_unique<BareClient<wrc::ping_request_t, wrc::ping_reply_t>>(*lcm, kBarePing, kBarePong, ping);
    wrc::contact_query_t bare_query = bench_query();
    bare_query.reply_channel = kBareReply;
    bare_contact = std::make_unique<BareClient<wrc::contact_query_t, wrc::contact_reply_t>>(*lcm, kBareQuery,
                                                                                             kBareReply, bare_query);
    bare_compute = std::make_unique<BareClient<wrc::contact_query_t, wrc::contact_reply_t>>(*lcm, kComputeQuery,
                                                                                             kComputeReply, bare_query);
    const double deadline = wrc::bus::monotonic_seconds() + 60.0;
    bool bare_ok = false;
    std::vector<bool> service_ok(services.size(), false);
    auto all_ok = [&] { return bare_ok && std::all_of(service_ok.begin(), service_ok.end(), [](bool b) { return b; }); };
    while (!all_ok() && wrc::bus::monotonic_seconds() < deadline) {
      if (!bare_ok) bare_ok = bare_ping->round_trip() && bare_contact->round_trip() && bare_compute->round_trip();
      for (std::size_t i = 0; i < services.size(); ++i) {
        if (service_ok[i]) continue;
        auto r = services[i].client->call(services[i].query, {0.2, 0});
        if (r && r.reply->status != wrc::contact_reply_t::OK)
          throw std::runtime_error(services[i].name + " service: " + r.reply->message);
        service_ok[i] = static_cast<bool>(r);
      }
    }
    if (!all_ok()) throw std::runtime_error("the echo or a contact service does not answer");
  }
  ~Bench() {
    wrc::bus::stop_children(children, 5.0);
    if (!cache_dir.empty()) std::filesystem::remove_all(cache_dir);
  }
};

Bench& bench() {
  static Bench instance;
  return instance;
}

using wrc::bus::percentile;

// The service of model kModels[index], or nothing (the benchmark skipped) when WRC_BENCH_SERVICES
// left it out.
ModelService* started_service(benchmark::State& state, std::int64_t index) {
  auto& services = bench().services;
  if (index < 0 || static_cast<std::size_t>(index) >= services.size()) {
    state.SkipWithError("this service was not started (WRC_BENCH_SERVICES)");
    return nullptr;
  }
  return &services[static_cast<std::size_t>(index)];
}

// One call to a service; its evaluation time as the service reports it [s] goes to `evaluation`.
bool service_round_trip(ModelService& service, double& evaluation) {
  auto r = service.client->call(service.query, {1.0, 0});
  if (!r) return false;
  evaluation = r.reply->compute_time;
  return r.reply->status == wrc::contact_reply_t::OK && r.reply->results[0].num_patches >= 2;
}

void time_into(std::vector<double>& into, const std::function<bool()>& f, benchmark::State& state, const char* what) {
  const double t0 = wrc::bus::monotonic_seconds();
  const bool ok = f();
  into.push_back((wrc::bus::monotonic_seconds() - t0) * 1e6);
  if (!ok) state.SkipWithError(what);
}

void InProcess(benchmark::State& state) {
  const ModelService* service = started_service(state, state.range(0));
  if (service == nullptr) return;
  const ModelService& m = *service;
  const wrc::ContactQuery q = library_query(m.query);
  for (auto _ : state) benchmark::DoNotOptimize(m.model->evaluate(q));
  state.SetLabel(m.name);
}

// Runs every measurement once per iteration, in a new random order each time.
void run_shuffled(benchmark::State& state, const std::vector<std::function<void()>>& measurements,
                  const std::function<void()>& after_iteration = {}) {
  std::vector<std::size_t> order(measurements.size());
  std::iota(order.begin(), order.end(), 0);
  std::mt19937 random(20261122);
  for (auto _ : state) {
    std::shuffle(order.begin(), order.end(), random);
    for (std::size_t i : order) measurements[i]();
    if (after_iteration) after_iteration();
  }
}

// The one-point service against every floor (the goal above).
void Interleaved(benchmark::State& state) {
  ModelService* started = started_service(state, 0);
  if (started == nullptr) return;
  ModelService& onepoint = *started;
  std::vector<double> ping_us, contact_us, compute_us, service_us, local_us;
  std::vector<double> echo_eval_us, service_eval_us;  // evaluation time inside the other processes
  const wrc::ContactQuery q = library_query(onepoint.query);
  double service_evaluation = 0.0;
  run_shuffled(
      state,
      {[&] { time_into(ping_us, [] { return bench().bare_ping->round_trip(); }, state, "bare ping timed out"); },
       [&] { time_into(contact_us, [] { return bench().bare_contact->round_trip(); }, state, "bare contact timed out"); },
       [&] { time_into(compute_us, [] { return bench().bare_compute->round_trip(); }, state, "bare compute timed out"); },
       [&] {
         time_into(service_us, [&] { return service_round_trip(onepoint, service_evaluation); }, state,
                   "service round trip failed");
       },
       [&] {
         time_into(local_us, [&] {
           benchmark::DoNotOptimize(onepoint.model->evaluate(q));
           return true;
         }, state, "");
       }},
      [&] {
        echo_eval_us.push_back(bench().bare_compute->compute_time() * 1e6);
        service_eval_us.push_back(service_evaluation * 1e6);
      });
  const double ping = percentile(ping_us, 0.5), contact = percentile(contact_us, 0.5);
  const double service = percentile(service_us, 0.5), local = percentile(local_us, 0.5);
  state.counters["bare_ping_median_us"] = ping;
  state.counters["bare_contact_median_us"] = contact;
  state.counters["bare_compute_median_us"] = percentile(compute_us, 0.5);
  state.counters["service_median_us"] = service;
  state.counters["in_process_median_us"] = local;
  state.counters["echo_eval_median_us"] = percentile(echo_eval_us, 0.5);
  state.counters["service_eval_median_us"] = percentile(service_eval_us, 0.5);
  state.counters["service_p99_us"] = percentile(service_us, 0.99);
  state.counters["bare_contact_p99_us"] = percentile(contact_us, 0.99);
  const double budget_ping = 1.1 * ping + local, budget_contact = 1.1 * contact + local;
  state.counters["budget_ping_us"] = budget_ping;
  state.counters["budget_contact_us"] = budget_contact;
  state.counters["goal_ping"] = service <= budget_ping ? 1 : 0;
  state.counters["goal_contact"] = service <= budget_contact ? 1 : 0;
}

// Each service (argument: index into kModels) against the bare contact echo, with its in-process
// evaluation.
void PerModel(benchmark::State& state) {
  ModelService* started = started_service(state, state.range(0));
  if (started == nullptr) return;
  ModelService& m = *started;
  std::vector<double> contact_us, service_us, local_us;
  const wrc::ContactQuery q = library_query(m.query);
  double evaluation = 0.0;
  run_shuffled(
      state,
      {[&] { time_into(contact_us, [] { return bench().bare_contact->round_trip(); }, state, "bare contact timed out"); },
       [&] {
         time_into(service_us, [&] { return service_round_trip(m, evaluation); }, state, "service round trip failed");
       },
       [&] {
         time_into(local_us, [&] {
           benchmark::DoNotOptimize(m.model->evaluate(q));
           return true;
         }, state, "");
       }});
  const double contact = percentile(contact_us, 0.5), service = percentile(service_us, 0.5);
  const double local = percentile(local_us, 0.5);
  state.counters["bare_contact_median_us"] = contact;
  state.counters["service_median_us"] = service;
  state.counters["in_process_median_us"] = local;
  state.counters["budget_contact_us"] = 1.1 * contact + local;
  state.counters["goal_contact"] = service <= 1.1 * contact + local ? 1 : 0;
  state.counters["service_over_bare"] = service / contact;  // the spline model's goal: <= 1.2
  state.SetLabel(m.name);
}

BENCHMARK(InProcess)->DenseRange(0, 3)->Unit(benchmark::kMicrosecond);
BENCHMARK(Interleaved)->Iterations(5000)->Unit(benchmark::kMicrosecond);
BENCHMARK(PerModel)->DenseRange(0, 3)->Iterations(3000)->Unit(benchmark::kMicrosecond);

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "--bare-echo") return run_bare_echo();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  try {
    bench();
  } catch (const std::exception& e) {
    std::cerr << "bench_contact_service: " << e.what() << "\n";
    return 1;
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
