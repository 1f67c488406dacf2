// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The quantities the spline contact model fits per wheel over (y, roll, yaw): one list, used by
/// the sampling, the fit, the evaluation, the model file and the accuracy report.

#include <array>

#include "core/geometry/contact_point_fields.hpp"

namespace wrc {

/// Index of a fitted quantity. All are functions of the wheelset's lateral shift y [m], roll
/// [rad] and yaw [rad] (the height z only shifts positions and the distance, see kZ).
enum SplineField : int {
  /// Vertical displacement: the height of the wheelset centre above the top-of-rail plane at which
  /// this wheel just touches its rail [m]. The distance at any height z is z - z_touch (exact: the
  /// distance is affine in z with unit slope). Fitted C2 (the paper: the reaction forces contain
  /// its second derivatives).
  kFieldZ = 0,
  /// Flange clearance: the smallest vertical distance of the wheel's flange region (s below the
  /// flange split, see SplineFitOptions::flange_angle) minus the contact point's distance [m],
  /// capped at SplineFitOptions::clearance_cap. Continuous; <= 0 means the flange touches first:
  /// flange contact, the physical discontinuity the model keeps (the event function).
  kFieldFlangeClearance,
  kFieldSWheel,        ///< wheel profile coordinate of the contact point [m]
  kFieldSRail,         ///< rail profile coordinate of the contact point [m]
  kFieldWheelX,        ///< contact point on the wheel relative to the wheelset centre, track x [m]
  kFieldWheelY,        ///< the same, track y [m]
  kFieldWheelZ,        ///< the same, track z [m]
  kFieldRailZ,         ///< height of the rail surface at the contact point, at z = z_touch [m]
  kFieldContactAngle,  ///< contact angle [rad], > 0 when the normal force pushes towards the track centre
  kFieldRollingRadius, ///< rolling radius [m]
  kFieldNormalX,       ///< common normal, rail into wheel, track x [-] (renormalised after evaluation)
  kFieldNormalY,       ///< the same, track y [-]
  kFieldNormalZ,       ///< the same, track z [-]
  kFieldHertzA,        ///< Hertz relative curvature A, rolling direction [1/m]
  kFieldHertzB,        ///< Hertz relative curvature B, lateral, after the conformal-contact floor [1/m]
  kFieldMinorOverMajor,///< Hertz k' = min(a, b) / max(a, b) [-]
  kFieldEllipticK,     ///< complete elliptic integral K(e) of the Hertz ellipse [-]
  kFieldEllipticE,     ///< complete elliptic integral E(e) [-]
  kFieldHertzM,        ///< Hertz coefficient m of the rolling semi-axis a [-]
  kFieldHertzN,        ///< Hertz coefficient n of the lateral semi-axis b [-]
  kFieldWheelCurvatureLateral,  ///< wheel profile curvature [1/m], > 0 convex
  kFieldRailCurvatureLateral,   ///< rail profile curvature [1/m], > 0 convex
  // Fields below kSplineQueryFieldCount are what a contact query uses; the rest is reported only.
  kFieldTheta,         ///< angular position on the wheel from its lowest point [rad]
  kFieldWheelCurvatureRolling,  ///< wheel curvature in the rolling direction [1/m]
  kFieldRailCurvatureRolling,   ///< rail curvature along the track [1/m]
  kFieldDistanceCurvature,      ///< d2(distance)/ds2 along the curve C [1/m]
  kSplineFieldCount
};

/// The fields a contact query evaluates (the others complete ContactPoint for reports).
inline constexpr int kSplineQueryFieldCount = kFieldTheta;

/// The fitted quantity of each contact point field (core/geometry/contact_point_fields.hpp), in
/// ContactPointField order: the sample stores a point's fields there and the evaluation rebuilds
/// the point from them.
inline constexpr std::array<SplineField, kContactPointFieldCount> kSplineFieldOfPointField{{
    kFieldSWheel, kFieldSRail, kFieldTheta, kFieldWheelX, kFieldWheelY, kFieldWheelZ, kFieldRailZ,
    kFieldContactAngle, kFieldRollingRadius, kFieldNormalX, kFieldNormalY, kFieldNormalZ,
    kFieldWheelCurvatureLateral, kFieldWheelCurvatureRolling, kFieldRailCurvatureLateral,
    kFieldRailCurvatureRolling, kFieldDistanceCurvature,
}};

/// Name (as in the model file, the report and spline_model_t) and SI unit of a fitted quantity.
struct SplineFieldInfo {
  const char* name;
  const char* unit;
};

/// The names and units of every field, in SplineField order.
inline constexpr std::array<SplineFieldInfo, kSplineFieldCount> kSplineFields{{
    {"z", "m"},
    {"flange_clearance", "m"},
    {"s_wheel", "m"},
    {"s_rail", "m"},
    {"wheel_x", "m"},
    {"wheel_y", "m"},
    {"wheel_z", "m"},
    {"rail_z", "m"},
    {"contact_angle", "rad"},
    {"rolling_radius", "m"},
    {"normal_x", "-"},
    {"normal_y", "-"},
    {"normal_z", "-"},
    {"hertz_A", "1/m"},
    {"hertz_B", "1/m"},
    {"minor_over_major", "-"},
    {"elliptic_K", "-"},
    {"elliptic_E", "-"},
    {"hertz_m", "-"},
    {"hertz_n", "-"},
    {"wheel_curvature_lateral", "1/m"},
    {"rail_curvature_lateral", "1/m"},
    {"theta", "rad"},
    {"wheel_curvature_rolling", "1/m"},
    {"rail_curvature_rolling", "1/m"},
    {"distance_curvature", "1/m"},
}};

}  // namespace wrc
