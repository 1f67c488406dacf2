// SPDX-License-Identifier: Apache-2.0
#include "protocol/contact/contact_service_key.hpp"

#include "core/identity/geometry_key.hpp"
#include "core/models/contact_model_factory.hpp"
#include "protocol/geometry/spline_model_codec.hpp"

namespace wrc::protocol {

std::string contact_service_key(const std::string& model, const GeometrySpec& geometry, const SplineFitOptions& fit) {
  const std::string key = geometry_key(geometry);
  if (!contact_model_entry(model).needs_data || fit.canonical_text() == SplineFitOptions{}.canonical_text()) return key;
  return model_key(key, fit);
}

}  // namespace wrc::protocol
