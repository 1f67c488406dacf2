// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Options for reading profile files.

#include <optional>

namespace wrc {

/// Options for the profile file readers.
struct ProfileFileOptions {
  /// Rail inclination contained in the data [rad]. When set, it overrides what the reader would
  /// infer (SIMPACK: the "canted" rule; MiniProf: 0; text: the "# cant:" line or 0). Ignored for
  /// wheels.
  std::optional<double> built_in_cant;
};

}  // namespace wrc
