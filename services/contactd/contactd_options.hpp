// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Command line of wrc-contactd beyond the options every service shares (bus/service/service_options.hpp):
///   --model M   (required; a name of core/models/contact_model_factory.hpp's registry)
///   --wheel W --rail R --rail-cant C --gauge G --gauge-depth D --flange-back F
///   --taping-line-offset T --inclination I --r0 R0
/// parsed by the one option parser (options/options.hpp) from the one table and reader of the
/// profile and track options the geometry commands of the `wrc` front end use
/// (options/geometry_options.hpp; core/identity/geometry_key.hpp: geometry_arguments writes
/// them). Given twice, the last one wins.

#include <string>
#include <vector>

#include "core/geometry/geometry_spec.hpp"
#include "core/spline/spline_fit_options.hpp"

namespace wrc::contactd {

/// Parsed wrc-contactd options (those after bus::ServiceOptions took its own).
struct ContactdOptions {
  std::string model;      ///< a registered contact model (contact_model_names())
  GeometrySpec geometry;  ///< profiles, rail cant and track
  SplineFitOptions fit;   ///< the spline model's fit (its box, knots, ...); the default for the others

  /// Parses the arguments ServiceOptions left over. Throws std::invalid_argument with one line
  /// naming the option and value (unknown option, missing value, bad number, unknown model).
  static ContactdOptions parse(const std::vector<std::string>& args);
  /// Help text of these options, one line each (from the table).
  static std::string help_text();
};

}  // namespace wrc::contactd
