// SPDX-License-Identifier: Apache-2.0
#include "cli/in_process_contact.hpp"

#include <iostream>

#include "core/models/contact_model_factory.hpp"
#include "core/spline/spline_geometry_fit.hpp"

namespace wrc::cli {

std::shared_ptr<ContactEvaluator> in_process_contact(const std::string& model,
                                                     std::shared_ptr<const WheelsetGeometry> geometry,
                                                     const SplineFitOptions& fit) {
  ContactModelData data;
  if (contact_model_entry(model).needs_data) {
    const SplineFit fitted = fit_spline_geometry(*geometry, fit, {});
    if (const std::string note = across_jumps_note(fitted, fit); !note.empty()) std::cerr << note << "\n";
    data.splines = fitted.model;
  }
  return std::make_shared<InProcessContact>(make_contact_model(model, std::move(geometry), {}, data));
}

}  // namespace wrc::cli
