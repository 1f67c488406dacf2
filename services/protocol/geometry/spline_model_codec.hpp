// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A fitted SplineContactGeometry <-> spline_model_t (coefficients inline), the model's cache key,
/// and the inline size limit. The model's file form is protocol/geometry/spline_model_file.hpp.
/// Used by wrc-geometryd (which fits and publishes models) and wrc-contactd --model spline (which
/// decodes them).

#include <memory>
#include <string>

#include "core/geometry/geometry_spec.hpp"
#include "core/spline/spline_geometry_fit.hpp"
#include "wrc/spline_model_t.hpp"

namespace wrc::protocol {

/// Layout version written into spline_model_t.version.
inline constexpr int kSplineModelVersion = 4;  // 4: per-jump height half-widths and y reaches
/// Largest encoded spline_model_t sent inline [B]; larger models travel as a file (one UDP
/// datagram holds < 64 kB).
inline constexpr int kMaxInlineModelBytes = 60000;

/// SHA-256 of the geometry key and the canonical text of the fit options: the cache key of a model.
std::string model_key(const std::string& geometry_key, const SplineFitOptions& options);

/// The complete model message (coefficients inline, no file) of a fit.
spline_model_t encode_model(const SplineFit& fit, const GeometrySpec& spec, const SplineFitOptions& options);

/// The model of a message with inline coefficients. Checks every size and count against the
/// others, the function names against spline_fields.hpp, finiteness, and model_hash.
/// @throws std::invalid_argument naming the inconsistent field.
std::shared_ptr<const SplineContactGeometry> decode_model(const spline_model_t& message);

/// An encoded message larger than kMaxInlineModelBytes?
bool too_large_for_inline(const spline_model_t& message);
}  // namespace wrc::protocol
