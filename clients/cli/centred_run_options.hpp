// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The run of `wrc stability` and `wrc bifurcation`: the run parameters from --params,
/// --suspension and the wheelset options, with the lateral load set to 0 unless given (both study
/// the wheelset about its centred state on straight track, which a lateral load would move).

#include <string>

#include "cli/options.hpp"
#include "core/dynamics/wheelset_simulation.hpp"

namespace wrc::cli {

/// The run spec of the options o; a lateral load from the parameters (not from --lateral-force)
/// is set to 0, and a line on standard output says so with `why` (zero_lateral_load_unless_given,
/// cli/run_options.hpp).
RunSpec centred_run_spec(const Options& o, const std::string& why);

}  // namespace wrc::cli
