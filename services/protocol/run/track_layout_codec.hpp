// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A track layout (core/track/track_layout.hpp) <-> the layout fields of run_command_t
/// (layout_cant_base, num_layout_segments, layout_segments). No transport here.

#include <cstddef>

#include "core/track/track_layout.hpp"
#include "wrc/run_command_t.hpp"

namespace wrc::protocol {

/// Most segments a run's layout may have (run_command_t.num_layout_segments).
inline constexpr std::size_t kMaxLayoutSegments = 10000;

/// Writes layout into m's layout fields (straight track: no segments).
void to_layout_fields(const TrackLayout& layout, run_command_t& m);

/// The layout of m's layout fields. @throws std::invalid_argument naming the field and the
/// segment (a count that does not match the list, an unknown kind, the layout's own rules).
TrackLayout layout_from_fields(const run_command_t& m);

}  // namespace wrc::protocol
