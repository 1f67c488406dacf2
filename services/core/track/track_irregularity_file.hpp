// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Track irregularities as a measuring car or a user writes them: CSV, one header line naming the
/// columns with their units, then one line per sample (docs/track.md, parameters/irregularities-*.csv):
///   # comment lines start with '#'
///   s [m],alignment [mm],vertical_level [mm],cross_level [mm],gauge [mm]
///   0,0.00,0.00,0.00,0.00
///   0.25,0.12,-0.31,0.05,0.40
/// Columns: s (distance along the track [m]) and the four channels (track_irregularity.hpp), each
/// exactly once, in any order, every channel in [m] or [mm]. Every error names the file, the line
/// and the column.

#include <string>

#include "core/track/track_irregularity.hpp"

namespace wrc {

/// Largest irregularity file [B] (20000 samples of five long numbers fit in 2 MiB).
inline constexpr std::size_t kMaxIrregularityFileBytes = 4u << 20;

/// The irregularities in csv_text; source names it in errors.
/// @throws std::invalid_argument "<source>:<line>: <column>: ..." for a malformed header, an unknown,
///         missing or repeated column, a unit other than m / mm, a cell that is not a number, a
///         row with another number of cells, and whatever TrackIrregularity refuses (with the line).
TrackIrregularity parse_track_irregularity(const std::string& csv_text, const std::string& source);

/// The irregularities in the file at path (read_regular_file, at most kMaxIrregularityFileBytes).
/// @throws std::invalid_argument naming the file, as parse_track_irregularity.
TrackIrregularity read_track_irregularity_file(const std::string& path);

/// The irregularities as CSV in metres, exact numbers: parse_track_irregularity reads back the same.
/// @param comment written first as '#' lines (one per line of the text; none when empty).
std::string track_irregularity_text(const TrackIrregularity& irregularity, const std::string& comment = "");

}  // namespace wrc
