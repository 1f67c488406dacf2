// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A track layout as a user writes it (docs/track.md, parameters/track-*.json): one JSON object
///   { "cant_base": 1.5,
///     "segments": [ {"type": "straight", "length": 200},
///                   {"type": "transition", "length": 100},
///                   {"type": "curve", "length": 400, "radius": 600, "direction": "left", "cant": 0.1},
///                   {"type": "transition", "length": 100},
///                   {"type": "straight", "length": 200} ] }
/// lengths, radius and cant in metres, cant_base optional (1.5 m). Every error names the file, the
/// segment and the key.

#include <string>

#include "core/track/track_layout.hpp"

namespace wrc {

/// The layout in json_text; source names it in errors ("track.json").
/// @throws std::invalid_argument "<source>: segments[3]: radius: ..." for anything malformed.
TrackLayout parse_track_layout(const std::string& json_text, const std::string& source);

/// The layout in the file at path (a regular file of at most 1 MiB).
/// @throws std::invalid_argument naming the file, as parse_track_layout.
TrackLayout read_track_layout_file(const std::string& path);

/// The layout as the JSON text parse_track_layout reads (exact numbers: it reads back the same).
std::string track_layout_text(const TrackLayout& layout);

}  // namespace wrc
