// SPDX-License-Identifier: Apache-2.0
#include "protocol/geometry/track_codec.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/geometry/track_table.hpp"
#include "core/identity/geometry_key.hpp"
#include "protocol/message_fields.hpp"

namespace wrc::protocol {
namespace {

// The field of each track_parameter_table() key (the inclination is track_t's rail_inclination).
const std::vector<MessageField<track_t>>& track_fields() {
  static const std::vector<MessageField<track_t>> fields{
      WRC_MESSAGE_FIELD(track_t, gauge),
      WRC_MESSAGE_FIELD(track_t, gauge_depth),
      WRC_MESSAGE_FIELD(track_t, flange_back_spacing),
      WRC_MESSAGE_FIELD(track_t, taping_line_offset),
      message_field("inclination", &track_t::rail_inclination),
      WRC_MESSAGE_FIELD(track_t, nominal_radius),
  };
  return fields;
}

}  // namespace

track_t to_message(const GeometrySpec& spec) {
  track_t t;
  t.wheel_profile.name = spec.wheel;
  t.wheel_profile.content_hash = profile_content_hash(spec.wheel);
  t.rail_profile.name = spec.rail;
  t.rail_profile.content_hash = profile_content_hash(spec.rail);
  t.rail_cant = spec.rail_cant ? *spec.rail_cant : std::numeric_limits<double>::quiet_NaN();
  to_message_fields(track_parameter_table(), spec.track, track_fields(), t);
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
  from_message_fields(track_parameter_table(), t, track_fields(), spec.track);
  spec.track.validate();  // the rule between the members
  for (const profile_ref_t* ref : {&t.wheel_profile, &t.rail_profile}) {
    if (!ref->content_hash.empty() && ref->content_hash != profile_content_hash(ref->name))
      throw std::invalid_argument("track_t: the content of profile '" + ref->name +
                                  "' here differs from the sender's (content_hash " + ref->content_hash + ")");
  }
  return spec;
}
}  // namespace wrc::protocol
