// SPDX-License-Identifier: Apache-2.0
// `wrc run --vehicle parameters/vehicles/single-wheelset.json` is the paper's benchmark bit for
// bit: the same request reaches wrc-dynamicsd (the file's masses, inertias, loads and axle boxes
// are the benchmark's exactly, SingleWheelsetVehicle.*), so every field of the summary is equal,
// compared with ==, but what names or times the run (run_id, wall_time). The spline model, the
// paper's benchmark to t = 2 s, in-process (where the contact is evaluated is not what differs;
// InProcessComparisonTest holds the bus to the in-process run). The Cooperrider bogie (several
// bodies, the vehicle's equations) runs over the bus as in-process: every wheelset's final state
// and every counter equal, its queries on the spline lanes counted per instance, the history and
// the summary with both wheelsets.
#include <sys/wait.h>

#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bus_fixture.hpp"
#include "json_leaves.hpp"

namespace wrc::bus::test {
namespace {

class VehicleRunTest : public BusTest {
 protected:
  // `wrc run` with args after the common ones; the summary (empty when none was written) and the
  // exit status.
  // in_process false: over the bus (the services started by wrc run).
  nlohmann::json run(const std::string& name, const std::vector<std::string>& extra, int* exit_status,
                     std::string* log_text = nullptr, bool in_process = true) {
    const std::string summary = temp_path(name + ".json"), log = temp_path(name + ".log");
    std::vector<std::string> args{"run",   "--model",     "spline",           "--t-end", "2",   "--summary",
                                  summary, "--build-dir", WRC_TEST_BUILD_DIR, "--run-id", name};
    if (in_process) args.push_back("--in-process");
    args.insert(args.end(), extra.begin(), extra.end());
    ChildProcess cli(WRC_CLI_PATH, args, log);
    int status = -1;
    EXPECT_TRUE(cli.wait(120.0, &status)) << read_text(log);
    *exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    if (log_text) *log_text = read_text(log);
    std::ifstream in(summary);
    return in ? nlohmann::json::parse(in) : nlohmann::json{};
  }
};

TEST_F(VehicleRunTest, TheSingleWheelsetFileIsTheBenchmarkBitForBit) {
  int status = -1;
  std::string log;
  const nlohmann::json benchmark = run("benchmark", {}, &status);
  ASSERT_EQ(status, 0);
  const nlohmann::json from_file =
      run("vehicle", {"--vehicle", std::string(WRC_SOURCE_DIR) + "/parameters/vehicles/single-wheelset.json"}, &status,
          &log);
  ASSERT_EQ(status, 0) << log;
  EXPECT_NE(log.find("vehicle: 'benchmark single wheelset'"), std::string::npos) << log;
  ASSERT_EQ(benchmark.value("state", ""), "finished") << benchmark.dump();
  std::map<std::string, nlohmann::json> a, b;
  json_leaves(benchmark, "", a);
  json_leaves(from_file, "", b);
  ASSERT_GT(a.size(), 100u);
  EXPECT_EQ(a.size(), b.size());
  for (const auto& [path, value] : a) {
    if (path == "run_id" || path == "wall_time") continue;
    ASSERT_TRUE(b.count(path)) << path;
    EXPECT_EQ(value, b.at(path)) << path;
  }
}

TEST_F(VehicleRunTest, TheBogieOverTheBusIsTheInProcessRun) {
  const std::string bogie = std::string(WRC_SOURCE_DIR) + "/parameters/vehicles/cooperrider-bogie.json";
  // Released with its leading wheelset 2 mm off the centre line, on the bogie's wheel radius.
  const std::vector<std::string> options{"--vehicle", bogie, "--r0", "0.425", "--y0", "0.002"};
  int status = -1;
  std::string local_log, bus_log;
  std::vector<std::string> with_history = options;
  with_history.insert(with_history.end(), {"--history", temp_path("bogie-bus.csv")});
  const nlohmann::json local = run("bogie-local", options, &status, &local_log);
  ASSERT_EQ(status, 0) << local_log;
  const nlohmann::json bus = run("bogie-bus", with_history, &status, &bus_log, false);
  ASSERT_EQ(status, 0) << bus_log;
  EXPECT_NE(bus_log.find("vehicle: 'Cooperrider bogie'"), std::string::npos) << bus_log;
  ASSERT_EQ(local.value("state", ""), "finished") << local.dump();
  ASSERT_EQ(bus.value("state", ""), "finished") << bus.dump();
  ASSERT_TRUE(bus.contains("vehicle")) << bus.dump();
  const nlohmann::json& wheelsets = bus["vehicle"]["wheelsets"];
  ASSERT_EQ(wheelsets.size(), 2u);
  EXPECT_EQ(wheelsets[0]["name"], "wheelset_1");
  EXPECT_EQ(wheelsets[1]["name"], "wheelset_2");
  // The first wheelset is the summary's final state; released off the centre line, it moved.
  EXPECT_EQ(bus["final_state"], wheelsets[0]["final_state"]);
  EXPECT_NE(wheelsets[0]["final_state"]["y"].get<double>(), wheelsets[1]["final_state"]["y"].get<double>());
  // The frame's largest accelerations: it moves (a few mm at a few Hz: well above 1e-3 m/s^2).
  ASSERT_EQ(bus["vehicle"]["accelerations"].size(), 1u);
  EXPECT_EQ(bus["vehicle"]["accelerations"][0]["name"], "frame");
  EXPECT_GT(bus["vehicle"]["accelerations"][0]["lateral"]["max"].get<double>(), 1e-3);
  // Over the bus as in-process: every final state and counter but the bus's own times and misses.
  EXPECT_EQ(local["vehicle"], bus["vehicle"]);
  for (const auto& [key, value] : local["counters"].items()) {
    if (key.rfind("bus_", 0) == 0 || key == "contact_retries" || key == "contact_timeouts" ||
        key == "contact_failovers")
      continue;
    EXPECT_EQ(value, bus["counters"][key]) << key;
  }
  long counted = 0;
  for (const auto& [instance, queries] : bus["query_instances"].items()) {
    EXPECT_EQ(instance.rfind("spline/", 0), 0u) << instance;
    counted += queries.get<long>();
  }
  EXPECT_EQ(counted, bus["counters"]["contact_queries"].get<long>());
  // The history: both wheelsets at every output time.
  std::ifstream history(temp_path("bogie-bus.csv"));
  std::string header, line;
  ASSERT_TRUE(std::getline(history, header));
  EXPECT_NE(header.find(",wheelset [-],model [-]"), std::string::npos) << header;
  std::map<int, int> rows;
  while (std::getline(history, line)) {
    const std::size_t last = line.rfind(','), before = line.rfind(',', last - 1);
    ++rows[std::stoi(line.substr(before + 1, last - before - 1))];
  }
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0], rows[1]);
  EXPECT_GE(rows[0], 2000);  // 2 s of output every 1 ms
}

// A vehicle in a curve leaves the spline model's default box (the tread, |y| <= 6 mm, docs/vehicle.md),
// so a run takes the spline fit's options (--box, --knots, ...): released 8 mm off the centre
// (flange contact, 27 mrad of roll) the default model refuses the start naming its box, the one
// fitted over --box -0.012:0.012,0.03,0.005 starts (and runs until its left wheel lifts off). In
// process the dynamics fits it; over the bus the run starts a spline service fitted so (its key is
// the fit's model key, protocol/contact/contact_service_key.hpp) and ends as the in-process run,
// every field but the wall time and the bus's own counters equal.
TEST_F(VehicleRunTest, ARunFitsItsSplineModelWithItsFitOptions) {
  int status = -1;
  std::string log;
  const std::vector<std::string> start{"--lateral-force", "0", "--y0", "0.008"};
  const nlohmann::json narrow = run("narrow", start, &status, &log);
  ASSERT_FALSE(narrow.empty()) << log;
  EXPECT_EQ(narrow["state"], "failed");
  EXPECT_NE(narrow["message"].get<std::string>().find("y = 0.008 m not in [-0.006, 0.006] m"), std::string::npos)
      << narrow["message"];
  std::vector<std::string> wide_args = start;
  wide_args.insert(wide_args.end(), {"--box", "-0.012:0.012,0.03,0.005"});
  const nlohmann::json wide = run("wide", wide_args, &status, &log);
  ASSERT_FALSE(wide.empty()) << log;
  EXPECT_EQ(wide["message"].get<std::string>().find("box"), std::string::npos) << wide["message"];
  EXPECT_GT(wide["counters"]["steps"].get<long>(), 10) << wide.dump();
  const nlohmann::json bus = run("wide-bus", wide_args, &status, &log, false);
  ASSERT_FALSE(bus.empty()) << log;
  EXPECT_NE(log.find("starting"), std::string::npos) << log;  // its own spline service, fitted so
  EXPECT_EQ(bus["state"], wide["state"]);
  EXPECT_EQ(bus["message"], wide["message"]);
  EXPECT_EQ(bus["final_state"], wide["final_state"]);
  EXPECT_EQ(bus["counters"]["steps"], wide["counters"]["steps"]);
}

TEST_F(VehicleRunTest, WhatAVehicleFileGivesIsNotAnOption) {
  int status = -1;
  std::string log;
  const std::string car = std::string(WRC_SOURCE_DIR) + "/parameters/vehicles/cooperrider-car.json";
  EXPECT_TRUE(run("car-mass", {"--vehicle", car, "--mass", "1500"}, &status, &log).empty());
  EXPECT_NE(status, 0);
  EXPECT_NE(log.find("--mass: a vehicle of several bodies takes it from its file (--vehicle)"), std::string::npos)
      << log;
}

}  // namespace
}  // namespace wrc::bus::test
