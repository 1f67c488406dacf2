// SPDX-License-Identifier: Apache-2.0
// What a run writes (clients/cli/run_outputs.hpp) and what a sweep extracts from it
// (sweep_results.hpp): the summary JSON round-trips through its file exactly, with the run's
// request (its first model, its parameters) and its outcome (last model, final state) in it;
// the history CSV has one header "name [unit]" per column and one row per state in time order, and
// an --extract that names neither a group nor a value is refused listing the groups.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "cli/options.hpp"
#include "cli/run_outputs.hpp"
#include "cli/sweep/sweep_results.hpp"

namespace wrc::cli {
namespace {

std::string temp_file(const std::string& name) {
  return (std::filesystem::path(::testing::TempDir()) / (name + std::to_string(::getpid()))).string();
}

TEST(RunOutputs, SummaryRoundTripsThroughItsFile) {
  protocol::RunRequest request;
  request.model = "spline";
  request.run_id = "r1";
  request.spec.wheelset.speed = 12.5;
  run_summary_t summary{};
  summary.model = "onepoint";  // swapped to, say: the summary's model is the run's last
  summary.y = -4.7955e-3;
  const nlohmann::json j = summary_json(summary, request, "key");
  ASSERT_TRUE(j.contains("final_state"));
  ASSERT_TRUE(j.contains("counters"));
  const std::string path = temp_file("summary.json");
  write_summary(path, j);
  std::ifstream in(path);
  const nlohmann::json back = nlohmann::json::parse(in);
  EXPECT_EQ(back, j);
  EXPECT_EQ(back.at("model"), "onepoint");
  EXPECT_EQ(back.at("initial_model"), "spline");
  EXPECT_EQ(back.at("final_state").at("y").get<double>(), -4.7955e-3);  // to the last bit
  EXPECT_EQ(back.at("parameters").at("speed").get<double>(), 12.5);
  std::remove(path.c_str());
}

TEST(RunOutputs, HistoryHasUnitsInItsHeaderAndRowsInTimeOrder) {
  StateHistory history;
  for (double t : {0.02, 0.0, 0.01}) {
    wheelset_state_t s{};
    s.t = t;
    s.y = 1e-3 * t;
    history[{t, 0}] = s;
  }
  const std::string path = temp_file("history.csv");
  write_history(path, history);
  std::ifstream in(path);
  std::string header, line;
  std::getline(in, header);
  std::stringstream columns(header);
  int n = 0;
  for (std::string c; std::getline(columns, c, ',');) {
    ++n;
    EXPECT_NE(c.find(" ["), std::string::npos) << "no unit: " << c;
    EXPECT_EQ(c.back(), ']') << c;
  }
  EXPECT_GT(n, 5);
  EXPECT_EQ(header.rfind("t [s],y [m]", 0), 0u) << header;
  double last = -1.0;
  int rows = 0;
  while (std::getline(in, line)) {
    const double t = std::stod(line.substr(0, line.find(',')));
    EXPECT_GT(t, last);
    last = t;
    ++rows;
  }
  EXPECT_EQ(rows, 3);
  std::remove(path.c_str());
}

TEST(SweepResults, AnUnknownExtractListsTheGroups) {
  protocol::RunRequest example;
  example.model = "onepoint";
  try {
    result_columns({"nothing"}, example);
    ADD_FAILURE() << "accepted";
  } catch (const UsageError& e) {
    std::string groups;
    for (const std::string& g : extract_groups()) groups += (groups.empty() ? "" : ", ") + g;
    EXPECT_NE(std::string(e.what()).find("neither a group (" + groups + ")"), std::string::npos) << e.what();
  }
  const std::vector<ResultColumn> final = result_columns({"final"}, example);
  ASSERT_FALSE(final.empty());
  EXPECT_EQ(final.front().path.rfind("final_state.", 0), 0u);
  EXPECT_THROW(result_columns({"final", "final"}, example), UsageError);  // a column twice
}

}  // namespace
}  // namespace wrc::cli
