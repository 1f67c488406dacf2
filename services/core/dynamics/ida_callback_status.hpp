// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// What a residual or Jacobian callback tells IDA when the equations throw: a contact
/// configuration the model cannot evaluate (ContactConfigurationError) is recoverable (IDA retries
/// with a smaller step), anything else ends the run. Shared by the wheelset and vehicle runs.

#include <exception>
#include <string>
#include <utility>

#include "core/model_interface/contact_model.hpp"

namespace wrc {

/// Calls evaluate(); returns 0 when it returns, 1 (recoverable) when it throws a
/// ContactConfigurationError, -1 for any other exception. The exception's text goes to last_error.
template <class Evaluate>
int ida_callback_status(std::string& last_error, Evaluate&& evaluate) {
  try {
    std::forward<Evaluate>(evaluate)();
    return 0;
  } catch (const ContactConfigurationError& e) {
    last_error = e.what();
    return 1;
  } catch (const std::exception& e) {
    last_error = e.what();
    return -1;
  }
}

}  // namespace wrc
