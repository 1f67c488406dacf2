// SPDX-License-Identifier: Apache-2.0
/// @file
/// wrc-contactd's own options (services/contactd/contactd_options.hpp): a full command line lands
/// in the model, geometry and (spline) fit fields; a bad value, a missing value, an unknown option or model and
/// a missing --model are refused with one line naming the option and the value.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "contactd/contactd_options.hpp"

namespace wrc::contactd {
namespace {

// Expects parse(args) to throw std::invalid_argument whose message contains `expected`.
void expect_refused(const std::vector<std::string>& args, const std::string& expected) {
  try {
    ContactdOptions::parse(args);
    ADD_FAILURE() << "accepted, expected '" << expected << "'";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
  }
}

// Every option lands in its own field (distinct values; both `--x v` and `--x=v`).
TEST(ContactdOptions, ParsesEveryOption) {
  const ContactdOptions o = ContactdOptions::parse({"--model", "interp", "--wheel=conic:0.05", "--rail", "circle:0.1",
                                                    "--gauge", "1.5", "--gauge-depth=0.012", "--flange-back", "1.36",
                                                    "--taping-line-offset", "0.071", "--r0", "0.45",
                                                    "--inclination", "1:20"});
  EXPECT_EQ(o.model, "interp");
  EXPECT_EQ(o.geometry.wheel, "conic:0.05");
  EXPECT_EQ(o.geometry.rail, "circle:0.1");
  EXPECT_DOUBLE_EQ(o.geometry.track.gauge, 1.5);
  EXPECT_DOUBLE_EQ(o.geometry.track.gauge_depth, 0.012);
  EXPECT_DOUBLE_EQ(o.geometry.track.flange_back_spacing, 1.36);
  EXPECT_DOUBLE_EQ(o.geometry.track.taping_line_offset, 0.071);
  EXPECT_DOUBLE_EQ(o.geometry.track.nominal_radius, 0.45);
  EXPECT_NEAR(o.geometry.track.inclination, std::atan(1.0 / 20.0), 1e-6);  // 1:20 as an angle [rad]
}

TEST(ContactdOptions, RefusesNamingOptionAndValue) {
  expect_refused({"--model", "onepoint", "--gauge", "3"}, "--gauge: 3 is outside [0.5, 2.5]");
  expect_refused({"--model", "onepoint", "--r0", "abc"}, "--r0: 'abc' is not a finite number");
  expect_refused({"--model", "onepoint", "--gauge-depth=-0.001"}, "--gauge-depth: -0.001 is outside [0, 0.05]");
  expect_refused({"--model", "onepoint", "--frobnicate", "1"}, "unknown option --frobnicate (see wrc-contactd --help)");
  expect_refused({"--model", "onepoint", "stray"}, "unexpected argument 'stray'");
  expect_refused({"--model", "onepoint", "--gauge"}, "option --gauge needs a value");
  expect_refused({"--model", "twopoint"}, "--model: ");
  expect_refused({"--model", "twopoint"}, "twopoint");
  expect_refused({"--model", "onepoint", "--inclination", "1:0"}, "--inclination: ");
  expect_refused({"--gauge", "1.435"}, "--model is required (onepoint, interp, multipoint, spline)");
  expect_refused({"--model", "onepoint", "--box", "-0.012:0.012,0.004,0.005"},
                 "--box: a fit option, but the onepoint model is not fitted (the spline model is)");
  expect_refused({"--model", "spline", "--box", "-1:0.012,0.004,0.005"}, "--box: y_min = -1 is outside");
}

// The spline model's fit options land in its fit (wrc fit's names); without them, the default fit.
TEST(ContactdOptions, TheSplineServiceTakesTheFitOptions) {
  const ContactdOptions wide =
      ContactdOptions::parse({"--model", "spline", "--box", "-0.012:0.012,0.004,0.005", "--knots", "20x2x2"});
  EXPECT_DOUBLE_EQ(wide.fit.y_min, -0.012);
  EXPECT_DOUBLE_EQ(wide.fit.y_max, 0.012);
  EXPECT_DOUBLE_EQ(wide.fit.roll_max, 0.004);
  EXPECT_EQ(wide.fit.intervals[0], 20);
  const ContactdOptions plain = ContactdOptions::parse({"--model", "spline"});
  EXPECT_EQ(plain.fit.canonical_text(), SplineFitOptions{}.canonical_text());
}

}  // namespace
}  // namespace wrc::contactd
