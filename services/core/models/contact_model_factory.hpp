// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The registry of contact models: the one list of model names, what each is, and how it is
/// built (service processes, command line, tests).

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/model_interface/contact_model.hpp"
#include "core/model_interface/contact_model_options.hpp"
#include "core/spline/spline_contact_geometry.hpp"

namespace wrc {

/// Precomputed data a model is built from besides geometry and options.
struct ContactModelData {
  /// The fitted splines of the spline model (fit_spline_geometry(), or a model file from
  /// wrc-geometryd).
  std::shared_ptr<const SplineContactGeometry> splines;
};

/// One registered model.
struct ContactModelEntry {
  std::string name;         ///< "onepoint", "interp", "multipoint", "spline"
  std::string description;  ///< one line for help texts
  bool needs_data = false;  ///< built from ContactModelData (precomputed by the geometry service)
  /// How the wheelset dynamics uses the model (docs/dynamics.md): kRigid, contact constraints
  /// with the normal forces as unknowns (one common point per wheel: onepoint, interp, spline);
  /// kElastic, normal forces from the penetration (multipoint: several points share a wheel's
  /// load by their own approach, which a single constraint per wheel cannot express).
  ContactFormulation dynamics_formulation = ContactFormulation::kRigid;
  std::function<std::unique_ptr<ContactModel>(std::shared_ptr<const WheelsetGeometry>, const ContactModelOptions&,
                                              const ContactModelData&)>
      build;
};

/// Every model, in the order help texts list them.
const std::vector<ContactModelEntry>& contact_model_registry();

/// The registered names, in registry order.
std::vector<std::string> contact_model_names();

/// The registry entry called name. @throws std::invalid_argument listing the known names.
const ContactModelEntry& contact_model_entry(const std::string& name);

/// Builds the model called name for geometry:
///  - "onepoint": OnePointModel (Hertzian one-point contact at the common point);
///  - "interp": InterpolatedModel (interpolated Hertzian contact, MEDYNA); precomputes its table
///    (options.interp) here, which takes tens of milliseconds;
///  - "multipoint": MultiPointModel (an ellipse at every local minimum of the distance);
///  - "spline": SplineModel (Arnold's unified approach) from data.splines.
/// @throws std::invalid_argument for an unknown name (the message lists the known names), for
///         "spline" without splines, for a null geometry or invalid options;
///         ContactConfigurationError when the interp table cannot be built.
std::unique_ptr<ContactModel> make_contact_model(const std::string& name,
                                                 std::shared_ptr<const WheelsetGeometry> geometry,
                                                 const ContactModelOptions& options = {},
                                                 const ContactModelData& data = {});

}  // namespace wrc
