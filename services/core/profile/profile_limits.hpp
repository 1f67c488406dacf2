// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The limits a profile file must respect to be read: its size, the magnitude of each value and
/// the shape a wheel or rail profile can have. The one place of these numbers; each says why.
/// Checked by read_profile_file_bytes() (size, file kind), validate_profile_points() (magnitude)
/// and check_profile_plausibility() (shape).

#include <cstddef>

namespace wrc {

/// Largest profile file read [bytes]. A measured MiniProf or SIMPACK profile holds a few hundred to
/// a few thousand points (under 100 kB); 4 MiB leaves room for 100 000 points and bounds the memory
/// a wrong path (a log, an image) can take.
inline constexpr std::size_t kMaxProfileFileBytes = 4u << 20;

/// Largest magnitude of any profile coordinate, lateral or height [m]. Wheel and rail profiles
/// span about 0.15 m around their reference point; 1 m is far beyond any and still catches an
/// absurd value (1e300) at its line.
inline constexpr double kMaxProfileCoordinate = 1.0;

/// Narrowest profile (last minus first lateral coordinate) [m]. A contact patch is about 10 mm
/// wide, so a profile narrower than 5 mm cannot carry one; a 140 mm wheel whose length unit is off
/// by 1000 (0.14 mm) fails by a factor of 35.
inline constexpr double kMinProfileWidth = 5e-3;

/// Widest profile [m]. A wheel rim with its flange is at most about 150 mm wide, a whole rail
/// section (foot) 150 mm; 0.3 m is twice that, and a profile in mm read as metres fails.
inline constexpr double kMaxProfileWidth = 0.3;

/// Largest height range (highest minus lowest point) of a wheel profile [m]: the flange (at most
/// kMaxFlangeHeight above the taping line) plus the tread's fall and chamfer towards the field side
/// (about 15 mm).
inline constexpr double kMaxWheelHeightRange = 0.06;

/// Largest height range of a rail profile [m]: a whole rail section is at most 0.19 m tall (UIC60:
/// 172 mm); a head profile spans a few tens of millimetres.
inline constexpr double kMaxRailHeightRange = 0.2;

/// Highest flange of a wheel profile above its taping line (s = 0) [m]. New standard flanges are
/// 28 mm (S1002) to 32 mm; worn flanges grow to about 36 mm before the wheel is turned (UIC limit
/// 36 mm); 40 mm leaves a margin.
inline constexpr double kMaxFlangeHeight = 0.04;

/// Largest mean slope (least-squares line through the points) of a wheel profile [-]. A wheel
/// rises towards its flange (s < 0): the mean slope is negative (a 1:40 cone -0.025, S1002 with its
/// flange lower still), 0 for a cylinder. A positive one means the profile is upside down or
/// mirrored, which gives negative contact angles; 0.01 admits a cylindrical tread measured with a
/// slight tilt.
inline constexpr double kMaxWheelMeanSlope = 0.01;

/// How far a rail profile may lie below the chord between its end points on average [m]. A rail
/// head is convex (its crown above the chord); one below it is upside down. 0.1 mm admits a nearly
/// flat, noisy head.
inline constexpr double kMaxRailSagBelowChord = 1e-4;

/// A spike: one point standing out from both neighbours, in the same direction, by more than
/// kMinSpikeHeight [m] with both adjacent segments steeper than kMinSpikeSlope [-] (84 degrees).
/// The steepest real profile faces (a flange flank, a gauge face) are about 75 degrees (slope 3.7)
/// and never rise and fall again within one point spacing; a flange tip is rounded over millimetres.
inline constexpr double kMinSpikeHeight = 0.5e-3;
inline constexpr double kMinSpikeSlope = 10.0;

}  // namespace wrc
