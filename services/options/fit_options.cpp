// SPDX-License-Identifier: Apache-2.0
#include "options/fit_options.hpp"

#include <array>
#include <sstream>
#include <stdexcept>
#include <string>

#include "core/numerics/number_text.hpp"
#include "core/spline/spline_fit_table.hpp"
#include "options/parameter_options.hpp"

namespace wrc {

namespace {

// "NxMxK", or "N" when all three are the same (how --knots and --degree are written).
std::string triple_text(const std::array<int, 3>& v) {
  if (v[0] == v[1] && v[1] == v[2]) return std::to_string(v[0]);
  return std::to_string(v[0]) + "x" + std::to_string(v[1]) + "x" + std::to_string(v[2]);
}

}  // namespace

std::vector<OptionSpec> fit_option_specs() {
  const SplineFitOptions d;
  std::vector<OptionSpec> specs{
      {"--knots", true, "knot intervals in y x roll x yaw [-]", triple_text(d.intervals)},
      {"--degree", true, "spline degree, one for all or y x roll x yaw [-] (0..3)", triple_text(d.degrees)},
      {"--box", true, "left wheel's box YMIN:YMAX,ROLL_MAX,YAW_MAX [m, rad, rad] (right: mirrored)",
       number_text(d.y_min) + ":" + number_text(d.y_max) + "," + number_text(d.roll_max) + "," +
           number_text(d.yaw_max)},
      {"--knot-placement", true, "breakpoints in y: graded (dense where jumps sweep) or uniform",
       d.placement == KnotPlacement::kUniform ? "uniform" : "graded"},
      {"--samples", true, "exact-geometry samples in roll x yaw [-]",
       std::to_string(d.roll_samples) + "x" + std::to_string(d.yaw_samples)},
  };
  for (auto& spec : parameter_option_specs(spline_fit_table(), SplineFitOptions{})) specs.push_back(spec);
  specs.push_back(
      {"--paper-variant", false, "the paper's benchmark splines: cubic 15x4 in (y, roll), quadratic in yaw", ""});
  specs.push_back({"--threads", true, "sampling threads (0: one per core)", std::to_string(SplineFitOptions{}.threads),
      NumberRange{0, 64}});
  return specs;
}

std::vector<OptionSpec> spline_model_fit_option_specs() {
  std::vector<OptionSpec> specs = fit_option_specs();
  for (OptionSpec& spec : specs) spec.help = "spline model only: " + spec.help;
  return specs;
}

std::string first_fit_option(const Options& options) {
  for (const OptionSpec& spec : fit_option_specs())
    if (options.has(spec.name)) return spec.name;
  return "";
}

std::vector<std::string> fit_arguments(const Options& options) {
  std::vector<std::string> args;
  for (const OptionSpec& spec : fit_option_specs()) {
    if (!options.has(spec.name)) continue;
    args.push_back(spec.name);
    if (spec.takes_value) args.push_back(options.text(spec.name));
  }
  return args;
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
    // Each part against its table entry's range, before any rule between them.
    for (const char* key : {"y_min", "y_max", "roll_max", "yaw_max"}) {
      const auto* entry = find_parameter(spline_fit_table(), key);
      if (const auto why = entry->violation(entry->get(o)))
        throw UsageError("--box: " + std::string(key) + " = " + entry->value_text(entry->get(o)) + " " + *why);
    }
  }
  const std::string placement = options.choice("--knot-placement", {"graded", "uniform"});
  o.placement = placement == "uniform" ? KnotPlacement::kUniform : KnotPlacement::kGraded;
  apply_parameter_options(spline_fit_table(), options, o);
  o.threads = options.integer("--threads");
  try {
    o.validate();
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  return o;
}

}  // namespace wrc
