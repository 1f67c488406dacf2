// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// What a START command carries besides the model, geometry and swaps, declared once: the run
/// parameters (core/dynamics/run_parameter_table.hpp) as members of RunRequest, and the contact
/// client's settings (contact_timeout, contact_retries, contact_wait; `wrc run --timeout`,
/// `--retries`, `--contact-wait`). The run command codec and `wrc run`'s options walk it.

#include <vector>

#include "core/numerics/parameter_table.hpp"
#include "protocol/run/run_command_codec.hpp"

namespace wrc::protocol {

/// The contact client's settings, with the rule wrc-dynamicsd applies.
const std::vector<Parameter<RunRequest>>& contact_client_table();

/// run_parameter_table() lifted into RunRequest::spec, then contact_client_table().
const std::vector<Parameter<RunRequest>>& run_request_table();

}  // namespace wrc::protocol
