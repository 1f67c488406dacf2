#pragma once
/// @file
/// Builds a contact model by name (service processes, command line, tests).

#include <memory>
#include <string>
#include <vector>

#include "core/models/contact_model.hpp"
#include "core/models/contact_model_options.hpp"

namespace wrc {

/// The names make_contact_model() builds: "onepoint", "interp", "multipoint".
std::vector<std::string> contact_model_names();

/// Builds the model called name for geometry:
///  - "onepoint": OnePointModel (Hertzian one-point contact at the common point);
///  - "interp": InterpolatedModel (interpolated Hertzian contact, MEDYNA); precomputes its table
///    (options.interp) here, which takes tens of milliseconds;
///  - "multipoint": MultiPointModel (an ellipse at every local minimum of the distance).
/// @throws std::invalid_argument for "spline" (Arnold's spline model: not available yet, a later
///         issue), for any other name (the message lists the known names), for a null geometry or
///         invalid options; ContactConfigurationError when the interp table cannot be built.
std::unique_ptr<ContactModel> make_contact_model(const std::string& name,
                                                 std::shared_ptr<const WheelsetGeometry> geometry,
                                                 const ContactModelOptions& options = {});

}  // namespace wrc
