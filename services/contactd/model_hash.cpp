// SPDX-License-Identifier: Apache-2.0
#include "contactd/model_hash.hpp"

#include "core/identity/sha256.hpp"
#include "core/models/interpolated_model.hpp"
#include "core/models/spline_model.hpp"

namespace wrc::contactd {

std::string model_hash(const ContactModel& model) {
  if (const auto* interp = dynamic_cast<const InterpolatedModel*>(&model))
    return sha256_hex_of_doubles(interp->table().data());
  if (const auto* spline = dynamic_cast<const SplineModel*>(&model)) return spline->splines().data_hash();
  return "";
}

}  // namespace wrc::contactd
