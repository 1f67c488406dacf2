// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The base of the Hertzian contact models (one-point, interpolated, multi-point, spline): what
/// every one of them holds (geometry, options, the FASTSIM solvers) and the one evaluate() they
/// share (validate the query, the wheelset motion, the patches of each wheel, the resultant).

#include <memory>
#include <string>

#include "core/model_interface/contact_model.hpp"
#include "core/model_interface/contact_model_options.hpp"
#include "core/model_interface/patch_builder.hpp"
#include "core/models/fastsim_cache.hpp"

namespace wrc {

/// A contact model whose patches are Hertz ellipses with FASTSIM creep forces. Subclasses say
/// which patches each wheel gets (add_wheel_patches()).
class HertzianContactModel : public ContactModel {
 public:
  /// validate_contact_query(), then add_wheel_patches() for the left and the right wheel, then
  /// check_contact_range() (contact_range.hpp: ContactConfigurationError or NoContactError outside
  /// the models' range), then the resultant of every patch about the wheelset centre.
  ContactResult evaluate(const ContactQuery& query) const final;
  const WheelsetGeometry& geometry() const final { return *geometry_; }
  const ContactModelOptions& options() const { return options_; }

 protected:
  /// @param model the model's name, for the error of a null geometry.
  /// @throws std::invalid_argument for a null geometry or invalid options.
  HertzianContactModel(std::shared_ptr<const WheelsetGeometry> geometry, ContactModelOptions options,
                       const std::string& model);

  /// Appends the patches of one wheel (none when it carries no load or does not touch) and
  /// returns the wheel's constraint (always).
  virtual WheelConstraint add_wheel_patches(WheelSide side, const PatchContext& context,
                                            ContactResult& result) const = 0;

  /// add_wheel_patches() for a wheel whose rail the query moved (ContactQuery::rail_offsets): in
  /// the rail's coordinates (RailFrame), patches and constraints carried back into the track frame.
  void add_moved_rail_patches(WheelSide side, const PatchContext& context, ContactResult& result) const;

  /// The exact common point of one wheel at pose, checked (require_common_point()).
  ContactPoint exact_common_point(WheelSide side, const WheelsetPose& pose) const;

  std::shared_ptr<const WheelsetGeometry> geometry_;
  ContactModelOptions options_;
  double steepest_flange_ = 0;  ///< steepest flange point of the wheel profile [m] (flange_climb.hpp)
  FastsimCache fastsim_;
};

}  // namespace wrc
