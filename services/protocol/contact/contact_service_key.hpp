// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The key a contact service computes with, which it publishes (heartbeat_t.geometry_key) and
/// which a query to it carries (contact_query_t.geometry_key): the geometry's key, or for the
/// spline model fitted with options other than the default its model key (geometry and fit), so
/// that a run never takes a spline service of another fit for its own.

#include <string>

#include "core/geometry/geometry_spec.hpp"
#include "core/spline/spline_fit_options.hpp"

namespace wrc::protocol {

/// The key of a contact service of model on geometry, the spline model fitted with fit.
std::string contact_service_key(const std::string& model, const GeometrySpec& geometry, const SplineFitOptions& fit);

}  // namespace wrc::protocol
