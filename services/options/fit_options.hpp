// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The spline-fit options of the command line (wrc fit, run, sweep, stability, bifurcation and
/// wrc-contactd; the same names as SplineFitOptions).

#include <vector>

#include <string>

#include "options/options.hpp"
#include "core/spline/spline_fit_options.hpp"

namespace wrc {

/// --knots, --degree, --box, --knot-placement, --samples, --sample-step, --jump-weight,
/// --jump-band, --flange-region-angle, --paper-variant, --threads.
std::vector<OptionSpec> fit_option_specs();

/// SplineFitOptions from parsed options (defaults of SplineFitOptions; --paper-variant starts from
/// SplineFitOptions::paper_benchmark()). Throws UsageError naming the option.
SplineFitOptions fit_options_from(const Options& options);

/// fit_option_specs() for a command whose contact model may be the spline model (run, sweep,
/// stability, bifurcation), each help beginning "spline model only: ".
std::vector<OptionSpec> spline_model_fit_option_specs();

/// The first fit option given in options ("--box", ...), or empty when none is.
std::string first_fit_option(const Options& options);

/// The fit options given in options as the arguments of another program's command line (a
/// spline service started for a run): each name, and its value when it takes one.
std::vector<std::string> fit_arguments(const Options& options);

}  // namespace wrc
