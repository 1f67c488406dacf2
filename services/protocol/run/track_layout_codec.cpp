// SPDX-License-Identifier: Apache-2.0
#include "protocol/run/track_layout_codec.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace wrc::protocol {

void to_layout_fields(const TrackLayout& layout, run_command_t& m) {
  m.layout_cant_base = layout.cant_base();
  m.num_layout_segments = static_cast<std::int32_t>(layout.segments().size());
  m.layout_segments.clear();
  for (const TrackSegment& s : layout.segments()) {
    track_segment_t t{};
    t.kind = s.kind == TrackSegmentKind::kStraight     ? track_segment_t::STRAIGHT
             : s.kind == TrackSegmentKind::kTransition ? track_segment_t::TRANSITION
                                                       : track_segment_t::CURVE;
    t.length = s.length;
    t.radius = s.kind == TrackSegmentKind::kCurve ? s.radius : 0.0;
    t.left = s.left;
    t.cant = s.kind == TrackSegmentKind::kCurve ? s.cant : 0.0;
    m.layout_segments.push_back(t);
  }
}

TrackLayout layout_from_fields(const run_command_t& m) {
  const std::string count = "num_layout_segments = " + std::to_string(m.num_layout_segments);
  if (m.num_layout_segments < 0) throw std::invalid_argument(count + " is negative");
  if (static_cast<std::size_t>(m.num_layout_segments) > kMaxLayoutSegments)
    throw std::invalid_argument(count + " is more than the limit of " + std::to_string(kMaxLayoutSegments) +
                                " layout segments");
  if (static_cast<std::size_t>(m.num_layout_segments) != m.layout_segments.size())
    throw std::invalid_argument(count + " does not match the " + std::to_string(m.layout_segments.size()) +
                                " segments of the list");
  if (m.layout_segments.empty()) return TrackLayout();
  std::vector<TrackSegment> segments;
  for (std::size_t k = 0; k < m.layout_segments.size(); ++k) {
    const track_segment_t& t = m.layout_segments[k];
    TrackSegment s;
    switch (t.kind) {
      case track_segment_t::STRAIGHT: s.kind = TrackSegmentKind::kStraight; break;
      case track_segment_t::TRANSITION: s.kind = TrackSegmentKind::kTransition; break;
      case track_segment_t::CURVE: s.kind = TrackSegmentKind::kCurve; break;
      default:
        throw std::invalid_argument("layout_segments[" + std::to_string(k) + "].kind = " + std::to_string(t.kind) +
                                    " is not STRAIGHT, TRANSITION or CURVE");
    }
    s.length = t.length;
    s.radius = t.radius;
    s.left = t.left;
    s.cant = t.cant;
    segments.push_back(s);
  }
  try {
    return TrackLayout(std::move(segments), m.layout_cant_base);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("layout: ") + e.what());
  }
}

}  // namespace wrc::protocol
