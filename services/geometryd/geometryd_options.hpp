// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Command line of wrc-geometryd beyond the options every service shares (bus/service/service_options.hpp):
///   --cache-dir DIR   where the model files are kept (default: default_cache_dir())

#include <string>
#include <vector>

namespace wrc::geometryd {

/// Parsed wrc-geometryd options (those after bus::ServiceOptions took its own).
struct GeometrydOptions {
  std::string cache_dir;  ///< directory of the model cache (<model_key>.splinemodel files)

  /// Parses the arguments ServiceOptions left over. Throws std::invalid_argument with one line
  /// naming the option (unknown option, missing or empty value).
  static GeometrydOptions parse(const std::vector<std::string>& args);
  /// Help text of these options, one line each (from the table; options/options.hpp parses).
  static std::string help_text();
};

/// The default cache directory: $WRC_CACHE_DIR, else $XDG_CACHE_HOME/wrc/models, else
/// $HOME/.cache/wrc/models (unset and empty variables are skipped). Throws std::runtime_error
/// when none of the three variables is set.
std::string default_cache_dir();

}  // namespace wrc::geometryd
