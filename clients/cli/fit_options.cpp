#include "cli/fit_options.hpp"

#include <sstream>
#include <stdexcept>

namespace wrc::cli {

std::vector<OptionSpec> fit_option_specs() {
  return {
      {"--knots", true, "knot intervals in y x roll x yaw [-]", "10x2x2"},
      {"--degree", true, "spline degree, one for all or y x roll x yaw [-] (0..3)", "3"},
      {"--box", true, "left wheel's box YMIN:YMAX,ROLL_MAX,YAW_MAX [m, rad, rad] (right: mirrored)",
       "-0.006:0.006,0.001,0.005"},
      {"--knot-placement", true, "breakpoints in y: graded (dense where jumps sweep) or uniform", "graded"},
      {"--samples", true, "exact-geometry samples in roll x yaw [-]", "9x9"},
      {"--sample-step", true, "spacing of the samples in y [m]", "1e-4"},
      {"--jump-weight", true, "weight of samples near a tread jump of the common point [-], (0, 1]", "0.01"},
      {"--jump-band", true, "half-width in y of the down-weighted band around each jump [m]", "5e-4"},
      {"--transition", true, "half-width of the blend between branch fits at a jump [m] (0: one fit across the jumps)", "2e-4"},
      {"--flange-angle", true, "profile slope angle that starts the flange region [rad]", "0.7"},
      {"--paper-variant", false, "the paper's benchmark splines: cubic 15x4 in (y, roll), quadratic in yaw", ""},
      {"--threads", true, "sampling threads (0: one per core)", "0"},
  };
}

SplineFitOptions fit_options_from(const Options& options) {
  SplineFitOptions o = options.has("--paper-variant") ? SplineFitOptions::paper_benchmark() : SplineFitOptions{};
  try {
    if (options.has("--knots")) o.intervals = SplineFitOptions::parse_triple(options.text("--knots"), "--knots", 1, 200);
    if (options.has("--degree")) o.degrees = SplineFitOptions::parse_triple(options.text("--degree"), "--degree", 0, 3);
    if (options.has("--samples")) {
      const auto s = SplineFitOptions::parse_triple(options.text("--samples") + "x1", "--samples", 1, 101);
      o.roll_samples = s[0];
      o.yaw_samples = s[1];
    }
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  if (options.has("--box")) {
    const std::string text = options.text("--box");
    const size_t colon = text.find(':'), c1 = text.find(',', colon == std::string::npos ? 0 : colon);
    const size_t c2 = c1 == std::string::npos ? c1 : text.find(',', c1 + 1);
    if (colon == std::string::npos || c1 == std::string::npos || c2 == std::string::npos)
      throw UsageError("--box: '" + text + "' is not of the form YMIN:YMAX,ROLL_MAX,YAW_MAX");
    o.y_min = parse_finite(text.substr(0, colon), "--box y_min");
    o.y_max = parse_finite(text.substr(colon + 1, c1 - colon - 1), "--box y_max");
    o.roll_max = parse_finite(text.substr(c1 + 1, c2 - c1 - 1), "--box roll_max");
    o.yaw_max = parse_finite(text.substr(c2 + 1), "--box yaw_max");
  }
  const std::string placement = options.choice("--knot-placement", {"graded", "uniform"});
  o.placement = placement == "uniform" ? KnotPlacement::kUniform : KnotPlacement::kGraded;
  if (options.has("--sample-step")) o.sample_step_y = options.number("--sample-step", {1e-6, 1e-2});
  if (options.has("--jump-weight")) o.jump_weight = options.number("--jump-weight", {1e-12, 1.0});
  if (options.has("--jump-band")) o.jump_band = options.number("--jump-band", {0.0, 0.01});
  if (options.has("--transition")) o.transition = options.number("--transition", {0.0, 0.002});
  if (options.has("--flange-angle")) o.flange_angle = options.number("--flange-angle", {0.1, 1.5});
  o.threads = options.has("--threads") ? options.integer("--threads", {0, 64}) : 0;
  try {
    o.validate();
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  return o;
}

}  // namespace wrc::cli
