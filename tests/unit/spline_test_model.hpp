// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A spline contact model of S1002 on UIC60 for unit tests, fitted once per test binary: the
/// default box and knots on a coarser sample grid (0.25 mm in y, 5 x 5 in roll and yaw) so that
/// the fit takes a fraction of a second, and the default model (SplineFitOptions{}) for the
/// accuracy tests; and a small interpolation table for tests that build every model.

#include <memory>

#include "core/models/contact_model_factory.hpp"
#include "core/profile/profile_factory.hpp"
#include "core/spline/spline_geometry_fit.hpp"

namespace wrc::test {

inline std::shared_ptr<const WheelsetGeometry> s1002_uic60_geometry() {
  static const auto geometry = std::make_shared<const WheelsetGeometry>(make_profile("S1002", ProfileSide::kWheel),
                                                                        make_profile("UIC60", ProfileSide::kRail));
  return geometry;
}

/// Options of the quick test model.
inline SplineFitOptions quick_spline_options() {
  SplineFitOptions o;
  o.sample_step_y = 2.5e-4;
  o.roll_samples = 5;
  o.yaw_samples = 5;
  return o;
}

/// The quick model's fit (S1002/UIC60, quick_spline_options()).
inline const SplineFit& quick_spline_fit() {
  static const SplineFit fit = fit_spline_geometry(*s1002_uic60_geometry(), quick_spline_options());
  return fit;
}

/// The default model's fit (S1002/UIC60, SplineFitOptions{}: ~1.5 s).
inline const SplineFit& default_spline_fit() {
  static const SplineFit fit = fit_spline_geometry(*s1002_uic60_geometry(), SplineFitOptions{});
  return fit;
}

/// Model options with a small interpolation table (5 y x 2 yaw nodes, 3 roll nodes about the rigid
/// roll), quick to build, for tests of behaviour every model shares.
inline ContactModelOptions small_table_options() {
  ContactModelOptions o;
  o.interp.y_points = 5;
  o.interp.yaw_points = 2;
  return o;
}

/// Model data for make_contact_model(): the quick model's splines.
inline ContactModelData quick_spline_data() { return ContactModelData{quick_spline_fit().model}; }

}  // namespace wrc::test
