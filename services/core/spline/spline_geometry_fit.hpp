// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The precomputation of the spline contact model: sample the exact geometry of both wheels over
/// their boxes, find the jumps of the tread contact point, weight and place knots accordingly, and
/// fit every quantity by weighted least squares (Arnold, section 4).

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/geometry/wheelset_geometry.hpp"
#include "core/spline/spline_contact_geometry.hpp"
#include "core/spline/spline_fit_options.hpp"
#include "core/spline/wheel_sample.hpp"

namespace wrc {

/// A jump of the tread contact point found on one line of constant (roll, yaw) [m, rad].
struct TreadJump {
  double y = 0, roll = 0, yaw = 0;     ///< where it jumps (y to 0.1 um) [m, rad, rad]
  double s_before = 0, s_after = 0;    ///< wheel coordinate just below and above y [m]
};

/// Exact samples of one wheel on a grid of lines y_0..y_{n-1} at each (roll_j, yaw_k), and the jumps
/// found on each line.
struct WheelSampleGrid {
  WheelSide side = WheelSide::kLeft;
  std::vector<double> y, roll, yaw;     ///< grid values [m, rad, rad]
  std::vector<WheelSample> samples;     ///< index ((j * yaw.size() + k) * y.size() + i)
  std::vector<std::vector<TreadJump>> line_jumps;  ///< per line j * yaw.size() + k
  int exact_evaluations = 0;            ///< potential-point scans made (grid and jump bisection)
  const WheelSample& at(size_t i, size_t j, size_t k) const { return samples[(j * yaw.size() + k) * y.size() + i]; }
  /// Distance in y from sample (i, j, k) to the nearest jump on its line [m] (+inf without one).
  double jump_distance(size_t i, size_t j, size_t k) const;
};

/// Progress of a long computation: work units done of total, and what is being done.
using FitProgress = std::function<void(long done, long total, const std::string& stage)>;

/// Samples one wheel over a grid (threads as given, 0 = one per core) and locates the tread jumps
/// on every line by bisection in y to 0.1 um. Throws std::runtime_error naming the pose when more
/// than 1 % of the samples have no tread contact point (box beyond the profiles).
WheelSampleGrid sample_wheel_grid(const WheelsetGeometry& geometry, WheelSide side, std::vector<double> y,
                                  std::vector<double> roll, std::vector<double> yaw, const SplineFitOptions& options,
                                  double s_split, int threads, const FitProgress& progress = {},
                                  long progress_offset = 0, long progress_total = 0);

/// Residuals of one fitted quantity over a set of samples [SI of the quantity].
struct FieldError {
  double max_error = 0;
  double rms_error = 0;
  int samples = 0;
};

/// What the fit of one wheel found and how well it fits its own samples.
struct WheelFitReport {
  std::vector<TreadJump> jumps;          ///< every tread jump found on the sample lines
  /// Per jump surface (branch fits only): its height half-width and y reach [m, m]
  /// (JumpSurface::height_half_width, y_reach).
  std::vector<std::pair<double, double>> jump_half_widths;
  /// The breakpoints used in y, per branch (one list for the paper's form) [m].
  std::vector<std::vector<double>> y_breakpoints;
  FitStatistics fit;                     ///< least-squares assembly and solve
  int samples = 0;                       ///< samples in all
  int samples_near_jumps = 0;            ///< within jump_band of a jump (weight jump_weight)
  int samples_in_flange_contact = 0;     ///< flange clearance <= 0
  int exact_evaluations = 0;             ///< potential-point scans
  /// The fewest and the most tread jumps on one sample line [-]. Branch fits need the same number
  /// (> 0) on every line: where the box's roll and yaw move a jump in and out of it, the wheel is
  /// fitted once across its jumps (the paper's form), which smooths the tread's local conicity
  /// near them.
  int fewest_line_jumps = 0, most_line_jumps = 0;
  bool across_jumps = false;             ///< fitted once across the jumps
  /// Residuals on the samples with weight 1 outside flange contact (the continuous region).
  std::array<FieldError, kSplineFieldCount> residuals{};
};

/// The fitted model and its report.
struct SplineFit {
  std::shared_ptr<const SplineContactGeometry> model;
  std::array<WheelFitReport, 2> wheels;  ///< left, right
  /// The exact samples the model was fitted to, left and right wheel (the geometry table).
  std::array<std::shared_ptr<const WheelSampleGrid>, 2> samples;
  double sampling_seconds = 0;           ///< exact-geometry sampling and jump location [s]
  double fitting_seconds = 0;            ///< weights, knots and least squares [s]
};

/// One line per wheel that fit asked for branch fits (transition > 0, no y breakpoints given) but
/// fitted across its jumps because its sample lines hold different numbers of them: the wheel,
/// the numbers and what it means for the model; empty when there is none.
std::string across_jumps_note(const SplineFit& fit, const SplineFitOptions& options);

/// The grid values of the fit's samples: n values from lo to hi inclusive (n >= 2), or the
/// midpoints of the n - 1 intervals of that grid when midpoints is set (a validation set that does
/// not coincide with the samples).
std::vector<double> sample_values(double lo, double hi, int n, bool midpoints = false);

/// Breakpoints in y for a wheel from its jumps: uniform, or graded with density 1 + grading *
/// (share of lines with a jump within jump_band + half a cell) and at least two samples per interval.
std::vector<double> place_y_breakpoints(const SplineFitOptions& options, const SplineBox& box,
                                        const std::vector<TreadJump>& jumps, int lines);

/// Fits the spline contact model of geometry (both wheels; progress over both wheels' lines).
/// @throws std::invalid_argument for invalid options; std::runtime_error when sampling fails.
SplineFit fit_spline_geometry(const WheelsetGeometry& geometry, const SplineFitOptions& options,
                              const FitProgress& progress = {});

}  // namespace wrc
