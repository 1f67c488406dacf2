// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Detects a wheel whose flange has climbed onto or over its rail. The exact geometry still finds
/// a minimum of the distance then (the flange tip resting on the rail head), but no contact model
/// applies: the configuration is impossible for a wheel running on its rail.
///
/// Rule: the common point lies on the flange beyond its steepest point (towards the flange tip)
/// AND its contact angle has dropped below kFlangeClimbAngle = 20 deg. Beyond the steepest flange
/// point the contact angle falls as the flange climbs; at 20 deg Nadal's limit
/// (tan(d) - mu) / (1 + mu tan(d)) is 0.06 for mu = 0.3, i.e. the wheel is derailing. Ordinary
/// flange contact (S1002/UIC60 up to y = 10 mm: 46 deg and more) is not affected.
/// The models also reject a contact on or beyond the flange apex (WheelsetGeometry::beyond_flange_apex()).

#include "core/geometry/contact_point.hpp"
#include "core/geometry/wheelset_pose.hpp"
#include "core/profile/profile.hpp"

namespace wrc {

/// Contact angle below which a contact beyond the steepest flange point counts as climbed [rad].
inline constexpr double kFlangeClimbAngle = 0.3490658503988659;  // 20 deg

/// The wheel profile coordinate of the steepest flange point [m]: the s <= 0 where the profile
/// rises fastest towards the flange (largest -F'(s)), sampled every 10 um. For a profile without a
/// flange (a cone, constant slope) this is the lower end of the profile.
double steepest_flange_point(const Profile& wheel);

/// Throws ContactConfigurationError naming the wheel, s, the contact angle and the pose when
/// point.s < steepest and point.contact_angle < kFlangeClimbAngle.
void check_flange_not_climbed(const ContactPoint& point, double steepest, const WheelsetPose& pose);

}  // namespace wrc
