// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The run parameter file (`wrc run --params FILE`): a JSON object whose keys are those of
/// run_parameter_table() (core/dynamics/run_parameter_table.hpp; the same names as run_command_t's
/// fields), comments allowed. Keys not given keep their value; an unknown key, a key given twice
/// (in any object), a wrong type, a number beyond the range of a double (1e999) or an invalid
/// value (the table's rule: kind and range) is an error naming the file and the key.

#include <string>

#include "core/dynamics/run_parameter_table.hpp"

namespace wrc {

/// Applies the JSON text of a parameter file to spec (then validates it).
/// @param source name for error messages (the path).
/// @throws std::invalid_argument "<source>: <key>: <reason>".
void apply_run_parameters(const std::string& json_text, const std::string& source, RunSpec& spec);

/// Reads path (regular file, at most 1 MB) and applies it. @throws std::invalid_argument / std::runtime_error.
void apply_run_parameter_file(const std::string& path, RunSpec& spec);

/// The parameter file of spec (every key, with a unit comment per line).
std::string run_parameter_text(const RunSpec& spec);

}  // namespace wrc
