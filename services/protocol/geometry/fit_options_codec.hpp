// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// SplineFitOptions <-> spline_fit_options_t: the options of a spline fit as requests to
/// wrc-geometryd and models carry them.

#include "core/spline/spline_fit_options.hpp"
#include "wrc/spline_fit_options_t.hpp"

namespace wrc::protocol {

spline_fit_options_t to_message(const SplineFitOptions& options);
/// @throws std::invalid_argument naming the field for counts out of range or invalid options.
SplineFitOptions from_message(const spline_fit_options_t& message);
}  // namespace wrc::protocol
