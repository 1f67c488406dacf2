// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// GeometrySpec <-> track_t: the profiles (by name and content hash) and the track of a geometry
/// as every request, model and run command carries them.

#include "core/geometry/geometry_spec.hpp"
#include "wrc/track_t.hpp"

namespace wrc::protocol {

/// track_t of a spec; profile content hashes are the SHA-256 of the file bytes (files) or of the
/// built-in name.
track_t to_message(const GeometrySpec& spec);
/// @throws std::invalid_argument for a rail cant that is neither NaN nor finite.
GeometrySpec from_message(const track_t& message);
}  // namespace wrc::protocol
