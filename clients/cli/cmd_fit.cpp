// SPDX-License-Identifier: Apache-2.0
// wrc fit: the precomputation of the spline contact model from the command line, with a progress
// bar: in this process with its accuracy report against the exact geometry, or on wrc-geometryd
// (--service, cli/fit_on_service.hpp).

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "cli/command.hpp"
#include "cli/fit_on_service.hpp"
#include "options/fit_options.hpp"
#include "cli/options.hpp"
#include "cli/output_paths.hpp"
#include "cli/profile_options.hpp"
#include "cli/progress_bar.hpp"
#include "cli/service_starter.hpp"
#include "cli/table_json.hpp"
#include "core/geometry/track_table.hpp"
#include "core/identity/geometry_key.hpp"
#include "core/spline/spline_fit_table.hpp"
#include "core/spline/spline_geometry_fit.hpp"
#include "core/spline/spline_validation.hpp"

namespace wrc::cli {
namespace {

using nlohmann::json;

json field_error(const FieldError& e) {
  return {{"max_error", e.max_error}, {"rms_error", e.rms_error}, {"points", e.samples}};
}

// The worse of the two wheels (max of max, rms over both wheels' points).
FieldError both_wheels(const FieldError& a, const FieldError& b) {
  FieldError e;
  e.samples = a.samples + b.samples;
  e.max_error = std::max(a.max_error, b.max_error);
  if (e.samples > 0)
    e.rms_error = std::sqrt((a.rms_error * a.rms_error * a.samples + b.rms_error * b.rms_error * b.samples) / e.samples);
  return e;
}

json report_json(const GeometrySpec& spec, const SplineFitOptions& o, const SplineFit& fit,
                 const SplineAccuracy* accuracy) {
  json r;
  // The track and the scalar fit options under their tables' keys (core/geometry/track_table.hpp,
  // core/spline/spline_fit_table.hpp), with what no table holds.
  r["geometry"] = table_json(track_parameter_table(), spec.track);
  r["geometry"]["wheel"] = spec.wheel;
  r["geometry"]["rail"] = spec.rail;
  r["geometry"]["geometry_key"] = geometry_key(spec);
  r["options"] = table_json(spline_fit_table(), o);
  r["options"]["intervals"] = o.intervals;
  r["options"]["degrees"] = o.degrees;
  r["options"]["knot_placement"] = o.placement == KnotPlacement::kUniform ? "uniform" : "graded";
  r["options"]["flange_split_s"] = fit.model->s_split();
  json wheels = json::array();
  for (WheelSide side : {WheelSide::kLeft, WheelSide::kRight}) {
    const WheelFitReport& w = fit.wheels[static_cast<size_t>(side)];
    json jumps = json::array();
    for (const TreadJump& j : w.jumps)
      jumps.push_back({{"y", j.y}, {"roll", j.roll}, {"yaw", j.yaw}, {"s_before", j.s_before}, {"s_after", j.s_after}});
    json transitions = json::array();
    for (const auto& [half_width, y_reach] : w.jump_half_widths)
      transitions.push_back({{"height_half_width", half_width}, {"y_reach", y_reach}});
    json residuals;
    for (int f = 0; f < kSplineFieldCount; ++f)
      residuals[kSplineFields[static_cast<size_t>(f)].name] = field_error(w.residuals[static_cast<size_t>(f)]);
    wheels.push_back({{"wheel", side_name(side)},
                      {"branches", w.y_breakpoints.size()},
                      {"across_jumps", w.across_jumps},
                      {"line_jumps", {{"fewest", w.fewest_line_jumps}, {"most", w.most_line_jumps}}},
                      {"y_breakpoints", w.y_breakpoints},
                      {"samples", w.samples},
                      {"samples_near_jumps", w.samples_near_jumps},
                      {"samples_in_flange_contact", w.samples_in_flange_contact},
                      {"exact_evaluations", w.exact_evaluations},
                      {"coefficients_per_function", w.fit.coefficients},
                      {"normal_matrix_nonzeros", w.fit.nonzeros},
                      {"fit_seconds", w.fit.seconds},
                      {"jumps", jumps},
                      {"transitions", transitions},
                      {"fit_residuals", residuals}});
  }
  r["wheels"] = wheels;
  r["timing"] = {{"sampling_seconds", fit.sampling_seconds},
                 {"fitting_seconds", fit.fitting_seconds},
                 {"precomputation_seconds", fit.sampling_seconds + fit.fitting_seconds}};
  if (!accuracy) return r;
  json parameters;
  for (int f = 0; f < kSplineFieldCount; ++f) {
    const auto& info = kSplineFields[static_cast<size_t>(f)];
    const FieldError& l = accuracy->wheels[0].continuous[static_cast<size_t>(f)];
    const FieldError& rr = accuracy->wheels[1].continuous[static_cast<size_t>(f)];
    json p = field_error(both_wheels(l, rr));
    p["unit"] = info.unit;
    p["left"] = field_error(l);
    p["right"] = field_error(rr);
    parameters[info.name] = p;
  }
  r["parameters"] = parameters;
  json validation;
  validation["set"] = "midpoints of the sample grid in y, roll and yaw (no validation point is a sample)";
  validation["excluded_band"] = accuracy->excluded_band;
  validation["excluded"] =
      "points within excluded_band [m] in y of a tread jump of the exact common point on their line, points inside a "
      "transition (where the model is the smooth maximum of two branches, not a fit of the lowest minimum), and points in "
      "flange contact (the model uses the exact geometry there)";
  validation["seconds"] = accuracy->seconds;
  json vw = json::array();
  for (WheelSide side : {WheelSide::kLeft, WheelSide::kRight}) {
    const WheelAccuracy& a = accuracy->wheels[static_cast<size_t>(side)];
    json bands = json::array(), by_distance = json::array();
    for (const JumpDistanceBand& b : a.z_by_jump_distance) {
      json jb = field_error(b.z);
      jb["from"] = b.from;
      jb["to"] = std::isinf(b.to) ? json(nullptr) : json(b.to);
      bands.push_back(jb);
      json fields;
      for (int f = 0; f < kSplineFieldCount; ++f)
        fields[kSplineFields[static_cast<size_t>(f)].name] = field_error(b.fields[static_cast<size_t>(f)]);
      by_distance.push_back({{"from", jb["from"]}, {"to", jb["to"]}, {"parameters", fields}});
    }
    vw.push_back({{"wheel", side_name(side)},
                  {"points", a.points},
                  {"excluded_near_jumps", a.excluded_near_jumps},
                  {"excluded_in_transition", a.excluded_in_transition},
                  {"excluded_flange_contact", a.excluded_flange_contact},
                  {"jumps", a.jumps},
                  {"z_by_jump_distance", bands},
                  {"by_jump_distance", by_distance}});
  }
  validation["wheels"] = vw;
  r["validation"] = validation;
  return r;
}

int run_fit(const std::vector<std::string>& args) {
  auto specs = profile_option_specs();
  for (OptionSpec& s : fit_option_specs()) specs.push_back(std::move(s));
  specs.push_back({"--report", true, "accuracy report to write (JSON)", ""});
  specs.push_back({"--no-validation", false, "skip the validation against the exact geometry", ""});
  for (OptionSpec& s : fit_on_service_option_specs()) specs.push_back(std::move(s));
  for (OptionSpec& s : service_start_option_specs()) specs.push_back(std::move(s));
  Options opt("fit", "[profile and track options] [--knots NYxNRxNPSI] [--degree D] [--box ...] (--report FILE.json | --service)",
              specs, args);
  if (opt.help_requested()) {
    std::cout << opt.help()
              << "\nFits Arnold's spline contact model (weighted least-squares tensor-product splines over\n"
                 "(y, roll, yaw), per wheel) to samples of the exact geometry and reports, per fitted quantity,\n"
                 "max_error and rms_error [SI] against the exact geometry at points that are not samples, in\n"
                 "the continuous region (the report says what is left out around each jump), and every\n"
                 "quantity's error against the distance from the nearest jump (by_jump_distance).\n"
                 "With --service, wrc-geometryd precomputes the model (the one every spline contact service of\n"
                 "this geometry and these options gets from its cache) and the bar follows its progress; no report.\n";
    return 0;
  }
  const SplineFitOptions options = fit_options_from(opt);
  const GeometrySpec spec = geometry_spec_from_options(opt);
  if (opt.has("--service")) {
    if (opt.has("--report")) throw UsageError("--report is for the fit in this process, not with --service");
    return fit_on_service(opt, spec, options);
  }
  for (const char* only_service : {"--recompute", "--wait"})
    if (opt.has(only_service)) throw UsageError(std::string(only_service) + " needs --service");
  const std::string report_path = opt.required_text("--report");
  check_output_path(report_path, "--report");  // before the fit, not after it
  const WheelsetGeometry geometry = make_geometry(spec);

  ProgressBar fit_bar("fit");
  const SplineFit fit = fit_spline_geometry(
      geometry, options, [&](long done, long total, const std::string& stage) { fit_bar.update(done, total, stage); });
  fit_bar.finish();
  std::unique_ptr<SplineAccuracy> accuracy;
  if (!opt.has("--no-validation")) {
    ProgressBar check_bar("validation");
    accuracy = std::make_unique<SplineAccuracy>(validate_spline_geometry(
        geometry, *fit.model, options,
        [&](long done, long total, const std::string& stage) { check_bar.update(done, total, stage); }));
    check_bar.finish();
  }
  const json report = report_json(spec, options, fit, accuracy.get());
  std::ofstream out(report_path);
  out << report.dump(2) << "\n";
  if (!out) throw std::runtime_error("fit: cannot write the report to " + report_path);

  std::printf("precomputation %.3f s (sampling %.3f s, fitting %.3f s); %d x %d knot intervals in y, roll, yaw %d\n",
              fit.sampling_seconds + fit.fitting_seconds, fit.sampling_seconds, fit.fitting_seconds,
              options.intervals[0], options.intervals[1], options.intervals[2]);
  if (const std::string note = across_jumps_note(fit, options); !note.empty()) std::printf("%s\n", note.c_str());
  if (accuracy) {
    // Every parameter's rms error against the distance from the nearest jump (both wheels).
    const auto& bands = accuracy->wheels[0].z_by_jump_distance;
    std::printf("%-24s", "rms by jump distance [mm]");
    for (const JumpDistanceBand& b : bands) {
      if (std::isinf(b.to)) {
        std::printf(" %11s", (">" + std::to_string(b.from * 1e3).substr(0, 4)).c_str());
      } else {
        std::printf(" %11s", (std::to_string(b.from * 1e3).substr(0, 4) + "-" + std::to_string(b.to * 1e3).substr(0, 4)).c_str());
      }
    }
    std::printf("\n");
    for (int f = 0; f < kSplineFieldCount; ++f) {
      std::printf("%-24s", kSplineFields[static_cast<size_t>(f)].name);
      for (size_t b = 0; b < bands.size(); ++b)
        std::printf(" %11.3g", both_wheels(accuracy->wheels[0].z_by_jump_distance[b].fields[static_cast<size_t>(f)],
                                           accuracy->wheels[1].z_by_jump_distance[b].fields[static_cast<size_t>(f)])
                                   .rms_error);
      std::printf("\n");
    }
    std::printf("%-24s %14s %14s   (validation, continuous region, both wheels)\n", "parameter", "max_error",
                "rms_error");
    for (int f = 0; f < kSplineFieldCount; ++f) {
      const auto& info = kSplineFields[static_cast<size_t>(f)];
      const FieldError e = both_wheels(accuracy->wheels[0].continuous[static_cast<size_t>(f)],
                                       accuracy->wheels[1].continuous[static_cast<size_t>(f)]);
      std::printf("%-24s %14.4g %14.4g %s\n", info.name, e.max_error, e.rms_error, info.unit);
    }
  }
  std::printf("report: %s\n", report_path.c_str());
  return 0;
}

const CommandRegistrar registrar{{"fit", "precompute the spline contact model and report its accuracy", run_fit}};

}  // namespace
}  // namespace wrc::cli
