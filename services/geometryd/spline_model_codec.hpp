#pragma once
/// @file
/// The spline model on the bus and on disk: SplineFitOptions <-> spline_fit_options_t,
/// GeometrySpec <-> track_t, a fitted SplineContactGeometry <-> spline_model_t, and the model file
/// (the LCM encoding of spline_model_t with the coefficients inline). Used by wrc-geometryd (which
/// writes models) and wrc-contactd --model spline (which reads them).

#include <memory>
#include <string>

#include "core/geometry/geometry_spec.hpp"
#include "core/spline/spline_geometry_fit.hpp"
#include "wrc/geometry_table_t.hpp"
#include "wrc/spline_model_t.hpp"
#include "wrc/track_t.hpp"

namespace wrc::geometryd {

/// Layout version written into spline_model_t.version.
inline constexpr int kSplineModelVersion = 3;
/// Layout version written into geometry_table_t.version.
inline constexpr int kGeometryTableVersion = 2;
/// Largest encoded spline_model_t sent inline [B]; larger models travel as a file (one UDP
/// datagram holds < 64 kB).
inline constexpr int kMaxInlineModelBytes = 60000;

spline_fit_options_t to_message(const SplineFitOptions& options);
/// @throws std::invalid_argument naming the field for counts out of range or invalid options.
SplineFitOptions from_message(const spline_fit_options_t& message);

/// track_t of a spec; profile content hashes are the SHA-256 of the file bytes (files) or of the
/// built-in name.
track_t to_message(const GeometrySpec& spec);
/// @throws std::invalid_argument for a rail cant that is neither NaN nor finite.
GeometrySpec from_message(const track_t& message);

/// SHA-256 of the geometry key and the canonical text of the fit options: the cache key of a model.
std::string model_key(const std::string& geometry_key, const SplineFitOptions& options);

/// The complete model message (coefficients inline, no file) of a fit.
spline_model_t encode_model(const SplineFit& fit, const GeometrySpec& spec, const SplineFitOptions& options);

/// The model of a message with inline coefficients. Checks every size and count against the
/// others, the function names against spline_fields.hpp, finiteness, and model_hash.
/// @throws std::invalid_argument naming the inconsistent field.
std::shared_ptr<const SplineContactGeometry> decode_model(const spline_model_t& message);

/// Writes message (inline coefficients) to path atomically (temporary file, then rename) and
/// returns the reference to publish: the same message without coefficients and with file_path,
/// file_hash (SHA-256 of the bytes) and file_size. @throws std::runtime_error naming the path.
spline_model_t write_model_file(const spline_model_t& message, const std::string& path);

/// The reference to an existing model file holding full (the message written there): full
/// without coefficients, with file_path (absolute), file_hash (SHA-256 of the file's bytes as they
/// are now) and file_size. @throws std::runtime_error when the file cannot be read.
spline_model_t file_reference(const spline_model_t& full, const std::string& path);

/// Reads and decodes a model file (no reference to check against: a cache lookup).
/// @throws std::runtime_error naming the path when it is missing or does not decode.
spline_model_t read_model_file(const std::string& path);

/// The complete message behind a reference: itself when the coefficients are inline, otherwise
/// read from file_path, checked against file_size and file_hash, decoded.
/// @throws std::runtime_error naming the path and what does not match.
spline_model_t resolve_model(const spline_model_t& reference);

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

/// An encoded message larger than kMaxInlineModelBytes?
bool too_large_for_inline(const spline_model_t& message);

}  // namespace wrc::geometryd
