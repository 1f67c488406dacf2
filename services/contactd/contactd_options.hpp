#pragma once
/// @file
/// Command line of wrc-contactd beyond the options every service shares (bus/service_options.hpp):
///   --model onepoint|interp|multipoint   (required)
///   --wheel W --rail R --rail-cant C --gauge G --gauge-depth D --flange-back F
///   --taping-line-offset T --inclination I --r0 R0
/// with the same meaning and defaults as the geometry commands of the `wrc` front end
/// (core/identity/geometry_key.hpp: geometry_arguments writes them).

#include <string>
#include <vector>

#include "core/geometry/geometry_spec.hpp"

namespace wrc::contactd {

/// Models this service can run.
inline const std::vector<std::string>& known_models() {
  static const std::vector<std::string> models{"onepoint", "interp", "multipoint"};
  return models;
}

/// Parsed wrc-contactd options (those after bus::ServiceOptions took its own).
struct ContactdOptions {
  std::string model;      ///< one of known_models()
  GeometrySpec geometry;  ///< profiles, rail cant and track

  /// Parses the arguments ServiceOptions left over. Throws std::invalid_argument with one line
  /// naming the option and value (unknown option, missing value, bad number, unknown model).
  static ContactdOptions parse(const std::vector<std::string>& args);
  /// Help text of these options, one line each.
  static std::string help_text();
};

}  // namespace wrc::contactd
