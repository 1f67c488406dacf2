// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The ranges of the pose options every command shares (--y, --y-from, --y-to, the bifurcation's
/// disturbances; --yaw), in one place: the geometry's limits (core/geometry/wheelset_geometry.hpp).

#include "cli/options.hpp"
#include "core/geometry/wheelset_geometry.hpp"

namespace wrc::cli {

/// Lateral shift [m]: +-kMaxGeometryLateralShift.
inline constexpr NumberRange kLateralShiftRange{-kMaxGeometryLateralShift, kMaxGeometryLateralShift};
/// Yaw angle [rad]: +-kMaxValidatedYaw, where the common-point search is validated.
inline constexpr NumberRange kYawRange{-kMaxValidatedYaw, kMaxValidatedYaw};

}  // namespace wrc::cli
