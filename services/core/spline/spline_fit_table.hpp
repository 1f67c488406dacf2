// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The scalar spline fit options, declared once: per member of SplineFitOptions its key (the
/// spline_fit_options_t field's name), command-line option of `wrc fit` (--sample-step,
/// --jump-weight, --jump-band, --transition, --flange-region-angle (not --flange-angle: a run's flange
/// angle is Nadal's); the box and the sample counts are
/// set by the compound --box and --samples), unit, description and range; the defaults are
/// SplineFitOptions{}'s. SplineFitOptions::validate, those options and the spline_fit_options_t
/// codec are generated from it. The knot counts and degrees (triples), the knot placement and
/// the breakpoints are not scalars and are handled where they are used; threads and the
/// potential-point search do not travel with a model.

#include <vector>

#include "core/numerics/parameter_table.hpp"
#include "core/spline/spline_fit_options.hpp"

namespace wrc {

/// Every scalar fit option, in spline_fit_options_t's order.
const std::vector<Parameter<SplineFitOptions>>& spline_fit_table();

}  // namespace wrc
