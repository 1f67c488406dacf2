// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The run parameters, declared once: per member of RunSpec its key (the parameter file's, the
/// run command message's and the summary's name), command-line option of `wrc run`, unit,
/// description, valid range; the default is RunSpec{}'s. WheelsetParameters, InitialState and
/// IntegratorSettings validate against their tables, and the parameter file, `wrc run`'s options,
/// the run command codec and the run summary are generated from run_parameter_table().

#include <vector>

#include "core/dynamics/wheelset_parameters.hpp"
#include "core/numerics/parameter_table.hpp"

namespace wrc {

using RunParameterKind = ParameterKind;
using RunParameter = Parameter<RunSpec>;

/// The wheelset's masses, loads, suspension, material and FASTSIM grid, in file order.
const std::vector<Parameter<WheelsetParameters>>& wheelset_parameter_table();
/// The initial state (y0, yaw0, y_dot0, yaw_dot0, spin_rate_offset).
const std::vector<Parameter<InitialState>>& initial_state_table();
/// The integrator settings (t_end, rtol, tolerances, steps, output period).
const std::vector<Parameter<IntegratorSettings>>& integrator_settings_table();

/// Every run parameter, in file order: the three tables above, as members of RunSpec.
const std::vector<RunParameter>& run_parameter_table();

}  // namespace wrc
