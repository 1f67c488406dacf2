// SPDX-License-Identifier: Apache-2.0
#include "core/track/track_layout.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/numerics/number_text.hpp"

namespace wrc {
namespace {

std::string segment_name(std::size_t k, const TrackSegment& s) {
  return "segment " + std::to_string(k + 1) + " (" + track_segment_kind_name(s.kind) + ")";
}

}  // namespace

TrackLayout::TrackLayout(std::vector<TrackSegment> segments, double cant_base)
    : segments_(std::move(segments)), cant_base_(cant_base) {
  if (!(cant_base_ >= 1.0 && cant_base_ <= 2.0))
    throw std::invalid_argument("cant base " + number_text(cant_base_, 9) + " m is outside [1, 2] m");
  for (std::size_t k = 0; k < segments_.size(); ++k) {
    const TrackSegment& s = segments_[k];
    const std::string name = segment_name(k, s);
    if (!(s.length > 0.0 && s.length <= 1e6))
      throw std::invalid_argument(name + ": length " + number_text(s.length, 9) + " m is outside (0, 1e6] m");
    if (s.kind != TrackSegmentKind::kCurve) continue;
    if (!(s.radius >= kMinCurveRadius && s.radius <= 1e6))
      throw std::invalid_argument(name + ": radius " + number_text(s.radius, 9) + " m is outside [" +
                                  number_text(kMinCurveRadius, 9) + ", 1e6] m");
    if (!(std::abs(s.cant) <= kMaxCant))
      throw std::invalid_argument(name + ": cant " + number_text(s.cant, 9) + " m is outside [-" +
                                  number_text(kMaxCant, 9) + ", " + number_text(kMaxCant, 9) + "] m");
  }
  // Each piece's start and end state; a transition ramps from the end of the piece before it to
  // the state of the piece after it (a straight where there is none).
  double s = 0.0;
  State previous;
  for (std::size_t k = 0; k < segments_.size(); ++k) {
    const TrackSegment& seg = segments_[k];
    State start = previous;
    State finish;
    if (seg.kind == TrackSegmentKind::kCurve) {
      start = finish = curve_state(seg);
      if (k > 0 && segments_[k - 1].kind != TrackSegmentKind::kTransition &&
          (previous.curvature != start.curvature || previous.cant_angle != start.cant_angle))
        throw std::invalid_argument(segment_name(k, seg) + " follows a segment of another curvature or cant without a " +
                                    "transition between them");
    } else if (seg.kind == TrackSegmentKind::kTransition) {
      if (k + 1 < segments_.size() && segments_[k + 1].kind == TrackSegmentKind::kCurve)
        finish = curve_state(segments_[k + 1]);
    } else if (previous.curvature != 0.0 || previous.cant_angle != 0.0) {
      throw std::invalid_argument(segment_name(k, seg) + " follows a curve without a transition between them");
    }
    if (seg.kind == TrackSegmentKind::kTransition && k + 1 < segments_.size() &&
        segments_[k + 1].kind == TrackSegmentKind::kTransition)
      throw std::invalid_argument(segment_name(k, seg) + " is followed by another transition");
    s += seg.length;
    ends_.push_back(s);
    starts_.push_back(start);
    finishes_.push_back(finish);
    previous = finish;
  }
}

TrackLayout::State TrackLayout::curve_state(const TrackSegment& curve) const {
  const double direction = curve.left ? 1.0 : -1.0;
  // The outer rail is the right one in a left-hand curve: raising it rolls the track frame
  // negatively (roll > 0 raises the left rail).
  return {direction / curve.radius, -direction * std::asin(curve.cant / cant_base_)};
}

TrackPoint TrackLayout::at(double s) const {
  TrackPoint p;
  if (segments_.empty()) return p;
  if (s >= ends_.back()) {  // past the end: the end state goes on
    p.curvature = finishes_.back().curvature;
    p.cant_angle = finishes_.back().cant_angle;
    return p;
  }
  const std::size_t k = static_cast<std::size_t>(std::upper_bound(ends_.begin(), ends_.end(), s) - ends_.begin());
  const TrackSegment& seg = segments_[k];
  const State& a = starts_[k];
  const State& b = finishes_[k];
  if (seg.kind != TrackSegmentKind::kTransition) {
    p.curvature = a.curvature;
    p.cant_angle = a.cant_angle;
    return p;
  }
  const double begin = ends_[k] - seg.length;
  const double u = std::clamp((s - begin) / seg.length, 0.0, 1.0);
  p.curvature_rate = (b.curvature - a.curvature) / seg.length;
  p.cant_angle_rate = (b.cant_angle - a.cant_angle) / seg.length;
  p.curvature = a.curvature + u * (b.curvature - a.curvature);
  p.cant_angle = a.cant_angle + u * (b.cant_angle - a.cant_angle);
  return p;
}

double TrackLayout::balanced_speed(const TrackSegment& curve, double cant_base, double g) {
  const double angle = std::asin(std::abs(curve.cant) / cant_base);
  return curve.cant > 0.0 ? std::sqrt(g * std::tan(angle) * curve.radius) : 0.0;
}

double TrackLayout::cant_deficiency(const TrackSegment& curve, double cant_base, double speed, double g) {
  return cant_base * speed * speed / (g * curve.radius) - curve.cant;
}

}  // namespace wrc
