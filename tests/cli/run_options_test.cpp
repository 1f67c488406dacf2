// SPDX-License-Identifier: Apache-2.0
// `wrc run`'s option assembly (clients/cli/run_options.hpp) without a process: the benchmark's
// values unless an option says otherwise, the lateral-load rule on a track layout, swaps in order
// and within the run, and bad values refused naming the option. The expected values are the
// benchmark's as docs/dynamics.md tabulates them (Fz = 154715 N, Fy = -20000 N, V = 30 m/s).
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "cli/run_options.hpp"

namespace wrc::cli {
namespace {

Options run_options(const std::vector<std::string>& args) { return Options("run", "", run_option_specs(), args); }

TEST(RunOptions, TheBenchmarkUnlessAnOptionSaysOtherwise) {
  std::ostringstream notes;
  const protocol::RunRequest r =
      run_request_from(run_options({"--model", "spline", "--summary", "s.json", "--speed", "12", "--y0", "0.001"}), notes);
  EXPECT_EQ(r.model, "spline");
  EXPECT_EQ(r.spec.wheelset.speed, 12.0);
  EXPECT_EQ(r.spec.initial.y, 0.001);
  EXPECT_EQ(r.spec.wheelset.vertical_force, 154715.0);
  EXPECT_EQ(r.spec.wheelset.lateral_force, -20000.0);
  EXPECT_FALSE(r.in_process);
  EXPECT_TRUE(r.swaps.empty());
  EXPECT_EQ(notes.str(), "");
}

// On a track layout the benchmark's lateral load would add to the curve's centrifugal force: it is
// set to 0 with a note, unless --lateral-force is given (even with the benchmark's own value).
TEST(RunOptions, ATrackLayoutDropsTheLateralLoadUnlessGiven) {
  const std::string track = std::string(WRC_PARAMETERS_DIR) + "/track-curve-R600.json";
  std::ostringstream notes;
  const protocol::RunRequest dropped =
      run_request_from(run_options({"--model", "onepoint", "--summary", "s.json", "--track", track}), notes);
  EXPECT_EQ(dropped.spec.wheelset.lateral_force, 0.0);
  EXPECT_NE(notes.str().find("lateral load: -20000 N of the parameters set to 0"), std::string::npos) << notes.str();
  std::ostringstream none;
  const protocol::RunRequest kept = run_request_from(
      run_options({"--model", "onepoint", "--summary", "s.json", "--track", track, "--lateral-force", "-20000"}), none);
  EXPECT_EQ(kept.spec.wheelset.lateral_force, -20000.0);
  EXPECT_EQ(none.str(), "");
}

TEST(RunOptions, SwapsAreOrderedAndInsideTheRun) {
  const std::vector<protocol::ScheduledSwap> swaps = parse_swaps("0.5:spline,1.25:onepoint", 2.0);
  ASSERT_EQ(swaps.size(), 2u);
  EXPECT_EQ(swaps[0].t, 0.5);
  EXPECT_EQ(swaps[0].model, "spline");
  EXPECT_EQ(swaps[1].t, 1.25);
  EXPECT_EQ(swaps[1].model, "onepoint");
  EXPECT_THROW(parse_swaps("1:spline,0.5:onepoint", 2.0), UsageError);  // not increasing
  EXPECT_THROW(parse_swaps("3:spline", 2.0), UsageError);                // after the run's end
  try {
    parse_swaps("0.5:nosuchmodel", 2.0);
    ADD_FAILURE() << "accepted an unknown model";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("unknown contact model 'nosuchmodel'; known models: onepoint"),
              std::string::npos) << e.what();
  }
}

TEST(RunOptions, BadValuesNameTheOption) {
  std::ostringstream notes;
  for (const auto& [args, name] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{"--model", "spline", "--summary", "s.json", "--speed", "nan"}, "--speed"},
           {{"--model", "spline", "--summary", "s.json", "--y0", "abc"}, "--y0"},
           {{"--model", "nosuch", "--summary", "s.json"}, "nosuch"}}) {
    try {
      run_request_from(run_options(args), notes);
      ADD_FAILURE() << "accepted " << name;
    } catch (const std::exception& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace wrc::cli
