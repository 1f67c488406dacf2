// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// How far one rail lies from its place in the track frame at the wheelset's position along the
/// track: the rail offsets that track irregularities (alignment, vertical level, cross-level,
/// gauge; docs/track.md) put into a contact query, and how fast they change under the moving
/// wheelset.

namespace wrc {

/// Largest |lateral| and |vertical| offset of a rail [m] a query accepts: 50 mm is several times
/// the worst irregularity a maintained track keeps (EN 13848-5's immediate-action limits are
/// 12-35 mm for alignment, level and gauge).
inline constexpr double kMaxRailOffset = 0.05;
/// Largest |roll| of a rail [rad] (a cross-level of 50 mm over 1.5 m is 0.033 rad).
inline constexpr double kMaxRailRoll = 0.05;
/// Largest |rate| of a rail offset [m/s] or roll [rad/s] seen by a moving wheelset (slope times
/// speed: 0.01 at 1000 m/s).
inline constexpr double kMaxRailOffsetRate = 10.0;

/// One rail moved rigidly from its nominal place: rolled by roll about its pivot (the point of
/// the rail head at the wheel's taping line, y = +-taping_half_distance, z = 0), then shifted by
/// (lateral, vertical). The rail stays straight along x at the wheelset (its heading and pitch, the
/// slopes of an irregularity, below 1e-2 rad, are left out of the geometry: docs/track.md). The
/// rail material is at rest; the rates say how the rail's cross-section under the wheelset changes
/// as the wheelset travels (speed times the slope along the track).
struct RailOffset {
  double lateral = 0;        ///< shift along track y, > 0 to the left [m]
  double vertical = 0;       ///< shift along track z, > 0 up [m]
  double roll = 0;           ///< rotation about track x, > 0 as the track's roll (raises y > 0) [rad]
  double lateral_rate = 0;   ///< d lateral / dt under the moving wheelset [m/s]
  double vertical_rate = 0;  ///< d vertical / dt [m/s]
  double roll_rate = 0;      ///< d roll / dt [rad/s]

  /// True when the rail is in its nominal place and does not move (every field exactly 0).
  bool nominal() const {
    return lateral == 0.0 && vertical == 0.0 && roll == 0.0 && lateral_rate == 0.0 && vertical_rate == 0.0 &&
           roll_rate == 0.0;
  }
};

}  // namespace wrc
