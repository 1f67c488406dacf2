#pragma once
/// @file
/// The run parameter file (`wrc run --params FILE`): a JSON object whose keys are the names of
/// run_parameter_table() (the same names as run_command_t's fields), comments allowed. Keys not
/// given keep their value; an unknown key, a wrong type or an invalid value is an error naming
/// the file and the key.

#include <string>
#include <vector>

#include "core/dynamics/wheelset_parameters.hpp"

namespace wrc {

/// What a parameter's JSON value is.
enum class RunParameterKind { kNumber, kInteger, kBoolean };

/// One parameter of a run: its file key, unit and meaning, and where it lives in RunSpec.
struct RunParameter {
  const char* key;          ///< e.g. "longitudinal_stiffness"
  const char* unit;         ///< e.g. "N/m"
  const char* description;  ///< one line
  RunParameterKind kind;
  double (*get)(const RunSpec&);       ///< the value (booleans as 0 / 1)
  void (*set)(RunSpec&, double value);
};

/// Every parameter, in file order. The one list of names for the file, the summary and the docs.
const std::vector<RunParameter>& run_parameter_table();

/// Applies the JSON text of a parameter file to spec (then validates it).
/// @param source name for error messages (the path).
/// @throws std::invalid_argument "<source>: <key>: <reason>".
void apply_run_parameters(const std::string& json_text, const std::string& source, RunSpec& spec);

/// Reads path (regular file, at most 1 MB) and applies it. @throws std::invalid_argument / std::runtime_error.
void apply_run_parameter_file(const std::string& path, RunSpec& spec);

/// The parameter file of spec (every key, with a unit comment per line).
std::string run_parameter_text(const RunSpec& spec);

}  // namespace wrc
