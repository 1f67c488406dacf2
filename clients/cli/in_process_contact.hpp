// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A contact model evaluated in this process, without the bus (`wrc stability`, a sweep's runs):
/// the spline model fitted here first, as `wrc run --in-process` has wrc-dynamicsd do.

#include <memory>
#include <string>

#include "core/dynamics/contact_evaluator.hpp"
#include "core/geometry/wheelset_geometry.hpp"
#include "core/spline/spline_fit_options.hpp"

namespace wrc::cli {

/// The contact model `model` on geometry, evaluated here (a model that needs precomputed data is
/// fitted first, with fit: the spline model's options, its box among them). @throws
/// std::invalid_argument for an unknown model or invalid fit options, std::runtime_error when it
/// cannot be built.
std::shared_ptr<ContactEvaluator> in_process_contact(const std::string& model,
                                                     std::shared_ptr<const WheelsetGeometry> geometry,
                                                     const SplineFitOptions& fit = {});

}  // namespace wrc::cli
