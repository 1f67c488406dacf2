// SPDX-License-Identifier: Apache-2.0
// `wrc fit` as the user runs it: a small model fitted from the command line writes a JSON report
// with every fitted parameter's max_error and rms_error (z among them), the validation set and
// what it leaves out, the jumps and knots of both wheels, the timing, and the fit options and the
// track under their parameter tables' keys, every key; bad options fail with one line naming the
// option.
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "bus_fixture.hpp"
#include "core/geometry/track_table.hpp"
#include "core/identity/geometry_key.hpp"
#include "core/spline/spline_fit_table.hpp"

namespace wrc::bus::test {
namespace {

TEST_F(BusTest, FitCommandWritesTheAccuracyReport) {
  const std::string report = temp_path("fit.json");
  int status = -1;
  const std::string out = run_command(std::string(WRC_CLI_PATH) +
                                          " fit --knots 6x1x1 --degree 3x1x1 --samples 3x3 --sample-step 2.5e-4 --report " +
                                          report + " 2>&1",
                                      &status);
  ASSERT_EQ(status, 0) << out;
  EXPECT_NE(out.find("z "), std::string::npos) << out;
  EXPECT_NE(out.find("report: " + report), std::string::npos) << out;
  std::ifstream in(report);
  const nlohmann::json r = nlohmann::json::parse(in);
  const auto& z = r.at("parameters").at("z");
  EXPECT_EQ(z.at("unit"), "m");
  // A coarse model (6 intervals in y, linear in roll and yaw) on the tread: z within tens of um.
  EXPECT_GT(z.at("max_error").get<double>(), 0.0);
  EXPECT_LT(z.at("rms_error").get<double>(), 2e-5);
  EXPECT_LE(z.at("rms_error").get<double>(), z.at("max_error").get<double>());
  for (const char* name : {"contact_angle", "rolling_radius", "s_wheel", "hertz_m", "flange_clearance"})
    EXPECT_TRUE(r.at("parameters").contains(name)) << name;
  EXPECT_EQ(r.at("options").at("intervals"), (nlohmann::json{6, 1, 1}));
  EXPECT_EQ(r.at("options").at("degrees"), (nlohmann::json{3, 1, 1}));
  EXPECT_EQ(r.at("options").at("knot_placement"), "graded");
  EXPECT_TRUE(r.at("options").at("flange_split_s").is_number());
  // Every scalar fit option and every track parameter under its table's key, with the value the
  // command fitted with (the defaults but for the options given above).
  SplineFitOptions fitted;
  fitted.roll_samples = fitted.yaw_samples = 3;
  fitted.sample_step_y = 2.5e-4;
  for (const auto& p : spline_fit_table()) {
    ASSERT_TRUE(r.at("options").contains(p.key)) << p.key;
    EXPECT_EQ(r.at("options").at(p.key).get<double>(), p.get(fitted)) << p.key;
  }
  for (const auto& p : track_parameter_table()) {
    ASSERT_TRUE(r.at("geometry").contains(p.key)) << p.key;
    EXPECT_EQ(r.at("geometry").at(p.key).get<double>(), p.get(TrackParameters{})) << p.key;
  }
  EXPECT_EQ(r.at("geometry").at("wheel"), "S1002");
  EXPECT_EQ(r.at("geometry").at("rail"), "UIC60");
  EXPECT_EQ(r.at("geometry").at("geometry_key"), geometry_key(GeometrySpec{}));
  EXPECT_EQ(r.at("validation").at("excluded_band").get<double>(), 5e-4);
  ASSERT_EQ(r.at("wheels").size(), 2u);
  for (const auto& w : r.at("wheels")) {
    // One list per branch (three for S1002/UIC60: two tread jumps): the 6 intervals asked over
    // the branch's own stretch and more at the same spacing over its continuations past the
    // jumps, which at most double its span here (a reach of 0.68 mm + 0.25 mm beside own
    // stretches of at least 1.3 mm); fewer where a branch is too short for two samples per
    // interval.
    ASSERT_EQ(w.at("branches").get<size_t>(), 3u);
    ASSERT_EQ(w.at("y_breakpoints").size(), 3u);
    for (const auto& b : w.at("y_breakpoints")) {
      EXPECT_LE(b.size(), 13u);
      EXPECT_GE(b.size(), 4u);
    }
    ASSERT_EQ(w.at("transitions").size(), 2u);
    for (const auto& t : w.at("transitions")) {
      EXPECT_GT(t.at("height_half_width").get<double>(), 0.0);
      EXPECT_LE(t.at("height_half_width").get<double>(), r.at("options").at("transition").get<double>());
      EXPECT_GT(t.at("y_reach").get<double>(), 0.0);
    }
    EXPECT_GT(w.at("jumps").size(), 0u);  // S1002/UIC60 has tread jumps in |y| <= 6 mm
  }
  EXPECT_GT(r.at("timing").at("precomputation_seconds").get<double>(), 0.0);

  const std::string bad = run_command(std::string(WRC_CLI_PATH) + " fit --knots 0x2x2 --report " + report + " 2>&1", &status);
  EXPECT_NE(status, 0);
  EXPECT_NE(bad.find("--knots: '0'"), std::string::npos) << bad;
  // Work without a bound is refused before any sampling, naming the option (the fit's memory
  // rule, SplineFitOptions::fit_memory_bytes(); the box's range from the option table).
  const std::string fine = run_command(std::string(WRC_CLI_PATH) + " fit --sample-step 1e-7 --report " + report + " 2>&1", &status);
  EXPECT_NE(status, 0);
  EXPECT_NE(fine.find("(--sample-step)"), std::string::npos) << fine;
  EXPECT_NE(fine.find("at most 1 GiB"), std::string::npos) << fine;
  const std::string wide =
      run_command(std::string(WRC_CLI_PATH) + " fit --box -1e300:1e300,0.001,0.005 --report " + report + " 2>&1", &status);
  EXPECT_NE(status, 0);
  EXPECT_NE(wide.find("--box: y_min = -1e300 is outside [-0.05, 0.05] [m]"), std::string::npos) << wide;
  const std::string no_report = run_command(std::string(WRC_CLI_PATH) + " fit 2>&1", &status);
  EXPECT_NE(status, 0);
  EXPECT_NE(no_report.find("--report"), std::string::npos) << no_report;
}

}  // namespace
}  // namespace wrc::bus::test
