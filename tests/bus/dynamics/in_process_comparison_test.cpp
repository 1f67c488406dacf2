// SPDX-License-Identifier: Apache-2.0
// A run over the bus against the same run --in-process, field by field. The other bus tests compare
// bus runs with bus runs (packet loss, a killed service), so a codec bug that changes every bus
// run alike (a field of the contact query or reply dropped, swapped or converted on the way) would
// pass them all; here the reference is wrc-dynamicsd evaluating the model itself.
//
// What must be equal, and why exactly: both runs are one wrc-dynamicsd integrating the same
// request; the only difference is where the contact model is evaluated (in the service's own
// process or in wrc-contactd) and the bus carries every number a run uses as a double, so the
// results are bit for bit the same or something on the way changed them. Every field of the two
// summaries is compared with ==, except what names or times the run (run_id, in_process,
// wall_time) and the bus's own re-sends (counters.contact_retries, contact_timeouts: 0 in process,
// possibly not on a loaded machine, and a re-sent query gets the same answer). The history CSV:
// every row of one run whose time is also in the other's, compared as text (17 digits); a state
// datagram may be lost on a loaded machine in either run, so only most rows are required.
//
// The models: onepoint (rigid, contact-point jumps, two-point contact: the tracked and second-point
// fields of the query), multipoint (elastic, several patches per wheel) and spline (its model
// fitted by the dynamics in process, fitted by wrc-geometryd and read from its file on the bus).
#include <sys/wait.h>

#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bus_fixture.hpp"
#include "json_leaves.hpp"

namespace wrc::bus::test {
namespace {

constexpr double kRunDeadline = 120.0;  // [s] a short run with service start-up (spline: two fits)
constexpr double kEnd = 0.1;            // [s] simulated, multipoint and spline
// [s] simulated, onepoint: its contact point jumps at 0.06 s and it enters two-point contact at
// about 0.42 s (the second point's fields of the query and the reply on the bus from then on).
constexpr double kOnepointEnd = 0.5;

// The run counters of where the bus time went (run_counter_table()).
constexpr const char* kBusTimes[] = {"bus_round_trip_time", "bus_send_time",  "bus_transfer_time",
                                     "bus_service_wakeup_time", "bus_compute_time", "bus_reply_time",
                                     "bus_client_wakeup_time"};

class InProcessComparisonTest : public BusTest {
 protected:
  void SetUp() override {
    BusTest::SetUp();
    ::setenv("WRC_CACHE_DIR", temp_path("models").c_str(), 1);  // the processes' spline model cache
    auto* counter = lcm_->subscribeFunction(
        ".*CONTACT_QUERY\\..*", +[](const lcm::ReceiveBuffer*, const std::string&, int* n) { ++*n; }, &queries_on_bus_);
    counter->setQueueCapacity(100000);
  }
  int queries_on_bus_ = 0;  // contact queries heard on the bus
  void TearDown() override {
    ::unsetenv("WRC_CACHE_DIR");
    BusTest::TearDown();
  }

  // Runs `wrc run --model model` (with --in-process when asked) to its end; returns the summary
  // and fills history with the CSV's rows by their time column.
  nlohmann::json run(const std::string& model, double t_end, bool in_process,
                     std::map<std::string, std::string>& history, std::string& header) {
    const std::string name = model + (in_process ? "-in-process" : "-bus");
    const std::string summary = temp_path(name + ".json"), csv = temp_path(name + ".csv"), log = temp_path(name + ".log");
    std::vector<std::string> args{"run", "--model", model, "--t-end", std::to_string(t_end), "--summary", summary,
                                  "--history", csv, "--build-dir", WRC_TEST_BUILD_DIR, "--run-id", name};
    if (in_process) args.push_back("--in-process");
    ChildProcess cli(WRC_CLI_PATH, args, log);
    int status = -1;
    EXPECT_TRUE(cli.wait(kRunDeadline, &status)) << read_text(log);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << read_text(log);
    std::ifstream rows(csv);
    std::getline(rows, header);
    for (std::string line; std::getline(rows, line);) history[line.substr(0, line.find(','))] = line;
    std::ifstream in(summary);
    if (!in) return {};
    return nlohmann::json::parse(in);
  }

  // Where the bus run's query time went: nothing in-process; over the bus the parts add up to
  // the round trips (they telescope from the first send to the reply handled; what they leave out
  // is the service's few instructions between its evaluation and the reply's stamp and the
  // dynamics' return from the call, under 20 us a query), each positive but the transfer (LCM's
  // receive time is the kernel's, taken inside the send call that the send part ends with).
  static void expect_query_times(const std::string& model, const nlohmann::json& local, const nlohmann::json& bus) {
    for (const char* part : kBusTimes) EXPECT_EQ(local["counters"].value(part, -1.0), 0.0) << model << " " << part;
    const nlohmann::json& c = bus["counters"];
    const double round_trip = c.value("bus_round_trip_time", 0.0);
    const double queries = c.value("contact_queries", 0.0);
    ASSERT_GT(queries, 10.0) << model;
    EXPECT_GT(round_trip, queries * 5e-6) << model << ": a round trip on a bus takes microseconds";
    double parts = 0;
    for (const char* part : kBusTimes) {
      if (std::string(part) == "bus_round_trip_time") continue;
      parts += c.value(part, 0.0);
      if (std::string(part) != "bus_transfer_time") {
        EXPECT_GT(c.value(part, 0.0), 0.0) << model << " " << part;
      }
    }
    if (c.value("contact_retries", 0) == 0) {
      EXPECT_LE(parts, round_trip + queries * 5e-6) << model;
      EXPECT_GE(parts, round_trip - queries * 20e-6) << model;
    }
    EXPECT_LT(c.value("bus_compute_time", 0.0), round_trip) << model;
  }

  // Both runs of model to t_end compared; returns the in-process summary.
  nlohmann::json expect_same_run(const std::string& model, double t_end) {
    std::map<std::string, std::string> local_rows, bus_rows;
    std::string local_header, bus_header;
    const nlohmann::json local = run(model, t_end, true, local_rows, local_header);
    const nlohmann::json bus = run(model, t_end, false, bus_rows, bus_header);
    EXPECT_EQ(local.value("state", ""), "finished") << local.dump();
    EXPECT_EQ(bus.value("state", ""), "finished") << bus.dump();
    if (!local.contains("counters") || !bus.contains("counters")) {
      ADD_FAILURE() << model << ": no summary";
      return local;
    }
    EXPECT_EQ(local["in_process"], true);
    EXPECT_EQ(bus["in_process"], false);

    std::map<std::string, nlohmann::json> a, b;
    json_leaves(local, "", a);
    json_leaves(bus, "", b);
    std::set<std::string> not_compared{"run_id", "in_process", "wall_time", "counters.contact_retries",
                                       "counters.contact_timeouts"};
    for (const char* part : kBusTimes) not_compared.insert(std::string("counters.") + part);
    int compared = 0;
    for (const auto& [key, value] : a) {
      if (not_compared.count(key)) continue;
      const auto other = b.find(key);
      if (other == b.end()) {
        ADD_FAILURE() << model << ": " << key << " only in the in-process summary";
        continue;
      }
      EXPECT_EQ(value, other->second) << model << ": " << key << " in process " << value.dump() << ", over the bus "
                                      << other->second.dump();
      ++compared;
    }
    // Who answered the queries: over the bus every answered query is counted for its instance; in
    // process nobody was asked.
    const std::string instances = "query_instances.";
    long counted = 0;
    for (const auto& [key, value] : b) {
      if (key.rfind(instances, 0) == 0) {
        EXPECT_EQ(key.substr(instances.size(), model.size() + 1), model + "/") << key;
        counted += value.get<long>();
        continue;
      }
      if (!a.count(key) && !not_compared.count(key)) ADD_FAILURE() << model << ": " << key << " only in the bus summary";
    }
    EXPECT_EQ(counted, bus["counters"]["contact_queries"].get<long>()) << model << ": queries counted per instance";
    for (const auto& [key, value] : a) EXPECT_NE(key.rfind(instances, 0), 0u) << model << ": " << key << " in process";
    EXPECT_GT(compared, 50) << model;  // final state, counters, parameters
    EXPECT_GT(local["counters"]["contact_queries"].get<long>(), 10) << model;
    expect_query_times(model, local, bus);
    // The run's queries went on the model's lanes: none reached the bus (this process listens
    // on it for every contact query channel).
    while (lcm_->handleTimeout(0) > 0) {
    }
    EXPECT_EQ(queries_on_bus_, 0) << model << ": contact queries on the bus instead of the model's lanes";

    EXPECT_EQ(local_header, bus_header);
    size_t common = 0;
    for (const auto& [t, row] : local_rows) {
      const auto other = bus_rows.find(t);
      if (other == bus_rows.end()) continue;
      EXPECT_EQ(row, other->second) << model << ": history at t = " << t;
      ++common;
    }
    // t_end / output period + 1 rows each; a lost state costs a row, most must be there.
    EXPECT_GE(common, local_rows.size() * 9 / 10) << model << ": " << local_rows.size() << " and " << bus_rows.size()
                                                 << " rows, " << common << " at the same times";
    EXPECT_GT(local_rows.size(), 10u) << model;
    return local;
  }
};

// Onepoint: jumps and two-point contact (checked: the run entered it, so the second point's
// fields went over the bus).
TEST_F(InProcessComparisonTest, OnepointOverTheBusIsTheInProcessRun) {
  const nlohmann::json local = expect_same_run("onepoint", kOnepointEnd);
  ASSERT_TRUE(local.contains("counters"));
  EXPECT_GT(local["counters"]["restarts"].get<long>(), 0);
  EXPECT_GT(local["counters"]["two_point_entries"].get<long>(), 0);
}

TEST_F(InProcessComparisonTest, MultipointOverTheBusIsTheInProcessRun) { expect_same_run("multipoint", kEnd); }

TEST_F(InProcessComparisonTest, SplineOverTheBusIsTheInProcessRun) { expect_same_run("spline", kEnd); }

}  // namespace
}  // namespace wrc::bus::test
