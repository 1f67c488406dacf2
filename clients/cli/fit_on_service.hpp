// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// `wrc fit --service`: the spline model precomputed by wrc-geometryd on the bus (started for the
/// command when none runs), with a progress bar fed by its progress_t messages; the model is then
/// in the service's cache, where every spline contact service of this geometry gets it.

#include "cli/options.hpp"
#include "core/geometry/geometry_spec.hpp"
#include "core/spline/spline_fit_options.hpp"

namespace wrc::cli {

/// The options fit_on_service() reads besides the service-start ones (service_starter.hpp).
std::vector<OptionSpec> fit_on_service_option_specs();

/// Sends one geometry_request_t for spec and fit (--recompute ignores the cache), shows the
/// progress, and prints the model key, model hash, timings and where the model is (inline or
/// its cache file with size). Returns 0; throws std::runtime_error naming the reason when the
/// request is rejected, the fit fails, or no answer comes within --wait seconds.
int fit_on_service(const Options& options, const GeometrySpec& spec, const SplineFitOptions& fit);

}  // namespace wrc::cli
