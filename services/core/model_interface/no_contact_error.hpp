// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The error of a configuration in which no wheel touches its rail.

#include "core/model_interface/contact_model.hpp"

namespace wrc {

/// Neither wheel touches its rail: the wheelset is lifted beyond kMaxElasticLift
/// (contact_range.hpp) in the elastic formulation. A ContactConfigurationError, so callers that
/// treat every impossible configuration alike keep doing so; the bus answers it NO_CONTACT
/// (contactd/query_evaluation.cpp) rather than IMPOSSIBLE_CONFIGURATION. The message names the gaps.
struct NoContactError : ContactConfigurationError {
  using ContactConfigurationError::ContactConfigurationError;
};

}  // namespace wrc
