// SPDX-License-Identifier: Apache-2.0
// wrc-dynamicsd as a real process with real contact services, driven by `wrc run` and `wrc swap`
// (every test in a private network namespace): every model runs and writes its summary; a live
// swap made from another process is listed and reproduced bit for bit by --swap-at; a swap to a
// missing service is refused with the reason; 5 % packet
// loss, a contact service killed with SIGKILL (restarted by the launcher) and wrc-dynamicsd
// killed mid-run (the run sent again to the one that takes over) end in the same final state as
// an undisturbed run, bit for bit.
#include <signal.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bus/transport/clock.hpp"
#include "bus/transport/guarded_subscription.hpp"
#include "bus_fixture.hpp"
#include "wrc/contact_select_t.hpp"
#include "wrc/progress_t.hpp"
#include "wrc/run_status_t.hpp"
#include "wrc/wheelset_state_t.hpp"
#include "wrc/wheelset_states_t.hpp"

namespace wrc::bus::test {
namespace {

constexpr double kRunDeadline = 300.0;  // [s] a run with service start-up and (spline) a fit
// [s] simulated time of a multipoint run that a test disturbs (kills a service) once the statuses,
// sent twice a second, say it is 1 s in: about 3 s of wall time over the bus here (10 s of it took
// 0.5 s once the chain's next step travelled with each query, and ended before the first status).
constexpr double kDisturbedRun = 60.0;

class DynamicsServiceTest : public BusTest {
 protected:
  void SetUp() override {
    BusTest::SetUp();
    cache_ = temp_path("models");
    ::setenv("WRC_CACHE_DIR", cache_.c_str(), 1);  // the processes' spline model cache
    status_ = std::make_unique<GuardedSubscription<run_status_t>>(
        *lcm_, names_.name(channel::kRunStatus), "test run status",
        [this](const run_status_t& s, const ReceivedMessage&) { last_status_ = s; });
  }
  void TearDown() override {
    ::unsetenv("WRC_CACHE_DIR");
    BusTest::TearDown();
  }

  // `wrc run` arguments; the run is named after its summary file.
  std::vector<std::string> run_args(const std::string& model, double t_end, const std::string& summary) const {
    return {"run", "--model", model, "--t-end", std::to_string(t_end), "--summary", summary, "--build-dir",
            WRC_TEST_BUILD_DIR, "--run-id", run_id(summary)};
  }
  static std::string run_id(const std::string& summary) {
    return summary.substr(summary.find_last_of('/') + 1);
  }
  // Dispatches until the run called id reports RUNNING past simulated time t [s].
  bool wait_running_past(const std::string& id, double t, double timeout) {
    return handle_until(
        [&] { return last_status_.run_id == id && last_status_.state == run_status_t::RUNNING && last_status_.t > t; },
        timeout);
  }
  // Runs `wrc run` to its end; returns the summary.
  nlohmann::json run(std::vector<std::string> args, const std::string& name) {
    const std::string log = temp_path(name + ".log");
    ChildProcess cli(WRC_CLI_PATH, args, log);
    int status = -1;
    EXPECT_TRUE(cli.wait(kRunDeadline, &status)) << read_text(log);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << read_text(log);
    return summary(args);
  }
  static nlohmann::json summary(const std::vector<std::string>& args) {
    for (size_t k = 0; k + 1 < args.size(); ++k)
      if (args[k] == "--summary") {
        std::ifstream in(args[k + 1]);
        if (!in) return {};
        return nlohmann::json::parse(in);
      }
    return {};
  }
  static void expect_same_final_state(const nlohmann::json& a, const nlohmann::json& b) {
    ASSERT_TRUE(a.contains("final_state") && b.contains("final_state"));
    for (const char* key : {"y", "z", "roll", "yaw", "y_dot", "z_dot", "roll_dot", "yaw_dot", "spin_rate",
                            "normal_force_left", "normal_force_right"})
      EXPECT_EQ(a["final_state"][key].get<double>(), b["final_state"][key].get<double>()) << key;
    EXPECT_EQ(a["counters"]["steps"], b["counters"]["steps"]);
  }
  // Waits until some instance of model is READY.
  bool wait_available(const std::string& model, double timeout) {
    return handle_until(
        [&] {
          for (const ServiceStatus& s : monitor_->services(monotonic_seconds()))
            if (s.last.model == model && s.available()) return true;
          return false;
        },
        timeout);
  }
  std::string cache_;
  std::unique_ptr<GuardedSubscription<run_status_t>> status_;
  run_status_t last_status_{};
};

// `wrc run` completes for every model, starting the services it needs, and the summary has the
// final state in wrc geometry's conventions and the counters; the spline run has no restarts.
TEST_F(DynamicsServiceTest, EveryModelRunsAndWritesItsSummary) {
  for (const std::string model : {"onepoint", "interp", "multipoint", "spline"}) {
    const nlohmann::json s = run(run_args(model, 0.2, temp_path(model + ".json")), model);
    ASSERT_TRUE(s.contains("state")) << model;
    EXPECT_EQ(s["state"], "finished") << model << ": " << s["message"];
    EXPECT_EQ(s["model"], model);
    EXPECT_EQ(s["formulation"], model == "multipoint" ? "elastic" : "rigid");
    EXPECT_DOUBLE_EQ(s["t_end"].get<double>(), 0.2);
    EXPECT_NEAR(s["final_state"]["z"].get<double>(), 0.46, 1e-3) << model;  // centre above the top of rail
    EXPECT_LT(s["final_state"]["y"].get<double>(), -1e-3) << model;      // pushed towards the right rail
    EXPECT_GT(s["counters"]["steps"].get<long>(), 10);
    EXPECT_GT(s["counters"]["contact_queries"].get<long>(), s["counters"]["steps"].get<long>());
    if (model == "spline") {
      EXPECT_EQ(s["counters"]["restarts"].get<long>(), 0);
    }
  }
}

// `wrc run --track FILE`: the spline model through the shipped layout (100 m straight, 90 m
// transition, a left-hand curve of 600 m with 0.13 m cant) to 240 m at 30 m/s, over the bus: the
// layout crosses run_command_t, the run finishes in the curve pushed outwards (towards -y, the
// cant deficiency of 0.099 m is carried by the outer wheel's flange root), and the summary lists
// the curve with its balanced speed sqrt(g R tan(phi)) and cant deficiency b V^2 / (g R) - h.
// Without --lateral-force the benchmark's -20 kN lateral load is set to 0 (on a curve it would add
// to the centrifugal force): the first line of output says so and the summary's parameters have
// lateral_force 0; an explicit --lateral-force on the command line keeps its value.
TEST_F(DynamicsServiceTest, ARunFollowsATrackLayout) {
  const std::string layout_file = std::string(WRC_SOURCE_DIR) + "/parameters/track-curve-R600.json";
  std::vector<std::string> args = run_args("spline", 8.0, temp_path("curve.json"));
  args.insert(args.end(), {"--track", layout_file});
  const nlohmann::json s = run(args, "curve");
  ASSERT_EQ(s["state"], "finished") << s.dump();
  const std::string output = read_text(temp_path("curve.log"));
  EXPECT_EQ(output.substr(0, output.find('\n')),
            "lateral load: -20000 N of the parameters set to 0 (a track layout's curves load the wheelset with their "
            "centrifugal force; --lateral-force F keeps a load)");
  EXPECT_EQ(s["parameters"]["lateral_force"].get<double>(), 0.0);
  EXPECT_LT(s["final_state"]["y"].get<double>(), -3e-3);
  EXPECT_EQ(s["counters"]["restarts"].get<long>(), 0);
  const nlohmann::json& layout = s["track_layout"];
  EXPECT_DOUBLE_EQ(layout["length"].get<double>(), 780.0);
  EXPECT_DOUBLE_EQ(layout["distance_travelled"].get<double>(), 240.0);
  ASSERT_EQ(layout["curves"].size(), 1u);
  const nlohmann::json& curve = layout["curves"][0];
  EXPECT_DOUBLE_EQ(curve["s_start"].get<double>(), 190.0);
  EXPECT_EQ(curve["direction"], "left");
  EXPECT_NEAR(curve["balanced_speed"].get<double>(), std::sqrt(9.81 * 600 * 0.13 / std::sqrt(1.5 * 1.5 - 0.13 * 0.13)),
              1e-9);
  EXPECT_NEAR(curve["cant_deficiency"].get<double>(), 1.5 * 30.0 * 30.0 / (9.81 * 600) - 0.13, 1e-12);

  std::vector<std::string> given = run_args("spline", 0.1, temp_path("curve-given.json"));
  given.insert(given.end(), {"--track", layout_file, "--lateral-force", "-1000"});
  const nlohmann::json g = run(given, "curve-given");
  ASSERT_EQ(g["state"], "finished") << g.dump();
  EXPECT_EQ(g["parameters"]["lateral_force"].get<double>(), -1000.0);
  EXPECT_EQ(read_text(temp_path("curve-given.log")).find("lateral load:"), std::string::npos);
}

// `wrc irregularities` then `wrc run --track FILE --irregularities FILE` with every model: ERRI
// low-level irregularities (3-70 m, seed 1, 300 m) over the shipped layout at 30 m/s for 7 s, through
// the straight and the transition into the curve (210 m). The samples cross run_command_t (the
// summary's range and sample count are the file's), every run finishes, in the curve pushed
// outwards (y < -2 mm: the cant deficiency of 99 mm on the outer flange root, as without
// irregularities), with Y/Q below Nadal's limit; the spline and the multi-point model without a
// restart. (The multi-point model joined once the minima of one overlap shared its depth,
// docs/contact-mechanics.md: before, its left wheel's fold made it take about 4e5 steps per
// simulated second here.)
TEST_F(DynamicsServiceTest, EveryModelRunsACurveOverIrregularTrack) {
  const std::string csv = temp_path("erri.csv");
  {
    const std::string log = temp_path("irregularities.log");
    ChildProcess cli(WRC_CLI_PATH,
                     {"irregularities", "--spectrum", "erri-low", "--length", "300", "--wavelengths", "3:70",
                      "--seed", "1", "--out", csv},
                     log);
    int status = -1;
    ASSERT_TRUE(cli.wait(60.0, &status)) << read_text(log);
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << read_text(log);
  }
  for (const char* model : {"spline", "interp", "onepoint", "multipoint"}) {
    std::vector<std::string> args = run_args(model, 7.0, temp_path(std::string("irregular-") + model + ".json"));
    args.insert(args.end(), {"--track", std::string(WRC_SOURCE_DIR) + "/parameters/track-curve-R600.json",
                             "--irregularities", csv, "--lateral-force", "0", "--output-period", "0.01"});
    const nlohmann::json s = run(args, std::string("irregular-") + model);
    ASSERT_EQ(s["state"], "finished") << model << ": " << s.dump();
    const nlohmann::json& irregularities = s["irregularities"];
    EXPECT_DOUBLE_EQ(irregularities["s_end"].get<double>(), 300.0) << model;
    EXPECT_EQ(irregularities["samples"].get<long>(), 1201) << model;
    EXPECT_GT(irregularities["alignment"]["rms"].get<double>(), 5e-4) << model;
    EXPECT_LT(s["final_state"]["y"].get<double>(), -2e-3) << model;
    const nlohmann::json& q = s["run_quantities"];
    for (const char* side : {"left", "right"})
      EXPECT_LT(q["y_over_q"][side]["max"].get<double>(), q["nadal_limit"].get<double>()) << model << " " << side;
    std::cout << "[ measured ] " << model << " over ERRI low into R 600 m: y = "
              << s["final_state"]["y"].get<double>() * 1e3 << " mm, max Y/Q "
              << std::max(q["y_over_q"]["left"]["max"].get<double>(), q["y_over_q"]["right"]["max"].get<double>())
              << ", restarts " << s["counters"]["restarts"] << ", wall " << s["wall_time"] << " s\n";
    if (std::string(model) == "spline" || std::string(model) == "multipoint") {
      EXPECT_EQ(s["counters"]["restarts"].get<long>(), 0) << model;
    }
  }
}

// What engineers read off a run (docs/run-quantities.md), over the bus with a flange angle and a
// friction of the test's own (so the parameter crosses run_command_t): the summary JSON has, under
// run_quantities, the maxima of |Y/Q| per wheel, |sum Y|, T gamma and p_max each with t and the
// distance, the limits computed from the run's values (Nadal: (tan d - mu) / (1 + mu tan d);
// Prud'homme: 1e4 N + P/3) and a unit for every key; the history CSV has "name [unit]" in every
// header, the new columns with their units, and no row above the summary's maxima.
TEST_F(DynamicsServiceTest, RunQuantitiesInSummaryAndHistory) {
  std::vector<std::string> args = run_args("spline", 0.3, temp_path("quantities.json"));
  const std::string csv = temp_path("quantities.csv");
  args.insert(args.end(), {"--history", csv, "--flange-angle", "1.2", "--friction", "0.25"});
  const nlohmann::json s = run(args, "quantities");
  ASSERT_EQ(s["state"], "finished") << s.dump();
  ASSERT_TRUE(s.contains("run_quantities")) << s.dump();
  const nlohmann::json& q = s["run_quantities"];
  const std::map<std::string, std::string> units{
      {"t", "s"},           {"distance", "m"},          {"y_over_q", "-"},          {"nadal_limit", "-"},
      {"flange_angle", "rad"}, {"friction", "-"},        {"track_shift_force", "N"}, {"prudhomme_limit", "N"},
      {"axle_load", "N"},   {"wear_number", "N"},       {"max_pressure", "Pa"},     {"y_over_q_2m", "-"},
      {"track_shift_force_2m", "N"}};
  for (const auto& [key, unit] : units) EXPECT_EQ(q["units"][key], unit) << key;
  for (const auto& item : q.items())
    EXPECT_TRUE(item.key() == "units" || q["units"].contains(item.key())) << item.key() << " has no unit";
  EXPECT_DOUBLE_EQ(q["flange_angle"].get<double>(), 1.2);
  EXPECT_DOUBLE_EQ(s["parameters"]["flange_angle"].get<double>(), 1.2);
  EXPECT_DOUBLE_EQ(q["friction"].get<double>(), 0.25);
  EXPECT_NEAR(q["nadal_limit"].get<double>(), (std::tan(1.2) - 0.25) / (1.0 + 0.25 * std::tan(1.2)), 1e-14);
  const double axle_load = 154715.0 + 1813.0 * 9.81;
  EXPECT_NEAR(q["axle_load"].get<double>(), axle_load, 1e-9);
  EXPECT_NEAR(q["prudhomme_limit"].get<double>(), 1e4 + axle_load / 3.0, 1e-9);
  auto expect_where = [&](const nlohmann::json& m, const std::string& what) {
    ASSERT_TRUE(m.contains("max") && m.contains("t") && m.contains("distance")) << what << ": " << m.dump();
    EXPECT_GT(m["max"].get<double>(), 0.0) << what;
    EXPECT_GE(m["t"].get<double>(), 0.0) << what;
    EXPECT_LE(m["t"].get<double>(), 0.3) << what;
    EXPECT_DOUBLE_EQ(m["distance"].get<double>(), 30.0 * m["t"].get<double>()) << what;
  };
  for (const char* key : {"y_over_q", "wear_number", "max_pressure"})
    for (const char* side : {"left", "right"}) expect_where(q[key][side], std::string(key) + " " + side);
  expect_where(q["track_shift_force"], "track_shift_force");
  // EN 14363's 2 m sliding means: at a window's end (a multiple of 0.5 m, from 2 m on), below the
  // instantaneous maxima.
  const auto expect_sliding = [&](const nlohmann::json& m, const nlohmann::json& instantaneous, const std::string& what) {
    ASSERT_TRUE(m.contains("max") && m.contains("t") && m.contains("distance")) << what << ": " << m.dump();
    EXPECT_GT(m["max"].get<double>(), 0.0) << what;
    EXPECT_LE(m["max"].get<double>(), instantaneous["max"].get<double>()) << what;
    EXPECT_GE(m["distance"].get<double>(), 2.0) << what;
    EXPECT_DOUBLE_EQ(std::fmod(m["distance"].get<double>(), 0.5), 0.0) << what;
    EXPECT_NEAR(m["t"].get<double>(), m["distance"].get<double>() / 30.0, 1e-12) << what;
  };
  for (const char* side : {"left", "right"})
    expect_sliding(q["y_over_q_2m"][side], q["y_over_q"][side], std::string("y_over_q_2m ") + side);
  expect_sliding(q["track_shift_force_2m"], q["track_shift_force"], "track_shift_force_2m");
  // The history: every header "name [unit]", the new columns among them.
  std::ifstream in(csv);
  std::string line;
  ASSERT_TRUE(std::getline(in, line)) << csv;
  std::vector<std::string> header;
  for (std::stringstream cells(line); std::getline(cells, line, ',');) header.push_back(line);
  for (const std::string& h : header) EXPECT_EQ(h.back(), ']') << "no unit in '" << h << "'";
  const std::vector<std::string> wanted{
      "t [s]", "distance [m]", "lateral_force_left [N]", "lateral_force_right [N]", "vertical_force_left [N]",
      "vertical_force_right [N]", "y_over_q_left [-]", "y_over_q_right [-]", "nadal_limit [-]",
      "track_shift_force [N]", "prudhomme_limit [N]", "creep_force_x_left [N]", "creep_force_y_right [N]",
      "wear_number_left [N]", "wear_number_right [N]", "max_pressure_left [Pa]", "max_pressure_right [Pa]"};
  std::map<std::string, size_t> at;
  for (const std::string& w : wanted) {
    const auto it = std::find(header.begin(), header.end(), w);
    ASSERT_NE(it, header.end()) << "no column '" << w << "' in the history";
    at[w] = static_cast<size_t>(it - header.begin());
  }
  long rows = 0;
  for (std::string row; std::getline(in, row); ++rows) {
    std::vector<std::string> cells;
    for (std::stringstream c(row); std::getline(c, line, ',');) cells.push_back(line);
    ASSERT_EQ(cells.size(), header.size()) << row;
    auto value = [&](const std::string& column) { return std::stod(cells[at[column]]); };
    EXPECT_LE(std::abs(value("y_over_q_right [-]")), q["y_over_q"]["right"]["max"].get<double>());
    EXPECT_LE(std::abs(value("track_shift_force [N]")), q["track_shift_force"]["max"].get<double>());
    EXPECT_LE(value("wear_number_right [N]"), q["wear_number"]["right"]["max"].get<double>());
    EXPECT_LE(value("max_pressure_right [Pa]"), q["max_pressure"]["right"]["max"].get<double>());
    EXPECT_EQ(value("nadal_limit [-]"), q["nadal_limit"].get<double>());
    EXPECT_DOUBLE_EQ(value("distance [m]"), 30.0 * value("t [s]"));
  }
  EXPECT_EQ(rows, 301);  // 0.3 s at the default 1 ms, both ends
}

// A swap from onepoint to spline made with `wrc swap spline` while the run integrates is acted on
// at a step boundary and listed in the summary; --swap-at with that time reproduces the run.
TEST_F(DynamicsServiceTest, LiveSwapIsListedAndReproducedBySwapAt) {
  const std::string log = temp_path("launch.log");
  auto launcher = launch({"geometry", "contact-onepoint", "contact-spline", "dynamics"}, log);
  for (const char* model : {"onepoint", "spline", "dynamicsd"})
    ASSERT_TRUE(wait_available(model, kRunDeadline)) << model << "\n" << read_text(log);
  const std::vector<std::string> args = run_args("onepoint", 1.5, temp_path("live.json"));
  ChildProcess cli(WRC_CLI_PATH, args, temp_path("live.log"));
  // Swap early in the run (before the one-point model reaches the jump, its slow part).
  ASSERT_TRUE(wait_running_past(run_id(temp_path("live.json")), 0.1, 120.0)) << read_text(temp_path("live.log"));
  int status = -1;
  // A selection of another sender numbered far in the future (a garbled or hostile key holder)
  // hides no later swap: selection numbers count per sender (it used to hide every one).
  contact_select_t future{};
  future.seq = INT64_MAX;
  future.model = "multipoint";
  publish_signed(*lcm_, names_.name(channel::kContactSelect), future);
  const std::string out = run_command(std::string(WRC_CLI_PATH) + " swap spline 2>&1", &status);
  ASSERT_EQ(status, 0) << out;
  ASSERT_TRUE(handle_until([&] { return cli.wait(0.0); }, kRunDeadline)) << read_text(temp_path("live.log"));
  const nlohmann::json live = summary(args);
  ASSERT_EQ(live["state"], "finished") << live.dump();
  ASSERT_EQ(live["swaps"].size(), 1u) << live["message"] << "\n" << out << "\n" << read_text(log);
  EXPECT_EQ(live["swaps"][0]["model"], "spline");
  EXPECT_EQ(live["model"], "spline");
  const double t_swap = live["swaps"][0]["t"].get<double>();
  EXPECT_GT(t_swap, 0.1);
  char swap_at[64];
  std::snprintf(swap_at, sizeof swap_at, "%.17g:spline", t_swap);
  std::vector<std::string> replay_args = run_args("onepoint", 1.5, temp_path("replay.json"));
  replay_args.insert(replay_args.end(), {"--swap-at", swap_at});
  const nlohmann::json replay = run(replay_args, "replay");
  ASSERT_EQ(replay["swaps"].size(), 1u);
  EXPECT_EQ(replay["swaps"][0]["t"].get<double>(), t_swap);
  expect_same_final_state(live, replay);
  launcher->signal(SIGINT);
  launcher->wait(20.0);
}

// 5 % of all datagrams of the bus and its lanes dropped (queries, replies, commands, heartbeats): every lost query is
// re-sent, and the run ends bit for bit where the undisturbed one does.
TEST_F(DynamicsServiceTest, PacketLossGivesTheSameFinalState) {
  if (!in_netns()) GTEST_SKIP() << "packet loss is only injected inside a private network namespace";
  if (std::system("nft --version >/dev/null 2>&1") != 0) GTEST_SKIP() << "nft (nftables) is not installed";
  std::vector<std::string> args = run_args("spline", 0.5, temp_path("clean.json"));
  args.insert(args.end(), {"--timeout", "0.02", "--retries", "5"});
  const nlohmann::json clean = run(args, "clean");
  ASSERT_EQ(clean["state"], "finished") << clean.dump();
  if (std::system("nft add table inet t && nft add chain inet t in '{ type filter hook input priority 0; }'") != 0)
    GTEST_SKIP() << "nft cannot create a table in this namespace (no CAP_NET_ADMIN?)";
  ASSERT_EQ(std::system("nft add rule inet t in udp dport 7667-7675 numgen random mod 100 lt 5 counter drop"), 0);
  std::vector<std::string> lossy_args = run_args("spline", 0.5, temp_path("lossy.json"));
  lossy_args.insert(lossy_args.end(), {"--timeout", "0.02", "--retries", "5"});
  const nlohmann::json lossy = run(lossy_args, "lossy");
  std::system("nft delete table inet t");
  ASSERT_EQ(lossy["state"], "finished") << lossy.dump();
  EXPECT_GT(lossy["counters"]["contact_retries"].get<long>(), 0) << "the loss rule did not act";
  expect_same_final_state(clean, lossy);
}

// Under `wrc launch`, 5 % of every datagram lost (heartbeats, queries, replies, commands,
// statuses) for the whole test: the launcher kills no service (single lost heartbeats are not
// silence, busy loops are covered by the heartbeat keeper), and a one-point and a spline run end
// bit for bit where the same runs end on the clean bus. WRC_LOSS_SECONDS (default 0) keeps the
// loss and a stream of runs going for that long first (the 10-minute campaign of docs/validation.md's
// reliability section); the check on the kills covers all of it.
TEST_F(DynamicsServiceTest, LossyBusKillsNoServiceAndRunsEndTheSame) {
  if (!in_netns()) GTEST_SKIP() << "packet loss is only injected inside a private network namespace";
  if (std::system("nft --version >/dev/null 2>&1") != 0) GTEST_SKIP() << "nft (nftables) is not installed";
  const std::string log = temp_path("launch.log");
  auto launcher = launch({"geometry", "contact-onepoint", "contact-spline", "dynamics"}, log);
  for (const char* model : {"onepoint", "spline", "dynamicsd"})
    ASSERT_TRUE(wait_available(model, kRunDeadline)) << model << "\n" << read_text(log);
  const auto runs = [&](const std::string& tag) {
    std::map<std::string, nlohmann::json> out;
    for (const std::string model : {"onepoint", "spline"}) {
      std::vector<std::string> args = run_args(model, 0.3, temp_path(tag + "-" + model + ".json"));
      args.insert(args.end(), {"--timeout", "0.05", "--retries", "5"});
      out[model] = run(args, tag + "-" + model);
    }
    return out;
  };
  const auto clean = runs("clean");
  if (std::system("nft add table inet t && nft add chain inet t in '{ type filter hook input priority 0; }'") != 0)
    GTEST_SKIP() << "nft cannot create a table in this namespace (no CAP_NET_ADMIN?)";
  ASSERT_EQ(std::system("nft add rule inet t in udp dport 7667-7675 numgen random mod 100 lt 5 counter drop"), 0);
  const char* seconds_text = std::getenv("WRC_LOSS_SECONDS");
  const double campaign = seconds_text ? std::atof(seconds_text) : 0.0;
  const double campaign_end = monotonic_seconds() + campaign;
  int campaign_runs = 0;
  while (monotonic_seconds() < campaign_end) {
    runs("campaign-" + std::to_string(campaign_runs));
    ++campaign_runs;
  }
  const auto lossy = runs("lossy");
  std::system("nft delete table inet t");
  for (const std::string model : {"onepoint", "spline"}) {
    ASSERT_EQ(lossy.at(model)["state"], "finished") << model << ": " << lossy.at(model).dump();
    expect_same_final_state(clean.at(model), lossy.at(model));
  }
  const std::string text = read_text(log);
  EXPECT_EQ(text.find("killing it"), std::string::npos) << text;
  EXPECT_EQ(text.find("restart #"), std::string::npos) << text;
  std::cerr << "5 % loss: " << campaign << " s of runs (" << campaign_runs << " rounds) and the checked runs, "
            << "no service killed\n";
  launcher->signal(SIGINT);
  launcher->wait(20.0);
}

// A live swap during a vehicle run (the Manchester coach, spline, over the bus, the demo's track)
// changes every wheelset's model at the next step: the run goes on with the one-point service to
// its end, lists the swap and ends with the new model, with all four wheelsets in its summary.
TEST_F(DynamicsServiceTest, ALiveSwapOfAVehicleRunChangesEveryWheelsetsModel) {
  const std::string log = temp_path("launch.log");
  auto launcher = launch({"geometry", "contact-onepoint", "contact-spline", "dynamics"}, log);
  for (const char* model : {"onepoint", "spline", "dynamicsd"})
    ASSERT_TRUE(wait_available(model, kRunDeadline)) << model << "\n" << read_text(log);
  // On the demo's irregular track (4 s take seconds over the bus: time to swap).
  int made = -1;
  const std::string irregularities = temp_path("irregularities.csv");
  const std::string made_out = run_command(std::string(WRC_CLI_PATH) +
                                               " irregularities --spectrum erri-low --length 300 --wavelengths 3:70 "
                                               "--seed 1 --out " + irregularities + " 2>&1",
                                           &made);
  ASSERT_EQ(made, 0) << made_out;
  std::vector<std::string> args = run_args("spline", 4.0, temp_path("coach.json"));
  args.insert(args.end(), {"--vehicle", std::string(WRC_SOURCE_DIR) + "/parameters/vehicles/manchester-coach.json",
                           "--track", std::string(WRC_SOURCE_DIR) + "/parameters/track-curve-R600.json",
                           "--irregularities", irregularities});
  ChildProcess cli(WRC_CLI_PATH, args, temp_path("coach.log"));
  ASSERT_TRUE(wait_running_past(run_id(temp_path("coach.json")), 0.2, 120.0)) << read_text(temp_path("coach.log"));
  int status = -1;
  const std::string out = run_command(std::string(WRC_CLI_PATH) + " swap onepoint 2>&1", &status);
  ASSERT_EQ(status, 0) << out;
  ASSERT_TRUE(handle_until([&] { return cli.wait(0.0); }, kRunDeadline)) << read_text(temp_path("coach.log"));
  const nlohmann::json coach = summary(args);
  ASSERT_EQ(coach["state"], "finished") << coach.dump();
  EXPECT_EQ(coach["model"], "onepoint");
  ASSERT_EQ(coach["swaps"].size(), 1u) << coach["swaps"];
  EXPECT_EQ(coach["swaps"][0]["model"], "onepoint") << coach["swaps"];
  EXPECT_GT(coach["swaps"][0]["t"].get<double>(), 0.2) << coach["swaps"];
  EXPECT_EQ(coach["vehicle"]["wheelsets"].size(), 4u);
}

// A swap to a model whose service is not on the bus is refused: the run keeps its model and its
// summary says why (also after another sender's selection numbered INT64_MAX).
TEST_F(DynamicsServiceTest, SwapToAMissingServiceIsRefusedWithTheReason) {
  const std::string log = temp_path("launch.log");
  auto launcher = launch({"contact-multipoint", "dynamics"}, log);
  for (const char* model : {"multipoint", "dynamicsd"})
    ASSERT_TRUE(wait_available(model, kRunDeadline)) << model << "\n" << read_text(log);
  // Long enough for `wrc status` (1.2 s) and `wrc swap` to act while it runs: 100 s simulated took
  // 8 s of wall time once and 2.9 s on a faster day, when the run ended before the swap came (the
  // test failed with no refusal); 400 s take some 12 s here (every 10 ms an output sample: at the
  // default 1 ms they would be more than a run may write).
  std::vector<std::string> args = run_args("multipoint", 400.0, temp_path("refused.json"));
  args.insert(args.end(), {"--output-period", "0.01"});
  // The run's progress_t: fraction of the simulated interval, with the time remaining once it moves.
  std::vector<progress_t> progress;
  GuardedSubscription<progress_t> progress_sub(*lcm_, names_.name(channel::kProgress), "test progress",
                                               [&](const progress_t& p, const ReceivedMessage&) { progress.push_back(p); });
  ChildProcess cli(WRC_CLI_PATH, args, temp_path("refused.log"));
  ASSERT_TRUE(wait_running_past(run_id(temp_path("refused.json")), 0.5, 60.0)) << read_text(temp_path("refused.log"));
  int status = -1;
  // `wrc status` says what each service is doing: the run with its simulated time, the query rate.
  const std::string listing = run_command(std::string(WRC_CLI_PATH) + " status --duration 1.2 2>&1", &status);
  ASSERT_EQ(status, 0) << listing;
  EXPECT_NE(listing.find("doing: run " + run_id(temp_path("refused.json")) + ": multipoint, t = "), std::string::npos)
      << listing;
  EXPECT_NE(listing.find("doing: serving multipoint queries, "), std::string::npos) << listing;
  // A selection of another sender numbered far in the future (a garbled or hostile key holder)
  // hides no later swap: selection numbers count per sender (it used to hide every one).
  contact_select_t future{};
  future.seq = INT64_MAX;
  future.model = "multipoint";
  publish_signed(*lcm_, names_.name(channel::kContactSelect), future);
  const std::string out = run_command(std::string(WRC_CLI_PATH) + " swap spline 2>&1", &status);
  ASSERT_EQ(status, 0) << out;
  ASSERT_TRUE(handle_until([&] { return cli.wait(0.0); }, kRunDeadline)) << read_text(temp_path("refused.log"));
  const nlohmann::json s = summary(args);
  EXPECT_EQ(s["state"], "finished") << s.dump();
  EXPECT_EQ(s["model"], "multipoint");
  EXPECT_TRUE(s["swaps"].empty());
  handle_until([] { return false; }, 0.6);  // the last progress report, published as the run ends
  const std::string task = "run " + run_id(temp_path("refused.json")) + " multipoint";
  long moving = 0;
  bool done = false;
  for (const progress_t& p : progress) {
    if (p.task != task) continue;
    EXPECT_EQ(p.total, 1000);
    EXPECT_GE(p.done, 0);
    EXPECT_LE(p.done, p.total);
    if (p.done > 0 && p.done < p.total) {
      ++moving;
      EXPECT_GT(p.remaining, 0.0) << p.message;
    }
    done = done || (p.done == p.total && p.remaining == 0.0);
  }
  EXPECT_GE(moving, 2) << "progress reports while the run moved";
  EXPECT_TRUE(done) << "a final progress report at 100 %";
  EXPECT_NE(s["message"].get<std::string>().find("swap to spline refused, keeping multipoint: no spline service"),
            std::string::npos)
      << s["message"];
  launcher->signal(SIGINT);
  launcher->wait(20.0);
}

// `wrc record` logs a run; `wrc plot run LOG` draws the same states as the run's --history file
// (every state of the log equals the CSV row of the same time, and the two pictures are the same),
// and `wrc replay LOG` plays them back onto the bus.
TEST_F(DynamicsServiceTest, RecordedRunGivesTheHistoryAndReplays) {
  const std::string log_file = temp_path("run.lcmlog");
  ChildProcess recorder(WRC_CLI_PATH, {"record", log_file}, temp_path("record.log"));
  // lcm-logger creates its file once it listens (a loaded machine may take a while to start it).
  ASSERT_TRUE(handle_until([&] { return std::ifstream(log_file).good(); }, 30.0)) << read_text(temp_path("record.log"));
  handle_until([] { return false; }, 0.3);
  std::vector<std::string> args = run_args("spline", 0.3, temp_path("recorded.json"));
  const std::string csv = temp_path("recorded.csv");
  args.insert(args.end(), {"--history", csv, "--output-period", "0.005"});
  const nlohmann::json s = run(args, "recorded");
  ASSERT_EQ(s["state"], "finished") << s.dump();
  handle_until([] { return false; }, 0.3);
  recorder.signal(SIGINT);
  int recorder_status = -1;
  ASSERT_TRUE(recorder.wait(10.0, &recorder_status)) << read_text(temp_path("record.log"));
  EXPECT_TRUE(WIFEXITED(recorder_status) && WEXITSTATUS(recorder_status) == 0) << read_text(temp_path("record.log"));
  EXPECT_NE(read_text(temp_path("record.log")).find("recorded "), std::string::npos) << read_text(temp_path("record.log"));
  // The CSV rows by time.
  std::map<double, double> csv_y;
  {
    std::ifstream in(csv);
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line)) {
      const double t = std::stod(line.substr(0, line.find(',')));
      const std::string rest = line.substr(line.find(',') + 1);
      csv_y[t] = std::stod(rest.substr(0, rest.find(',')));
    }
  }
  ASSERT_EQ(csv_y.size(), 61u);  // 0.3 s at 5 ms, both ends
  lcm::LogFile log(log_file, "r");
  ASSERT_TRUE(log.good());
  std::map<double, double> log_y;
  long batches = 0;
  for (const lcm::LogEvent* e = log.readNextEvent(); e != nullptr; e = log.readNextEvent()) {
    if (e->channel != names_.name(channel::kWheelsetState)) continue;
    wheelset_states_t batch;
    ASSERT_GE(batch.decode(e->data, 0, e->datalen), 0);
    ASSERT_GE(batch.num_states, 1);
    ASSERT_LE(batch.num_states, wheelset_states_t::MAX_STATES);
    ++batches;
    for (const wheelset_state_t& m : batch.states)
      if (m.run_id == run_id(temp_path("recorded.json"))) log_y[m.t] = m.y;
  }
  // On a mismatch, name the times that differ (the maps are too long for gtest to print whole).
  std::string differences;
  for (const auto& [t, y] : csv_y) {
    const auto it = log_y.find(t);
    if (it == log_y.end())
      differences += " t=" + std::to_string(t) + " missing from the log;";
    else if (it->second != y)
      differences += " t=" + std::to_string(t) + " differs;";
  }
  for (const auto& [t, y] : log_y)
    if (csv_y.count(t) == 0) differences += " t=" + std::to_string(t) + " only in the log;";
  EXPECT_EQ(log_y, csv_y) << differences;
  if (std::system("gnuplot --version >/dev/null 2>&1") == 0) {
    int status = -1;
    const std::string png = temp_path("from-log.png");
    const std::string out = run_command(std::string(WRC_CLI_PATH) + " plot run " + log_file + " --out " + png + " 2>&1",
                                        &status);
    EXPECT_EQ(status, 0) << out;
    EXPECT_GT(read_text(png).size(), 1000u);
    // The same picture as from the live run's history (SVG: no timestamps in it).
    const std::string svg_log = temp_path("from-log.svg"), svg_csv = temp_path("from-csv.svg");
    for (const auto& [input, svg] : {std::pair{log_file, svg_log}, std::pair{csv, svg_csv}}) {
      const std::string plotted =
          run_command(std::string(WRC_CLI_PATH) + " plot run " + input + " --out " + svg + " 2>&1", &status);
      EXPECT_EQ(status, 0) << plotted;
    }
    // The labels name the input file; everything else (every curve's points) must be equal. The
    // grid lines are left out: gnuplot breaks a grid line behind the key, whose width follows the
    // file name's length.
    auto without_grid = [](std::string svg) {
      std::string kept;
      std::istringstream lines(svg);
      for (std::string line; std::getline(lines, line);)
        if (line.find("class=\"gridline\"") == std::string::npos) kept += line + "\n";
      return kept;
    };
    std::string from_log = read_text(svg_log);
    EXPECT_GT(from_log.size(), 1000u);
    for (std::size_t at = from_log.find("run.lcmlog"); at != std::string::npos; at = from_log.find("run.lcmlog", at))
      from_log.replace(at, std::string("run.lcmlog").size(), "recorded.csv");
    EXPECT_EQ(without_grid(from_log), without_grid(read_text(svg_csv))) << "the log's plot differs from the history's";
  }
  // Replayed with the recorded timing, every batch of states arrives again (only the state channel is played:
  // the contact traffic in between is what a loaded receiver's socket buffer would drop).
  long replayed = 0;
  lcm::Subscription* sub = lcm_->subscribeFunction(
      regex_escape(names_.name(channel::kWheelsetState)),
      +[](const lcm::ReceiveBuffer*, const std::string&, long* count) { ++*count; }, &replayed);
  sub->setQueueCapacity(10000);
  ChildProcess player(WRC_CLI_PATH, {"replay", log_file, "--channels", regex_escape(names_.name(channel::kWheelsetState))},
                      temp_path("replay.log"));
  handle_until([&] { return player.wait(0.0); }, 60.0);
  handle_until([] { return false; }, 0.3);
  lcm_->unsubscribe(sub);
  EXPECT_GE(replayed, batches);
}

// A run that names its dynamics (what `wrc sweep --bus` gives each of its runs) is neither replaced
// nor stopped by a plain `wrc run` on the same bus (whose START names no dynamics): that dynamics
// ignores it, the plain run runs on a dynamics of its own, and both end as they would alone.
TEST_F(DynamicsServiceTest, ANamedRunIsNotReplacedByARunThatNamesNoDynamics) {
  std::vector<std::string> named = run_args("multipoint", 30.0, temp_path("named.json"));
  named.insert(named.end(), {"--dynamics-instance", "mine"});
  const std::string named_log = temp_path("named.log");
  ChildProcess first(WRC_CLI_PATH, named, named_log);
  ASSERT_TRUE(wait_running_past(run_id(temp_path("named.json")), 0.5, kRunDeadline)) << read_text(named_log);
  const nlohmann::json plain = run(run_args("multipoint", 0.1, temp_path("plain.json")), "plain");
  EXPECT_EQ(plain.value("state", ""), "finished") << plain.dump();
  int status = -1;
  ASSERT_TRUE(first.wait(kRunDeadline, &status)) << read_text(named_log);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << read_text(named_log);
  const nlohmann::json named_summary = summary(named);
  EXPECT_EQ(named_summary.value("state", ""), "finished") << read_text(named_log);
  EXPECT_EQ(named_summary.value("run_resends", -1), 0) << read_text(named_log);
  EXPECT_DOUBLE_EQ(named_summary.value("t_end", 0.0), 30.0);
}

// The contact service killed with SIGKILL in the middle of a run: the launcher restarts it, the
// dynamics waits for it and repeats the lost query, and the run ends bit for bit where an
// undisturbed one does.
TEST_F(DynamicsServiceTest, KilledContactServiceIsWaitedForAndTheRunEndsTheSame) {
  const std::string log = temp_path("launch.log");
  auto launcher = launch({"contact-multipoint", "dynamics"}, log);
  for (const char* model : {"multipoint", "dynamicsd"})
    ASSERT_TRUE(wait_available(model, kRunDeadline)) << model << "\n" << read_text(log);
  const nlohmann::json clean = run(run_args("multipoint", kDisturbedRun, temp_path("clean.json")), "clean");
  ASSERT_EQ(clean["state"], "finished") << clean.dump();
  const std::vector<std::string> args = run_args("multipoint", kDisturbedRun, temp_path("killed.json"));
  ChildProcess cli(WRC_CLI_PATH, args, temp_path("killed.log"));
  ASSERT_TRUE(wait_running_past(run_id(temp_path("killed.json")), 1.0, 60.0)) << read_text(temp_path("killed.log"));
  int killed_pid = 0;
  for (const ServiceStatus& s : monitor_->services(monotonic_seconds()))
    if (s.last.model == "multipoint" && s.available()) killed_pid = s.last.pid;
  ASSERT_GT(killed_pid, 0);
  ASSERT_EQ(::kill(killed_pid, SIGKILL), 0);
  // Heartbeats keep arriving while the run goes on (the restarted service is seen).
  ASSERT_TRUE(handle_until([&] { return cli.wait(0.0); }, kRunDeadline)) << read_text(temp_path("killed.log"));
  const nlohmann::json killed = summary(args);
  ASSERT_EQ(killed["state"], "finished") << killed.dump() << "\n" << read_text(log);
  EXPECT_GT(killed["counters"]["contact_timeouts"].get<long>() + killed["counters"]["contact_retries"].get<long>(), 0)
      << "killed pid " << killed_pid << " at t = " << last_status_.t << "\n" << killed["counters"].dump() << "\n"
      << read_text(temp_path("killed.log"));
  // A new process serves (the killed one's entry may still look alive for a few periods). A run
  // that ends soon after the restart may end before the new process's first READY heartbeat has
  // been read here: wait for it a few heartbeat periods.
  int restarted_pid = 0;
  handle_until([&] {
    for (const ServiceStatus& s : monitor_->services(monotonic_seconds()))
      if (s.last.model == "multipoint" && s.available() && s.last.pid != killed_pid) restarted_pid = s.last.pid;
    return restarted_pid > 0;
  }, 5.0);
  EXPECT_GT(restarted_pid, 0) << read_text(log);
  expect_same_final_state(clean, killed);
  launcher->signal(SIGINT);
  launcher->wait(20.0);
}

// Every counter of two summaries equal but the bus's own (re-sends and rounds without a reply,
// which a loaded machine may cause, and the bus times): the same run from its start.
void expect_same_counters(const nlohmann::json& a, const nlohmann::json& b) {
  for (const auto& [name, value] : a["counters"].items()) {
    if (name != "contact_retries" && name != "contact_timeouts" && name != "contact_failovers" &&
        name.rfind("bus_", 0) != 0) {
      EXPECT_EQ(value, b["counters"][name]) << name;
    }
  }
}

// The pid of the READY wrc-dynamicsd heard last (0: none).
int ready_dynamics_pid(const HeartbeatMonitor& monitor) {
  int pid = 0;
  for (const ServiceStatus& s : monitor.services(monotonic_seconds()))
    if (s.last.model == "dynamicsd" && s.available()) pid = s.last.pid;
  return pid;
}

class KilledDynamicsTest : public DynamicsServiceTest {
 protected:
  // A multipoint run (kDisturbedRun) undisturbed, then the same run with its
  // wrc-dynamicsd killed (SIGKILL) once it is 1 s into the run: the second run re-sent once
  // (`wrc run` says why, and what it did in its log line `recovery`), ending where the first
  // does in every state and counter.
  void expect_same_run_after_the_kill(const std::string& recovery) {
    // The run is still going when the statuses say it is past t = 1 s and the dynamics is killed.
    constexpr double kSimulated = kDisturbedRun;
    const nlohmann::json clean = run(run_args("multipoint", kSimulated, temp_path("clean.json")), "clean");
    ASSERT_EQ(clean["state"], "finished") << clean.dump();
    EXPECT_EQ(clean["run_resends"], 0);
    const std::vector<std::string> args = run_args("multipoint", kSimulated, temp_path("killed.json"));
    const std::string log = temp_path("killed.log");
    ChildProcess cli(WRC_CLI_PATH, args, log);
    ASSERT_TRUE(wait_running_past(run_id(temp_path("killed.json")), 1.0, kRunDeadline)) << read_text(log);
    const int killed_pid = ready_dynamics_pid(*monitor_);
    ASSERT_GT(killed_pid, 0);
    ASSERT_EQ(::kill(killed_pid, SIGKILL), 0);
    int restarted_pid = 0;  // the process that takes over, heard while the run goes on
    ASSERT_TRUE(handle_until(
        [&] {
          if (const int pid = ready_dynamics_pid(*monitor_); pid != killed_pid && pid > 0) restarted_pid = pid;
          return cli.wait(0.0);
        },
        kRunDeadline))
        << read_text(log);
    const nlohmann::json killed = summary(args);
    ASSERT_EQ(killed["state"], "finished") << killed.dump() << "\n" << read_text(log);
    EXPECT_EQ(killed["run_resends"], 1) << read_text(log);
    EXPECT_NE(read_text(log).find("is gone; sending the run again"), std::string::npos) << read_text(log);
    EXPECT_NE(read_text(log).find(recovery), std::string::npos) << read_text(log);
    EXPECT_GT(restarted_pid, 0);
    EXPECT_NE(restarted_pid, killed_pid);
    expect_same_final_state(clean, killed);
    expect_same_counters(clean, killed);
  }
};

// wrc-dynamicsd killed in the middle of a run under `wrc launch`: `wrc run` hears neither its
// statuses nor its heartbeats, sends the run again to the instance the launcher restarts, and
// the run (deterministic, from the start again) ends bit for bit where an undisturbed one does.
TEST_F(KilledDynamicsTest, TheRunIsSentAgainToTheRestartedServiceAndEndsTheSame) {
  const std::string log = temp_path("launch.log");
  auto launcher = launch({"contact-multipoint", "dynamics"}, log);
  for (const char* model : {"multipoint", "dynamicsd"})
    ASSERT_TRUE(wait_available(model, kRunDeadline)) << model << "\n" << read_text(log);
  expect_same_run_after_the_kill("run: sent again 1 time after losing");
  EXPECT_NE(read_text(log).find("restart #"), std::string::npos) << read_text(log);
  launcher->signal(SIGINT);
  launcher->wait(20.0);
}

// The same without a launcher: `wrc run` started wrc-dynamicsd itself, so it starts another.
TEST_F(KilledDynamicsTest, AServiceTheRunStartedIsStartedAgain) {
  expect_same_run_after_the_kill("has ended (log: ");
}

}  // namespace
}  // namespace wrc::bus::test
