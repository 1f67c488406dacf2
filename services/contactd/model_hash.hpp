#pragma once
/// @file
/// The model hash a contact service publishes (heartbeat_t.model_hash, contact_reply_t.model_hash):
/// SHA-256 of the model data it computes with: the interpolated model's ContactPointTable, the
/// spline model's coefficients; onepoint and multipoint compute from the geometry alone.

#include <string>

#include "core/models/contact_model.hpp"

namespace wrc::contactd {

/// SHA-256 (64 hex digits) of model's precomputed data; empty for a model without any.
/// "interp": the table's grid (counts, half ranges, y method) and, node by node (y slowest, yaw
/// fastest), left wheel then right, every interpolated quantity of the common point at the node
/// (z = 0), as little-endian doubles. The table's arrays are private to the model, so the hash is
/// taken of what the table answers at its nodes, which are its values.
/// "spline": SplineContactGeometry::data_hash() (spline_model_t.model_hash).
std::string model_hash(const ContactModel& model);

}  // namespace wrc::contactd
