// SPDX-License-Identifier: Apache-2.0
// The front end's commands called in-process through the command registry (clients/cli/command.hpp)
// with the mistakes users make: each is refused before any work (no service started, no fit, no
// file written), with a message that names the option and the bad value, and the value's valid
// range where it has one. One row per mistake; the message is the one `wrc <command>` prints
// after "wrc <command>: ".
#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/command.hpp"
#include "cli/plot/plot_kind.hpp"

namespace wrc::cli {
namespace {

// The message command throws for args, or "" when it does not throw.
std::string refusal(const std::string& command, const std::vector<std::string>& args) {
  for (const Command& c : command_registry()) {
    if (c.name != command) continue;
    try {
      c.run(args);
    } catch (const std::exception& e) {
      return e.what();
    }
    return "";
  }
  ADD_FAILURE() << "no command " << command;
  return "";
}

struct Mistake {
  std::string command;
  std::vector<std::string> args;
  std::string message;  // a part of the refusal
};

TEST(EarlyErrors, EachMistakeIsRefusedNamingTheOptionAndTheValue) {
  const std::string out = (std::filesystem::temp_directory_path() / "wrc-early-error-never-written.csv").string();
  std::filesystem::remove(out);
  const std::string car = std::string(WRC_PARAMETERS_DIR) + "/vehicles/cooperrider-car.json";
  const std::vector<Mistake> mistakes = {
      {"query", {"--model", "nonsense", "--y", "0"}, "--model: 'nonsense' is not one of onepoint, interp, multipoint, spline"},
      {"query", {"--model", "onepoint"}, "missing required option --y"},
      {"query", {"--model", "onepoint", "--y", "0", "--yaw", "0.2"}, "--yaw: 0.2 is outside [-0.06, 0.06] rad"},
      {"query", {"--model", "onepoint", "--y", "0", "--timeout", "0"}, "--timeout: 0 is outside [0.001, 600]"},
      {"query", {"--model", "onepoint", "--y", "--yaw"}, "option --y needs a value, but the next argument is the option '--yaw'"},
      {"bifurcation", {}, "--model is required"},
      {"bifurcation", {"--model", "spline", "--speeds", "30:30:5"}, "--speeds: give at least 2 speeds"},
      {"bifurcation", {"--model", "spline", "--max-time", "0"}, "--max-time: 0 is outside [0.001, 10000]"},
      {"bifurcation", {"--model", "onepoint", "--out", "/nonexistent-folder/b.csv"}, "the folder /nonexistent-folder does not exist"},
      {"bifurcation", {"--model", "onepoint", "--vehicle", car, "--yaw-inertia", "900", "--out", out},
       "--yaw-inertia: a vehicle of several bodies takes it from its file (--vehicle)"},
      {"bifurcation", {"--model", "onepoint", "--vehicle", car, "--out", out},
       "body 'front_wheelset_1': position: z = 0.425 m is the axle's height above the rails, the wheel's nominal "
       "radius is 0.46 m"},
      {"sweep", {"--grid"}, "--grid needs KEY=VALUES"},
      {"sweep", {"--grid", "speed=1:2:0", "--out", out}, "range 1:2:0: the step must be positive"},
      {"sweep", {"--grid", "speed=10,10", "--out", out}, "the value 10 is given twice"},
      {"fit", {"--sample-step", "1e-7", "--report", out}, "(--sample-step)"},
      {"fit", {"--box", "-1e300:1e300,0.001,0.005", "--report", out}, "--box: y_min = -1e300 is outside [-0.05, 0.05] [m]"},
      {"fit", {"--box", "-0.006:0.006,0.1,0.005", "--report", out}, "--box: roll_max = 0.1 is outside (0, 0.05] [rad]"},
      {"run", {"--model", "onepoint", "--t-end", "-1"}, "--t-end: -1 is outside (0, inf) [s]"},
      {"run", {"--model", "nonsense"}, "--model: 'nonsense' is not one of onepoint, interp, multipoint, spline"},
      {"conicity", {"--samples", "2"}, "--samples: 2 is outside [8, 100000]"},
      {"stability", {"--model", "onepoint", "--vehicle", car, "--mass", "900", "--out", out},
       "--mass: a vehicle of several bodies takes it from its file (--vehicle)"},
      {"stability", {"--model", "onepoint", "--vehicle", car, "--out", out},
       "body 'front_wheelset_1': position: z = 0.425 m is the axle's height above the rails, the wheel's nominal "
       "radius is 0.46 m"},
      {"geometry", {"--y", "1"}, "unknown option --y"},
      {"plot", {"area", "--y", "0.003", "--eps0", "1"}, "--eps0: 1 is outside [2.5e-05, 0.01]"},
      {"plot", {"conicity", "--a-from", "0.004", "--a-to", "0.001"}, "--a-to 0.001 is below --a-from 0.004"},
  };
  for (const Mistake& m : mistakes) {
    std::string line = "wrc " + m.command;
    for (const std::string& a : m.args) line += " " + a;
    const std::string message = refusal(m.command, m.args);
    EXPECT_NE(message.find(m.message), std::string::npos) << line << "\n  refused with: '" << message << "'";
    EXPECT_EQ(message.find('\n'), std::string::npos) << line << ": more than one line";
  }
  EXPECT_FALSE(std::filesystem::exists(out));
}

// Every command's and every plot kind's --help parses its option table, which checks each declared
// default against its declared range (options/options.hpp): none is out of its own range.
TEST(EarlyErrors, EveryCommandsDefaultsLieInTheirRanges) {
  for (const Command& c : command_registry()) {
    if (c.name == "plot") continue;  // its kinds below
    try {
      EXPECT_EQ(c.run({"--help"}), 0) << c.name;
    } catch (const std::exception& e) {
      ADD_FAILURE() << "wrc " << c.name << " --help: " << e.what();
    }
  }
  for (const plot::PlotKind& k : plot::plot_kinds()) {
    try {
      EXPECT_EQ(k.run({"--help"}), 0) << k.name;
    } catch (const std::exception& e) {
      ADD_FAILURE() << "wrc plot " << k.name << " --help: " << e.what();
    }
  }
}

}  // namespace
}  // namespace wrc::cli
