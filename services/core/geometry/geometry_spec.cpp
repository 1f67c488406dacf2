// SPDX-License-Identifier: Apache-2.0
#include "core/geometry/geometry_spec.hpp"

#include "core/profile/profile_factory.hpp"

namespace wrc {

WheelsetGeometry make_geometry(const GeometrySpec& spec) {
  spec.track.validate();
  ProfileFileOptions rail_options;
  rail_options.built_in_cant = spec.rail_cant;
  return WheelsetGeometry(make_profile(spec.wheel, ProfileSide::kWheel),
                          make_profile(spec.rail, ProfileSide::kRail, rail_options), spec.track);
}

}  // namespace wrc
