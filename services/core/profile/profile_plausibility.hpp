// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Checks that profile points describe a wheel or rail profile that can exist (size, height,
/// flange, orientation, no spike), against the limits of profile_limits.hpp.

#include "core/profile/profile.hpp"
#include "core/profile/profile_points.hpp"

namespace wrc {

/// Checks points (ordered by increasing lateral coordinate, as validate_profile_points() returns
/// them) of a profile of the given side: width in [kMinProfileWidth, kMaxProfileWidth]; height
/// range at most kMaxWheelHeightRange or kMaxRailHeightRange; a wheel's flange at most
/// kMaxFlangeHeight above the taping line and its mean slope at most kMaxWheelMeanSlope; a rail not
/// more than kMaxRailSagBelowChord below its end chord; no spike (kMinSpikeHeight, kMinSpikeSlope).
/// @throws ProfileError "<file>: <reason>" naming the value and the limit (with the line of a
///         spike).
void check_profile_plausibility(const ProfilePoints& points, ProfileSide side);

}  // namespace wrc
