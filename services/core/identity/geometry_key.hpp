// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The one identity of a geometry input on the bus: geometry_key(spec) is the SHA-256 of a
/// canonical, versioned text of every field of a GeometrySpec, the profiles by their content.
/// Services publish it as geometry_key in heartbeat_t, contact_reply_t and geometry_table_t;
/// clients put the key of the geometry they expect into contact_query_t.geometry_key, and a
/// service with another geometry rejects the query. geometry_arguments(spec) is the command line
/// that makes a service build that geometry.
///
/// Canonical text (version "wrc-geometry-v1"), one field a line, numbers with %.17g (exact):
///   wrc-geometry-v1
///   wheel builtin S1002            built-in profile: its canonical name (conic:/circle: with the
///                                  parameter as %.17g)
///   rail file <N>                  profile file: its byte count, a newline, its N bytes, a newline
///   rail_cant profile | <rad>      unset: as the profile says; otherwise the value
///   gauge, gauge_depth, flange_back_spacing, taping_line_offset, inclination, nominal_radius
/// Equal keys: same profiles (a file reached by another path gives the same key; an edited file
/// another one) and same track. Change the version when the text changes.

#include <string>
#include <vector>

#include "core/geometry/geometry_spec.hpp"

namespace wrc {

/// Version line the canonical text starts with.
inline constexpr const char* kGeometryKeyVersion = "wrc-geometry-v1";

/// The canonical text geometry_key() hashes (see the file comment).
/// @throws ProfileError when a profile file cannot be read.
std::string geometry_key_text(const GeometrySpec& spec);

/// SHA-256 of geometry_key_text(spec): 64 lowercase hex digits.
/// @throws ProfileError when a profile file cannot be read.
std::string geometry_key(const GeometrySpec& spec);

/// SHA-256 of one profile's content as the key sees it (a built-in's canonical name, a file's
/// bytes): profile_ref_t.content_hash. @throws ProfileError when a file cannot be read.
std::string profile_content_hash(const std::string& profile_spec);

/// Command-line arguments that make a service (wrc-contactd) build exactly this geometry:
/// --wheel, --rail, --rail-cant (when set), --gauge, --gauge-depth, --flange-back,
/// --taping-line-offset, --inclination, --r0 (numbers with 17 significant digits, angles [rad]).
std::vector<std::string> geometry_arguments(const GeometrySpec& spec);

}  // namespace wrc
