// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The linear steady-curving theory of a two-axle bogie (after Boocock and Wickens; derived in
/// docs/bogie-curving.md): a frame and two wheelsets in a curve of constant curvature 1/R with
/// linear creep, conicity and primary (and optional secondary) springs; the six steady
/// displacements from one linear system K q = F. It is the reference the vehicle equations' curving
/// will be tested against (issue 29).
///
/// Frames and signs (docs/conventions.md): x forward, y to the left, z up; yaw > 0 counter-
/// clockwise seen from above. The frame's centre is at the track centre line's point x = 0; the
/// leading wheelset (index 0 here, "1" in the doc) at x = +a, the trailing one (index 1, "2" in
/// the doc) at x = -a. The frame's lateral shift and yaw are measured from the track centre line
/// and tangent at x = 0; each wheelset's from the track centre line and tangent at its own x, so a
/// wheelset's yaw is its angle of attack. In a curve to the left (curvature > 0) and without
/// lateral loads the wheelsets run to the right of the centre line (y < 0, towards the outer rail)
/// and the leading one has yaw < 0 (it points towards the outer rail); the textbooks' y, measured
/// outwards, has the other sign.

#include <array>

namespace wrc {

/// The bogie, its contact and the curve. "Per wheel" and "per axle box" values are those of one
/// wheel or one box (two per wheelset); the secondary stiffnesses are the totals of the bogie.
struct BogieCurvingParameters {
  // The curve and the loads
  /// Track curvature 1/R [1/m]: > 0 curves to the left (the centre on the +y side), < 0 to the
  /// right, 0 on straight track.
  double curvature = 0;
  /// Uncompensated lateral acceleration a_y along +y in the track plane [m/s^2]: every body
  /// carries its mass times a_y. Cant deficiency theta_d [rad] in a curve to the left gives
  /// a_y = -g theta_d (outwards); see lateral_acceleration_of_cant_deficiency().
  double lateral_acceleration = 0;
  double frame_lateral_force = 0;     ///< F_f along +y on the frame besides m_f a_y [N] (e.g. a car body's share)
  double wheelset_lateral_force = 0;  ///< F_w along +y on each wheelset besides m_w a_y [N]

  // The bodies
  double frame_mass = 0;      ///< m_f [kg], > 0
  double wheelset_mass = 0;   ///< m_w of one wheelset [kg], > 0
  double semi_wheelbase = 0;  ///< a: the wheelsets at x = +a and -a from the frame's centre [m], > 0

  // Wheel-rail geometry and linear creep
  double conicity = 0;               ///< lambda = (r_left - r_right) / (2 y) [-], > 0
  double rolling_radius = 0;         ///< r0: centred rolling radius [m], > 0
  double contact_half_distance = 0;  ///< b0: half the lateral distance of the contact points [m], > 0
  double f11 = 0;                    ///< Kalker's longitudinal creep coefficient per wheel, G c^2 C11 [N], > 0
  double f22 = 0;                    ///< Kalker's lateral creep coefficient per wheel, G c^2 C22 [N], > 0
  /// Optional: gravitational lateral stiffness of one wheelset (the lateral components of the
  /// normal forces restoring a shifted wheelset) [N/m], >= 0; 0 leaves it out.
  double gravitational_lateral_stiffness = 0;
  /// Optional: lateral-spin creep coefficient per wheel, G c^3 C23 [N m], >= 0; 0 leaves spin out.
  double f23 = 0;
  /// Optional: spin creep coefficient per wheel, G c^4 C33 [N m^2], >= 0.
  double f33 = 0;
  /// Optional: d/dy of half the difference of the wheels' contact angles relative to the axle,
  /// (gamma_left - gamma_right) / 2 [rad/m]; the y-dependent part of the geometric spin. 0 for a
  /// conic tread; used only with f23 or f33.
  double contact_angle_slope = 0;

  // Primary suspension, per axle box (two per wheelset)
  double primary_longitudinal_stiffness = 0;  ///< k_x per axle box [N/m], >= 0
  double primary_lateral_stiffness = 0;       ///< k_y per axle box [N/m], >= 0
  /// b1: lateral semi-spacing of the longitudinal springs [m], > 0; a wheelset's primary yaw
  /// stiffness is 2 k_x b1^2.
  double primary_semi_spacing = 0;

  // Optional secondary suspension: frame to a body that follows the track
  double secondary_lateral_stiffness = 0;  ///< k_sy, total of the bogie [N/m], >= 0
  double secondary_yaw_stiffness = 0;      ///< k_spsi, total of the bogie [N m/rad], >= 0
  /// That body's lateral position at the frame's centre, from the track centre line there [m]
  /// (0: it follows the track, as does a car body whose centre line passes over the pivot).
  double body_lateral_offset = 0;
  /// That body's yaw from the track tangent at the frame's centre [rad] (0: it follows the track;
  /// a car body on pivots at +-L: -+L / R at the front (upper) and rear bogie).
  double body_yaw = 0;

  /// @throws std::invalid_argument naming the first field (and its value) that is not finite or
  ///         out of its range above, or the stiffnesses that leave the frame unrestrained (no
  ///         primary lateral stiffness and either no secondary lateral stiffness or no yaw
  ///         restraint at all: K is singular then).
  void validate() const;
};

/// One wheelset's steady state.
struct WheelsetCurvingState {
  double lateral = 0;  ///< y_i: shift from the track centre line at the wheelset's x [m]
  double yaw = 0;      ///< psi_i: yaw from the local track tangent [rad]
  /// The angle of attack as the project reports it: the yaw from the local tangent [rad].
  double angle_of_attack() const { return yaw; }

  double longitudinal_creepage_left = 0;  ///< xi_x of the left wheel [-]; the right one's is its negative
  double lateral_creepage = 0;            ///< xi_y of either wheel, -psi_i [-]
  double spin_creepage_left = 0;          ///< phi of the left wheel without its constant -gamma0/r0 [1/m]
  double spin_creepage_right = 0;         ///< phi of the right wheel without its constant +gamma0/r0 [1/m]
  /// -f11 xi_x on the left wheel [N]; the right wheel's is its negative, so the pair is a moment.
  double longitudinal_creep_force_left = 0;
  double lateral_creep_force = 0;  ///< both wheels' creep forces along +y, spin part included [N]
  double creep_yaw_moment = 0;     ///< both wheels' creep moment about +z at the wheelset's centre [N m]
  double gravitational_force = 0;  ///< -k_g y_i along +y [N]
  double primary_lateral_deflection = 0;  ///< wheelset minus frame at the axle boxes, along y [m]
  double primary_yaw_deflection = 0;      ///< wheelset minus frame yaw [rad]
  double primary_lateral_force = 0;       ///< on the wheelset from its two boxes, along +y [N]
  double primary_yaw_moment = 0;          ///< on the wheelset from its two boxes, about +z [N m]
};

/// The solved steady state.
struct BogieCurvingResult {
  double frame_lateral = 0;  ///< y_f: frame centre from the track centre line at x = 0 [m]
  double frame_yaw = 0;      ///< psi_f: frame from the track tangent at x = 0 [rad]
  /// [0] the leading wheelset (x = +a), [1] the trailing one (x = -a).
  std::array<WheelsetCurvingState, 2> wheelsets{};
  double secondary_lateral_force = 0;  ///< on the frame along +y [N]
  double secondary_yaw_moment = 0;     ///< on the frame about +z [N m]
  /// The pure rolling line -r0 b0 / (lambda R) [m]: a free wheelset's shift without creep, the
  /// scale of the lateral results.
  double pure_rolling_lateral = 0;
  /// The six balances recomputed from the forces above: the largest of |sum of the forces (or
  /// moments) on a body| over that sum's largest term [-]; rounding only.
  double relative_residual = 0;
};

/// Assembles and solves the six balances K q = F of docs/bogie-curving.md, q = (y_f, psi_f, y_1,
/// psi_1, y_2, psi_2).
/// @throws std::invalid_argument from parameters.validate(), or naming f23 and
///         contact_angle_slope when the optional spin terms make K singular.
BogieCurvingResult bogie_steady_curving(const BogieCurvingParameters& parameters);

/// a_y of a cant deficiency theta_d [rad] (> 0 above the balance speed) in a curve of curvature
/// 1/R [1/m]: -sign(1/R) g theta_d [m/s^2], outwards; 0 on straight track.
/// @param gravity g [m/s^2]
double lateral_acceleration_of_cant_deficiency(double cant_deficiency, double curvature, double gravity = 9.81);

}  // namespace wrc
