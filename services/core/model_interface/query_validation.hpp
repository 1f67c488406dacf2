// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The one rule a ContactQuery obeys at the model boundary, checked before any computation: which
/// range each field must lie in. The models check it in-process (validate_contact_query); the bus
/// adapter (protocol/contact/contact_query_codec.hpp) converts a message and checks the same rule
/// (find_query_violation), so a query is accepted or rejected alike in-process and over the bus.

#include <optional>
#include <string>

#include "core/model_interface/contact_model.hpp"

namespace wrc {

/// Smallest and largest FASTSIM element count accepted per direction (elements per strip and
/// strips) [-], both included.
inline constexpr int kMinFastsimGrid = 2;
inline constexpr int kMaxFastsimGrid = 400;

/// Shear modulus G: positive, at most this [Pa] (steel is 8.2e10; 1e13 leaves any real material in).
inline constexpr double kMaxShearModulus = 1e13;
/// Poisson's ratio nu: strictly between these [-] (0.5 is incompressible: Kalker's coefficients and
/// the contact modulus degenerate; 0 is no material either).
inline constexpr double kMinPoissonRatio = 0.0;
inline constexpr double kMaxPoissonRatio = 0.5;
/// Friction coefficient mu: from 0 up to this, both included [-].
inline constexpr double kMaxFriction = 10.0;
/// Rolling speed: positive, at most this [m/s].
inline constexpr double kMaxSpeed = 1000.0;

// The ranges of a wheelset that is on a track at all; whether a wheel touches its rail there is
// for the model to say (ContactConfigurationError).
/// |pose.y| and |pose.roll| at most this [m], [rad].
inline constexpr double kMaxLateralShift = 0.5;
inline constexpr double kMaxRoll = 0.5;
/// |pose.z| at most this [m].
inline constexpr double kMaxHeight = 10.0;
/// |y_dot|, |z_dot| [m/s] and |roll_dot|, |yaw_dot| [rad/s] at most this.
inline constexpr double kMaxPoseRate = 100.0;
/// |spin_rate| at most this [rad/s] (1000 m/s on a 0.1 m wheel).
inline constexpr double kMaxSpinRate = 1e4;
/// A normal load (either point of either wheel): from 0 up to this [N] (600 times a wheel's static
/// load; kElastic ignores the loads, but a bad one is still an error).
inline constexpr double kMaxNormalLoad = 1e8;
/// |tracked_s_wheel| and |second_tracked_s_wheel| at most this, or NaN (none) [m].
inline constexpr double kMaxTrackedProfileCoordinate = 1.0;

/// A field of a ContactQuery that has a rule.
enum class QueryField {
  kPoseY, kPoseZ, kPoseRoll, kPoseYaw, kPoseX,
  kYDot, kZDot, kRollDot, kYawDot, kSpinRate, kSpeed,
  kNormalLoadLeft, kNormalLoadRight, kSecondNormalLoadLeft, kSecondNormalLoadRight,
  kTrackedSWheelLeft, kTrackedSWheelRight, kSecondTrackedSWheelLeft, kSecondTrackedSWheelRight,
  kFormulation, kShearModulus, kPoissonRatio, kFriction, kFastsimElements, kFastsimStrips,
  kRailLateralLeft, kRailVerticalLeft, kRailRollLeft, kRailLateralRateLeft, kRailVerticalRateLeft,
  kRailRollRateLeft, kRailLateralRight, kRailVerticalRight, kRailRollRight, kRailLateralRateRight,
  kRailVerticalRateRight, kRailRollRateRight,
};

/// What a field's value must be.
enum class QueryRuleKind {
  kFinite,      ///< any finite value
  kClosed,      ///< finite, in [low, high]
  kOpen,        ///< finite, in (low, high)
  kPositiveAtMost,  ///< finite, in (0, high] (low is 0)
  kNanOrClosed, ///< NaN (none) or in [low, high]
  kCount,       ///< a whole number in low..high (FASTSIM grid; formulation: 0 kRigid, 1 kElastic)
};

/// The rule of one field.
struct QueryRule {
  QueryField field;
  QueryRuleKind kind;
  double low = 0;
  double high = 0;
  const char* unit = "";  ///< SI unit of the field ("-" for a ratio, "" for a count)
};

/// A field that breaks its rule, with its value.
struct QueryViolation {
  QueryRule rule;
  double value = 0;
};

/// The first field of query (in QueryField order) that breaks its rule, nothing when every field
/// keeps it.
std::optional<QueryViolation> find_query_violation(const ContactQuery& query);

/// The field's name in the library ("pose.y", "normal_load[0] (left)", "material.friction").
const char* query_field_name(QueryField field);

/// How a violation's value breaks its rule, in the words of the bus adapter and the command line
/// (after "<name> = <value> " or "<option>: <value> "): "is not a finite number", "is outside
/// [low, high] <unit>" (a closed rule or a count), "is outside (low, high) [-]" (an open one),
/// "is not positive" or "is outside (0, high] <unit>" (a positive one); the bounds with
/// number_text's nine digits.
std::string query_rule_breach(const QueryViolation& violation);

/// Throws std::invalid_argument "contact query: <field> [unit] = <value> <rule>" for the first
/// violation (find_query_violation): any pose value or rate NaN, infinite or outside its range
/// above; speed not in (0, kMaxSpeed]; a normal load negative, not finite or above
/// kMaxNormalLoad; a tracked coordinate infinite or beyond kMaxTrackedProfileCoordinate; G not in
/// (0, kMaxShearModulus]; nu not in (kMinPoissonRatio, kMaxPoissonRatio); mu not in
/// [0, kMaxFriction]; a FASTSIM count outside kMinFastsimGrid..kMaxFastsimGrid; a formulation that
/// is neither kRigid nor kElastic; a rail offset beyond kMaxRailOffset, kMaxRailRoll or
/// kMaxRailOffsetRate (rail_offset.hpp). Loads are checked in both formulations.
void validate_contact_query(const ContactQuery& query);

}  // namespace wrc
