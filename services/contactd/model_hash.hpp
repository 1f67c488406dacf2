// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The model hash a contact service publishes (heartbeat_t.model_hash, contact_reply_t.model_hash):
/// SHA-256 of the model data it computes with: the interpolated model's ContactPointTable, the
/// spline model's coefficients; onepoint and multipoint compute from the geometry alone.

#include <string>

#include "core/model_interface/contact_model.hpp"

namespace wrc::contactd {

/// SHA-256 (64 hex digits) of model's precomputed data; empty for a model without any.
/// "interp": ContactPointTable::data() (the grid's counts and half ranges, the transition
/// options, the y nodes, the rigid roll at every node, every tabulated value and slope of both
/// wheels, the jumps' bands and their continued points) as little-endian doubles
/// (sha256_hex_of_doubles).
/// "spline": SplineContactGeometry::data_hash() (spline_model_t.model_hash).
std::string model_hash(const ContactModel& model);

}  // namespace wrc::contactd
