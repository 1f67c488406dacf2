// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Where the two rails lie at one point of an irregular track: the four channels of
/// TrackIrregularity (alignment, vertical level, cross-level, gauge) as each rail's offset and
/// roll for the contact query (docs/track.md).

#include <array>

#include "core/model_interface/rail_offset.hpp"
#include "core/track/track_irregularity.hpp"

namespace wrc {

/// The left [0] and right [1] rail's offsets at point:
///   lateral  = alignment +- gauge / 2,  vertical = vertical_level +- cross_level / 2,
///   roll     = asin(cross_level / cant_base) for both rails (the sleeper tilts with the cross-level),
/// and their rates, speed times the slopes.
/// @param cant_base lateral distance the cross-level is measured over [m] (1.5 m).
/// @param speed forward speed of the wheelset [m/s].
std::array<RailOffset, 2> rail_offsets_at(const IrregularityPoint& point, double cant_base, double speed);

}  // namespace wrc
