// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The two wheels (and rails) of a wheelset.

namespace wrc {

/// Left (y > 0) or right (y < 0) wheel and rail.
enum class WheelSide { kLeft = 0, kRight = 1 };

/// +1 for the left side, -1 for the right: the sign of the track-frame y of that side.
inline double side_sign(WheelSide side) { return side == WheelSide::kLeft ? 1.0 : -1.0; }

/// "left" or "right".
inline const char* side_name(WheelSide side) { return side == WheelSide::kLeft ? "left" : "right"; }

}  // namespace wrc
