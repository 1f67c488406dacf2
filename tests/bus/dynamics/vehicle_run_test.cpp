// SPDX-License-Identifier: Apache-2.0
// `wrc run --vehicle parameters/vehicles/single-wheelset.json` is the paper's benchmark bit for
// bit: the same request reaches wrc-dynamicsd (the file's masses, inertias, loads and axle boxes
// are the benchmark's exactly, SingleWheelsetVehicle.*), so every field of the summary is equal,
// compared with ==, but what names or times the run (run_id, wall_time). The spline model, the
// paper's benchmark to t = 2 s, in-process (where the contact is evaluated is not what differs;
// InProcessComparisonTest holds the bus to the in-process run). A vehicle file of several bodies
// is refused before any run, naming the file and what it has.
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
  nlohmann::json run(const std::string& name, const std::vector<std::string>& extra, int* exit_status,
                     std::string* log_text = nullptr) {
    const std::string summary = temp_path(name + ".json"), log = temp_path(name + ".log");
    std::vector<std::string> args{"run",          "--model", "spline", "--t-end", "2", "--in-process", "--summary",
                                  summary,        "--build-dir", WRC_TEST_BUILD_DIR, "--run-id", name};
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

TEST_F(VehicleRunTest, AVehicleOfSeveralBodiesIsRefusedNamingTheFile) {
  int status = -1;
  std::string log;
  const std::string car = std::string(WRC_SOURCE_DIR) + "/parameters/vehicles/cooperrider-car.json";
  const nlohmann::json summary = run("car", {"--vehicle", car}, &status, &log);
  EXPECT_NE(status, 0);
  EXPECT_TRUE(summary.empty());
  EXPECT_NE(log.find("--vehicle: " + car + ": vehicle 'Cooperrider car': bodies: 7;"), std::string::npos) << log;
}

}  // namespace
}  // namespace wrc::bus::test
