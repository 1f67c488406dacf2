// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A rail profile placed in the track frame: inclined, at its gauge position, top of rail at z = 0.

#include <vector>

#include "core/geometry/slope_envelope.hpp"
#include "core/geometry/track.hpp"
#include "core/geometry/wheel_side.hpp"
#include "core/profile/profile.hpp"

namespace wrc {

/// Rail surface height below one track lateral position.
struct RailSample {
  bool valid = false;  ///< false when the position is outside the rail's lateral extent
  double u = 0;        ///< rail profile coordinate of the surface point [m]
  double z = 0;        ///< surface height in the track frame [m]
  double slope = 0;    ///< dz/dy in the track frame [-]
  double d2 = 0;       ///< d2z/dy2 in the track frame [1/m]
};

/// One rail in the track frame. The profile (rail-local u outward, v up) is rotated by the
/// inclination not already built into the profile (rail top towards the track centre), shifted so
/// that its highest point lies at z = 0 and so that its innermost point within gauge_depth below
/// the top of rail lies at |y| = gauge / 2. The right rail is the mirror image (y -> -y).
/// The rail surface is then the graph z(y) over the lateral range where the inclined profile is a
/// function of y with |dz/dy| <= 6 (80.5 degrees): steeper faces and overhangs below them are cut
/// off, since no wheel flange (S1002: 70 degrees) can touch them.
class PlacedRail {
 public:
  /// Throws std::invalid_argument when the profile is not a rail, the track is invalid, or no
  /// gauge point exists within gauge_depth below the top of rail.
  PlacedRail(ProfilePtr rail, const TrackParameters& track, WheelSide side);

  /// Surface height and derivatives below track lateral position y [m].
  RailSample at(double y) const;

  /// Only the surface slope dz/dy below y [m] (one profile evaluation; what the potential-point
  /// scan needs). Returns false outside the rail's lateral extent.
  bool slope_at(double y, double& slope) const;
  /// Surface height [m] and slope below y [m], one profile evaluation; false off the rail.
  bool height_and_slope_at(double y, double& z, double& slope) const;

  /// Track-frame lateral position and height of rail profile coordinate u [m].
  void profile_to_track(double u, double& y, double& z) const;

  /// Lateral extent of the rail surface in the track frame [m] (lower < upper).
  double y_lower() const { return y_lower_; }
  double y_upper() const { return y_upper_; }
  /// Rail profile coordinate of the top of rail (highest point after inclination) [m].
  double u_top() const { return u_top_; }
  /// Lateral position of the rail profile origin (u = 0, v = 0) in the track frame [m].
  double axis_y() const { return side_sign_ * axis_; }
  /// Track-frame lateral position of the gauge point [m] (+-gauge/2).
  double gauge_point_y() const { return gauge_point_y_; }
  /// Effective rotation applied to the profile [rad] (inclination minus built-in cant).
  double rotation() const { return alpha_; }
  WheelSide side() const { return side_; }
  const Profile& profile() const { return *rail_; }
  /// Geometric curvature of the rail profile at u [1/m], positive where the head is convex.
  double curvature_at(double u) const;
  /// Bounds of |dz/dy| and |d2z/dy2| of the rail surface over track-y bins (step-size control).
  const SlopeEnvelope& envelope() const { return envelope_; }
  /// Track-frame lateral positions [m] where the surface's curvature may jump: the profile's
  /// breakpoints and the two edges of the surface (1e-9 m inside), in no particular order.
  const std::vector<double>& surface_breaks() const { return surface_breaks_; }

 private:
  double local_y(double u, double v) const { return axis_ + u * cos_ - v * sin_; }  // side-local |y|
  double local_z(double u, double v) const { return z0_ + u * sin_ + v * cos_; }
  double solve_u(double side_local_y) const;
  double hermite_u(double side_local_y) const;
  // Height [m] and dz/du [-] of the inclined profile at u before the shift to z = 0.
  double inclined_height(double u) const;
  double inclined_slope(double u) const;
  // Part of the rail surface graph at u: y(u) increasing and |dz/dy| <= 6.
  bool on_surface(double u) const;
  // The steps of the constructor, in order (lo, hi the profile's range, du its scan step [m]):
  // top of rail u_top_ (the highest point of the inclined profile) and z0_;
  void find_top_of_rail(double lo, double hi, double du);
  // u_lower_, u_upper_: the part of the profile over which y(u) increases (seen from above);
  void find_surface_range(double lo, double hi, double du);
  // axis_ and gauge_point_y_ from the gauge point;
  void place_gauge_point(const TrackParameters& track, double lo, double du);
  // the inverse table u(y) and the lateral extent y_lower_, y_upper_;
  void build_inverse_table();
  // envelope_ and surface_breaks_.
  void build_envelope_and_breaks();

  ProfilePtr rail_;
  WheelSide side_;
  double side_sign_;
  double alpha_, cos_, sin_;
  double axis_ = 0;  // side-local lateral position of the profile origin [m]
  double z0_ = 0;    // vertical offset that puts the top of rail at z = 0 [m]
  double u_top_ = 0;
  double u_lower_ = 0, u_upper_ = 0;  // profile range over which y(u) is monotone
  double y_lower_ = 0, y_upper_ = 0;
  double gauge_point_y_ = 0;
  SlopeEnvelope envelope_;
  std::vector<double> surface_breaks_;
  std::vector<double> table_u_;  // u at uniformly spaced side-local y
  std::vector<double> table_du_; // du/dy at the nodes times the node spacing
  double table_y0_ = 0, table_y_last_ = 0, table_dy_ = 1;  // side-local y of the first and last node, spacing
};

}  // namespace wrc
