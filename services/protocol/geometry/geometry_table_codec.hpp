// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The exact samples behind a spline fit as geometry_table_t, inline or as a table file (the same
/// file form as a model's: protocol/geometry/message_file.hpp), and resolving a reference back to
/// the complete table with its size, layout and values' hash checked.

#include <string>

#include "core/geometry/geometry_spec.hpp"
#include "core/spline/spline_geometry_fit.hpp"
#include "wrc/geometry_table_t.hpp"

namespace wrc::protocol {

/// Layout version written into geometry_table_t.version.
inline constexpr int kGeometryTableVersion = 2;

/// The exact samples of one wheel behind a fit (SplineFit::samples) as a complete table (values
/// inline) for the model model_key.
geometry_table_t encode_table(const WheelSampleGrid& grid, const GeometrySpec& spec, const std::string& model_key);

/// Writes table (values inline) to path atomically and returns the reference to publish (no
/// values; file_path, file_size, file_hash). @throws std::runtime_error naming the path.
geometry_table_t write_table_file(const geometry_table_t& table, const std::string& path);
/// The reference to an existing table file holding full. @throws std::runtime_error.
geometry_table_t table_reference(const geometry_table_t& full, const std::string& path);
/// Reads and decodes a table file. @throws std::runtime_error naming the path.
geometry_table_t read_table_file(const std::string& path);
/// The complete table behind a reference (or the message itself when its values are inline),
/// checked: file size and SHA-256, version, sizes, table_hash. @throws std::runtime_error.
geometry_table_t resolve_table(const geometry_table_t& reference);
}  // namespace wrc::protocol
