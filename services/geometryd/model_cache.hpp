// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The model cache of wrc-geometryd: one file per model, <dir>/<model_key>.splinemodel, in the
/// format of protocol/geometry/spline_model_file.hpp (write_model_file). Every model the service fits is stored;
/// a request for a stored model is answered from its file.

#include <optional>
#include <vector>
#include <string>

#include "wrc/geometry_table_t.hpp"
#include "wrc/spline_model_t.hpp"

namespace wrc::geometryd {

/// File extension of a cached model.
inline constexpr const char* kModelFileExtension = ".splinemodel";
/// File extension of a cached geometry table (after ".left" or ".right").
inline constexpr const char* kTableFileExtension = ".geometrytable";

class ModelCache {
 public:
  /// dir: the cache directory; missing directories on the way are created with mode 0700.
  /// @throws std::runtime_error naming the path when it cannot be created or is no directory.
  explicit ModelCache(std::string dir);

  /// The cache directory as given.
  const std::string& dir() const { return dir_; }
  /// <dir>/<model_key>.splinemodel
  std::string path(const std::string& model_key) const;

  /// The complete message (coefficients inline) of model_key when its file exists, reads,
  /// holds that model_key and decodes (decode_model: sizes, finiteness, model_hash); otherwise
  /// nothing, with *why set to the reason when a file exists but is unusable (empty when there
  /// is no file).
  std::optional<spline_model_t> find(const std::string& model_key, std::string* why) const;

  /// Writes full (coefficients inline) to path(full.model_key) and returns the file reference
  /// (write_model_file). @throws std::runtime_error naming the path.
  spline_model_t store(const spline_model_t& full) const;

  /// <dir>/<model_key>.left.geometrytable or .right.geometrytable (wheel: geometry_table_t::LEFT, RIGHT).
  std::string table_path(const std::string& model_key, int wheel) const;
  /// Writes a complete table to table_path() and returns its reference (write_table_file).
  /// @throws std::runtime_error naming the path.
  geometry_table_t store_table(const geometry_table_t& full) const;
  /// References to the stored tables of model_key that read and decode (left, then right; none
  /// when missing or unusable).
  std::vector<geometry_table_t> find_tables(const std::string& model_key) const;

 private:
  std::string dir_;
};

/// The message to publish for the complete model full stored at path: full itself when it fits
/// inline (too_large_for_inline), otherwise its file reference (file_reference).
/// @throws std::runtime_error when the file is needed and cannot be read.
spline_model_t answer_message(const spline_model_t& full, const std::string& path);

}  // namespace wrc::geometryd
