// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Accuracy of a fitted spline contact model against the exact geometry on a validation set that
/// does not coincide with the fit's samples (the midpoints of the sample grid in y, roll and yaw).

#include <array>
#include <vector>

#include "core/spline/spline_geometry_fit.hpp"

namespace wrc {

/// Errors of every fitted quantity in one band of distance from the nearest tread jump.
struct JumpDistanceBand {
  double from = 0, to = 0;  ///< band of the distance in y to the nearest jump on the line [m] (to = +inf: beyond)
  FieldError z;             ///< |z_spline - z_exact| over the band's validation points [m]
  /// |spline - exact| of every field over the band's validation points [SI of the field] (fields[kFieldZ] = z).
  std::array<FieldError, kSplineFieldCount> fields{};
};

/// Accuracy of one wheel.
struct WheelAccuracy {
  /// Per field, over the continuous region: validation points farther than jump_band from every
  /// jump, outside every transition (where the model is one branch's fit alone, not the smooth
  /// maximum of two) and not in flange contact (exact flange clearance > 0).
  std::array<FieldError, kSplineFieldCount> continuous{};
  /// Errors against the distance from the nearest jump (z and every field), flange contact left out.
  std::vector<JumpDistanceBand> z_by_jump_distance;
  int points = 0;                 ///< validation points of this wheel
  int excluded_near_jumps = 0;    ///< within jump_band of a jump
  /// farther than jump_band from every jump but inside a transition (a jump whose two heights
  /// differ by less than its half-width there: the elastic contact loads both points)
  int excluded_in_transition = 0;
  int excluded_flange_contact = 0;///< in flange contact (the model uses the exact geometry there)
  int jumps = 0;                  ///< tread jumps found on the validation lines
};

/// Accuracy of both wheels and what the validation cost.
struct SplineAccuracy {
  std::array<WheelAccuracy, 2> wheels;  ///< left, right
  double seconds = 0;                   ///< wall time [s]
  double excluded_band = 0;             ///< half-width left out around each jump [m] (= jump_band)
};

/// Evaluates model at the midpoints of the sample grid of options (both wheels) as a contact
/// query does (with z's gradient, so the normal and the contact angle are the creep frame's) and
/// compares with the exact geometry. Distance bands: 0, 0.1, 0.25, 0.5, 1, 2 mm, beyond.
SplineAccuracy validate_spline_geometry(const WheelsetGeometry& geometry, const SplineContactGeometry& model,
                                        const SplineFitOptions& options, const FitProgress& progress = {});

}  // namespace wrc
