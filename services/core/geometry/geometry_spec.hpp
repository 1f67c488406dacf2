// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The geometry input of wrc: wheel and rail profile, the cant built into the rail profile, and
/// the track. Everything a WheelsetGeometry is built from, so that equal specs (equal
/// identity/geometry_key.hpp keys) give the same geometry in every process. Messages carry it as
/// track_t (lcmtypes/track_t.lcm, same names), command lines as --wheel, --rail, --rail-cant and
/// the track options (identity/geometry_key.hpp: geometry_arguments).

#include <optional>
#include <string>

#include "core/geometry/track.hpp"
#include "core/geometry/wheelset_geometry.hpp"

namespace wrc {

/// Profiles and track of one geometry (defaults: S1002 on UIC60, standard track).
struct GeometrySpec {
  std::string wheel = "S1002";  ///< wheel profile spec of core/profile/profile_factory.hpp
  std::string rail = "UIC60";   ///< rail profile spec of core/profile/profile_factory.hpp
  /// Inclination already contained in the rail profile data [rad] (ProfileFileOptions::
  /// built_in_cant, --rail-cant); unset = what the profile itself says (SIMPACK "canted" rule,
  /// a text file's "# cant:" line, else 0).
  std::optional<double> rail_cant;
  TrackParameters track;  ///< gauge, gauge depth, flange-back spacing, taping-line offset, inclination, r0 [SI]
};

/// Builds the wheelset geometry of spec (profiles by make_profile, rail read with rail_cant).
/// @throws ProfileError for a bad profile, std::invalid_argument for invalid track parameters.
WheelsetGeometry make_geometry(const GeometrySpec& spec);

}  // namespace wrc
