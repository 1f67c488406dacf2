// SPDX-License-Identifier: Apache-2.0
#include "core/spline/spline_validation.hpp"

#include <chrono>
#include <cmath>
#include <limits>

namespace wrc {
namespace {

// Accumulates |error| into a FieldError (rms finished by finish()).
void add(FieldError& e, double error, double& sum_sq) {
  e.max_error = std::max(e.max_error, error);
  sum_sq += error * error;
  ++e.samples;
}

void finish(FieldError& e, double sum_sq) {
  if (e.samples > 0) e.rms_error = std::sqrt(sum_sq / e.samples);
}

}  // namespace

SplineAccuracy validate_spline_geometry(const WheelsetGeometry& geometry, const SplineContactGeometry& model,
                                        const SplineFitOptions& options, const FitProgress& progress) {
  options.validate();
  const auto start = std::chrono::steady_clock::now();
  SplineAccuracy out;
  out.excluded_band = options.jump_band;
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<double> edges{0.0, 1e-4, 2.5e-4, 5e-4, 1e-3, 2e-3, inf};
  const int ny = options.y_samples();
  const long lines = static_cast<long>(options.roll_samples - 1) * (options.yaw_samples - 1);
  for (WheelSide side : {WheelSide::kLeft, WheelSide::kRight}) {
    const int w = static_cast<int>(side);
    const SplineBox box = model.box(side);
    const WheelSampleGrid grid =
        sample_wheel_grid(geometry, side, sample_values(box.y_min, box.y_max, ny, true),
                          sample_values(-box.roll_max, box.roll_max, options.roll_samples, true),
                          sample_values(-box.yaw_max, box.yaw_max, options.yaw_samples, true), options,
                          model.s_split(), options.threads, progress, w * lines, 2 * lines);
    WheelAccuracy& acc = out.wheels[static_cast<size_t>(w)];
    for (size_t b = 0; b + 1 < edges.size(); ++b) acc.z_by_jump_distance.push_back({edges[b], edges[b + 1], {}});
    std::array<double, kSplineFieldCount> sum_sq{};
    std::vector<std::array<double, kSplineFieldCount>> band_sq(acc.z_by_jump_distance.size());
    for (const auto& line : grid.line_jumps) acc.jumps += static_cast<int>(line.size());
    SplineEvaluation e;
    for (size_t j = 0; j < grid.roll.size(); ++j) {
      for (size_t k = 0; k < grid.yaw.size(); ++k) {
        for (size_t i = 0; i < grid.y.size(); ++i) {
          const WheelSample& s = grid.at(i, j, k);
          if (!s.valid) continue;
          ++acc.points;
          WheelsetPose pose;
          pose.y = grid.y[i];
          pose.roll = grid.roll[j];
          pose.yaw = grid.yaw[k];
          pose.z = geometry.track().nominal_radius;
          if (s.flange_clearance <= 0.0) {  // the model uses the exact geometry there
            ++acc.excluded_flange_contact;
            continue;
          }
          model.evaluate(side, pose, SplineDerivatives::kGradient, e);
          const double jump = grid.jump_distance(i, j, k);
          for (size_t b = 0; b < acc.z_by_jump_distance.size(); ++b) {
            JumpDistanceBand& band = acc.z_by_jump_distance[b];
            if (!(jump >= band.from && jump < band.to)) continue;
            for (int f = 0; f < kSplineFieldCount; ++f)
              add(band.fields[static_cast<size_t>(f)],
                  std::abs(e.value[static_cast<size_t>(f)] - s.fields[static_cast<size_t>(f)]),
                  band_sq[b][static_cast<size_t>(f)]);
          }
          if (jump < options.jump_band) {
            ++acc.excluded_near_jumps;
            continue;
          }
          if (e.upper_share > 0.0 && e.upper_share < 1.0) {
            ++acc.excluded_in_transition;
            continue;
          }
          for (int f = 0; f < kSplineFieldCount; ++f)
            add(acc.continuous[static_cast<size_t>(f)],
                std::abs(e.value[static_cast<size_t>(f)] - s.fields[static_cast<size_t>(f)]),
                sum_sq[static_cast<size_t>(f)]);
        }
      }
    }
    for (int f = 0; f < kSplineFieldCount; ++f)
      finish(acc.continuous[static_cast<size_t>(f)], sum_sq[static_cast<size_t>(f)]);
    for (size_t b = 0; b < acc.z_by_jump_distance.size(); ++b) {
      JumpDistanceBand& band = acc.z_by_jump_distance[b];
      for (int f = 0; f < kSplineFieldCount; ++f)
        finish(band.fields[static_cast<size_t>(f)], band_sq[b][static_cast<size_t>(f)]);
      band.z = band.fields[kFieldZ];
    }
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace wrc
