// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Track irregularities (core/track/track_irregularity.hpp) <-> the irregularity fields of
/// run_command_t (num_irregularity_samples and the five sample lists). No transport here.

#include "core/track/track_irregularity.hpp"
#include "wrc/run_command_t.hpp"

namespace wrc::protocol {

/// Writes irregularity into m's irregularity fields (none: no samples).
void to_irregularity_fields(const TrackIrregularity& irregularity, run_command_t& m);

/// The irregularities of m's fields. @throws std::invalid_argument naming the field (a count that
/// does not match a list, or beyond kMaxIrregularitySamples) or the sample (TrackIrregularity's rules).
TrackIrregularity irregularity_from_fields(const run_command_t& m);

}  // namespace wrc::protocol
