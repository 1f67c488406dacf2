#include "protocol/geometry/track_codec.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/identity/geometry_key.hpp"

namespace wrc::protocol {

track_t to_message(const GeometrySpec& spec) {
  track_t t;
  t.wheel_profile.name = spec.wheel;
  t.wheel_profile.content_hash = profile_content_hash(spec.wheel);
  t.rail_profile.name = spec.rail;
  t.rail_profile.content_hash = profile_content_hash(spec.rail);
  t.rail_cant = spec.rail_cant ? *spec.rail_cant : std::numeric_limits<double>::quiet_NaN();
  t.gauge = spec.track.gauge;
  t.gauge_depth = spec.track.gauge_depth;
  t.flange_back_spacing = spec.track.flange_back_spacing;
  t.taping_line_offset = spec.track.taping_line_offset;
  t.rail_inclination = spec.track.inclination;
  t.nominal_radius = spec.track.nominal_radius;
  return t;
}

GeometrySpec from_message(const track_t& t) {
  GeometrySpec spec;
  spec.wheel = t.wheel_profile.name;
  spec.rail = t.rail_profile.name;
  if (!std::isnan(t.rail_cant)) {
    if (!std::isfinite(t.rail_cant)) throw std::invalid_argument("track_t: rail_cant is infinite");
    spec.rail_cant = t.rail_cant;
  }
  spec.track.gauge = t.gauge;
  spec.track.gauge_depth = t.gauge_depth;
  spec.track.flange_back_spacing = t.flange_back_spacing;
  spec.track.taping_line_offset = t.taping_line_offset;
  spec.track.inclination = t.rail_inclination;
  spec.track.nominal_radius = t.nominal_radius;
  spec.track.validate();
  for (const profile_ref_t* ref : {&t.wheel_profile, &t.rail_profile}) {
    if (!ref->content_hash.empty() && ref->content_hash != profile_content_hash(ref->name))
      throw std::invalid_argument("track_t: the content of profile '" + ref->name +
                                  "' here differs from the sender's (content_hash " + ref->content_hash + ")");
  }
  return spec;
}
}  // namespace wrc::protocol
