// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The design geometry of the track along the distance travelled (docs/track.md): straights,
/// circular curves with cant, and transition curves between them (a clothoid: the curvature
/// linear in the distance, with a linear cant ramp). What the wheelset's equations need of it at
/// the distance s the wheelset has travelled is a TrackPoint: the curvature of the centre line and
/// the cant angle, and their rates along s. The rails are fixed in the track frame, so the contact
/// geometry, and every contact model, stays in track coordinates.
///
/// Signs (docs/conventions.md): curvature > 0 for a curve to the left (its centre at +y); cant
/// angle is the track frame's roll, > 0 raising the left rail, so the usual cant of a left-hand
/// curve (the outer, right rail raised) is a negative angle.

#include <string>
#include <vector>

namespace wrc {

/// The track at one distance along it.
struct TrackPoint {
  double curvature = 0;       ///< kappa = 1 / R of the centre line, > 0 turning left [1/m]
  double curvature_rate = 0;  ///< d kappa / d s [1/m^2]
  double cant_angle = 0;      ///< roll of the track frame, > 0 raising the left rail [rad]
  double cant_angle_rate = 0; ///< d(cant angle) / d s [rad/m]
  /// On straight, level track (every member 0): the equations reduce to those of straight track
  /// bit for bit.
  bool straight() const {
    return curvature == 0.0 && curvature_rate == 0.0 && cant_angle == 0.0 && cant_angle_rate == 0.0;
  }
};

/// What a piece of the layout is.
enum class TrackSegmentKind { kStraight, kTransition, kCurve };

/// Every kind, in the order of the enum.
inline constexpr TrackSegmentKind kTrackSegmentKinds[] = {TrackSegmentKind::kStraight, TrackSegmentKind::kTransition,
                                                           TrackSegmentKind::kCurve};

/// The kind's name in layout files and messages: "straight", "transition", "curve".
constexpr const char* track_segment_kind_name(TrackSegmentKind kind) {
  return kind == TrackSegmentKind::kStraight ? "straight" : kind == TrackSegmentKind::kCurve ? "curve" : "transition";
}

/// One piece of the layout. A transition takes its start from the end of the piece before it (a
/// straight at the start of the layout) and its end from the piece after it, and runs the
/// curvature and the cant linearly in between.
struct TrackSegment {
  TrackSegmentKind kind = TrackSegmentKind::kStraight;
  double length = 0;  ///< [m], > 0
  double radius = 0;  ///< curve: radius of the centre line [m], > 0 (straight, transition: unused)
  bool left = true;   ///< curve: turning left (+y side), else right
  double cant = 0;    ///< curve: rise of the outer rail over the cant base [m] (negative: the inner
                      ///< rail raised)
};

/// Largest |cant| of a curve [m]: a little above the 0.2 m that main lines allow at most.
inline constexpr double kMaxCant = 0.25;
/// Smallest curve radius [m]: tighter curves are tram or yard track, beyond this wheelset's box.
inline constexpr double kMinCurveRadius = 50.0;

/// A track layout: segments one after another from s = 0. Past the last segment the track keeps
/// its end state (a straight goes on straight, a curve goes on curving).
class TrackLayout {
 public:
  /// Straight, level track.
  TrackLayout() = default;
  /// @param cant_base lateral distance the cant is measured over [m] (1.5 m for standard gauge).
  /// @throws std::invalid_argument naming the first bad segment and value.
  TrackLayout(std::vector<TrackSegment> segments, double cant_base = 1.5);

  const std::vector<TrackSegment>& segments() const { return segments_; }
  double cant_base() const { return cant_base_; }
  /// Total length of the segments [m].
  double length() const { return ends_.empty() ? 0.0 : ends_.back(); }
  bool straight() const { return segments_.empty(); }

  /// The track at distance s [m] from the start (s < 0: as at 0).
  TrackPoint at(double s) const;

  /// The speed at which a curve's cant balances the centrifugal acceleration,
  /// sqrt(g tan|cant angle| / |kappa|) [m/s] (0 for an uncanted curve); g [m/s^2].
  static double balanced_speed(const TrackSegment& curve, double cant_base, double g);
  /// Cant deficiency of a curve at speed V [m/s]: the cant that would balance V minus the cant
  /// there is, over the cant base, base * (V^2 |kappa| / g) - cant (> 0: the flange side carries the
  /// excess) [m].
  static double cant_deficiency(const TrackSegment& curve, double cant_base, double speed, double g);

 private:
  // Curvature and cant angle at the end of each segment (a transition's from its neighbours).
  struct State {
    double curvature = 0;
    double cant_angle = 0;
  };
  State curve_state(const TrackSegment& curve) const;

  std::vector<TrackSegment> segments_;
  double cant_base_ = 1.5;
  std::vector<double> ends_;   // [m] distance at the end of each segment
  std::vector<State> starts_;  // state at the start of each segment
  std::vector<State> finishes_;  // state at the end of each segment
};

}  // namespace wrc
