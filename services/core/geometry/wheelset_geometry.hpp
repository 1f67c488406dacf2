// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A wheel profile and a rail profile placed on a track: the exact contact geometry of both
/// wheels of a rigid wheelset for any pose.

#include <optional>
#include <vector>

#include "core/geometry/contact_locus.hpp"
#include "core/geometry/contact_point.hpp"
#include "core/geometry/placed_rail.hpp"
#include "core/geometry/potential_points.hpp"
#include "core/geometry/slope_envelope.hpp"
#include "core/geometry/track.hpp"
#include "core/profile/profile.hpp"

namespace wrc {

/// Largest |yaw| [rad] for which the common-point search is validated: against a 5 um sampling
/// of the distance over y +-12 mm and roll +-20 mrad it finds the lowest point up to 60 mrad; from
/// 70 mrad on (a wheelset yawed by 4 degrees) the wheel point's lateral position varies so much
/// along the flange that the rail edges can be misplaced. Contact models reject larger yaw.
constexpr double kMaxValidatedYaw = 0.06;

/// Largest |lateral shift| [m] a geometry command (--y, --y-from, --y-to) or a spline box may ask
/// for: 50 mm, far beyond flange contact of any standard wheelset (S1002 on UIC60 climbs from
/// about 7 mm on) and inside the profiles' domains. (A contact query accepts any wheelset on a
/// track, up to kMaxLateralShift = 0.5 m of query_validation.hpp, and lets the model say whether
/// it touches.)
constexpr double kMaxGeometryLateralShift = 0.05;

/// Wheelset on track: the same wheel profile on both wheels (mirrored for the right wheel) and the
/// same rail profile on both rails (mirrored for the right rail).
class WheelsetGeometry {
 public:
  /// Throws std::invalid_argument for a wheel given as rail (or vice versa) or invalid track values.
  WheelsetGeometry(ProfilePtr wheel, ProfilePtr rail, const TrackParameters& track = {});

  /// The curve C of one wheel at pose.
  ContactLocus locus(WheelSide side, const WheelsetPose& pose) const;

  /// Every potential common point of one wheel at pose, ordered by s.
  std::vector<ContactPoint> potential_points(WheelSide side, const WheelsetPose& pose,
                                             const PotentialPointSearch& search = {}) const;

  /// The common point of one wheel at pose (nothing when the wheel is off the rail). Same result
  /// as select_common_point(potential_points(...)), found without listing the other points.
  std::optional<ContactPoint> common_point(WheelSide side, const WheelsetPose& pose,
                                           const PotentialPointSearch& search = {}) const;

  /// True when a contact point lies on or beyond the flange apex (the highest point of F on the
  /// flange side, s <= 0; towards the flange back): the flange has climbed onto the rail, a
  /// derailed configuration no contact model represents.
  bool beyond_flange_apex(const ContactPoint& point) const { return point.s <= flange_apex_ + 1e-6; }

  const PlacedRail& rail(WheelSide side) const { return side == WheelSide::kLeft ? left_rail_ : right_rail_; }
  const Profile& wheel_profile() const { return *wheel_; }
  const TrackParameters& track() const { return track_; }

 private:
  static ProfilePtr checked_wheel(ProfilePtr wheel);
  ProfilePtr wheel_;
  TrackParameters track_;
  PlacedRail left_rail_;
  PlacedRail right_rail_;
  SlopeEnvelope wheel_envelope_;  // bounds of |F'|, |F''| for the scan's step control
  double flange_apex_ = 0;  // wheel profile coordinate of the flange apex [m]
};

}  // namespace wrc
