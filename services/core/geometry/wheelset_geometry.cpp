#include "core/geometry/wheelset_geometry.hpp"

#include <stdexcept>

namespace wrc {

ProfilePtr WheelsetGeometry::checked_wheel(ProfilePtr wheel) {
  if (!wheel) throw std::invalid_argument("no wheel profile");
  if (wheel->side() != ProfileSide::kWheel)
    throw std::invalid_argument("profile '" + wheel->name() + "' is a rail profile, a wheel profile is needed");
  return wheel;
}

WheelsetGeometry::WheelsetGeometry(ProfilePtr wheel, ProfilePtr rail, const TrackParameters& track)
    : wheel_(checked_wheel(std::move(wheel))), rail_(rail), track_(track),
      left_rail_(rail, track, WheelSide::kLeft), right_rail_(rail, track, WheelSide::kRight) {}

ContactLocus WheelsetGeometry::locus(WheelSide side, const WheelsetPose& pose) const {
  return ContactLocus(*wheel_, rail(side), track_, side, pose);
}

std::vector<ContactPoint> WheelsetGeometry::potential_points(WheelSide side, const WheelsetPose& pose,
                                                             const PotentialPointSearch& search) const {
  return find_potential_points(locus(side, pose), search);
}

std::optional<ContactPoint> WheelsetGeometry::common_point(WheelSide side, const WheelsetPose& pose,
                                                           const PotentialPointSearch& search) const {
  return select_common_point(potential_points(side, pose, search));
}

}  // namespace wrc
