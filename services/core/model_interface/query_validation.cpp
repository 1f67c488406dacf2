// SPDX-License-Identifier: Apache-2.0
#include "core/model_interface/query_validation.hpp"

#include <cfloat>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

#include "core/geometry/wheelset_geometry.hpp"
#include "core/numerics/number_text.hpp"

namespace wrc {
namespace {

// Significant digits of the values and bounds in the library's messages [-].
constexpr int kDigits = 6;

bool keeps(const QueryRule& rule, double v) {
  switch (rule.kind) {
    case QueryRuleKind::kFinite: return std::isfinite(v);
    case QueryRuleKind::kClosed: return std::isfinite(v) && v >= rule.low && v <= rule.high;
    case QueryRuleKind::kOpen: return std::isfinite(v) && v > rule.low && v < rule.high;
    case QueryRuleKind::kPositiveAtMost: return std::isfinite(v) && v > 0.0 && v <= rule.high;
    case QueryRuleKind::kNanOrClosed: return std::isnan(v) || (v >= rule.low && v <= rule.high);
    case QueryRuleKind::kCount: return v >= rule.low && v <= rule.high;
  }
  return false;
}

bool is_load(QueryField field) {
  return field == QueryField::kNormalLoadLeft || field == QueryField::kNormalLoadRight ||
         field == QueryField::kSecondNormalLoadLeft || field == QueryField::kSecondNormalLoadRight;
}

// The library's wording of a broken rule (after "<field> [unit] = <value> ").
std::string library_rule_text(const QueryRule& rule, double v) {
  auto bound = [](double b) { return number_text(b, kDigits); };
  auto interval = [&](const char* open, const char* close) {
    return open + bound(rule.low) + ", " + bound(rule.high) + close;
  };
  switch (rule.kind) {
    case QueryRuleKind::kFinite: return "must be finite";
    case QueryRuleKind::kClosed:
      if (rule.field == QueryField::kPoseYaw && std::isfinite(v))
        return "is beyond the validated range +-" + bound(rule.high) + " rad of the contact geometry";
      if (is_load(rule.field) && !(v > rule.high)) return "must be non-negative and finite";
      if (!std::isfinite(v)) return "must be finite";
      return "must be in " + interval("[", "]");
    case QueryRuleKind::kOpen: return "must be in " + interval("(", ")");
    case QueryRuleKind::kPositiveAtMost: return "must be in (0, " + bound(rule.high) + "]";
    case QueryRuleKind::kNanOrClosed: return "must be NaN (none) or in " + interval("[", "]");
    case QueryRuleKind::kCount:
      if (rule.field == QueryField::kFormulation) return "is not kRigid or kElastic";
      return "must be in " + bound(rule.low) + ".." + bound(rule.high);
  }
  return "is invalid";
}

}  // namespace

std::optional<QueryViolation> find_query_violation(const ContactQuery& q) {
  using F = QueryField;
  using K = QueryRuleKind;
  const double tracked = kMaxTrackedProfileCoordinate;
  const double offset = kMaxRailOffset;
  const double rate = kMaxRailOffsetRate;
  const RailOffset& left = q.rail_offsets[0];
  const RailOffset& right = q.rail_offsets[1];
  const struct {
    QueryRule rule;
    double value;
  } fields[] = {
      {{F::kPoseY, K::kClosed, -kMaxLateralShift, kMaxLateralShift, "m"}, q.pose.y},
      {{F::kPoseZ, K::kClosed, -kMaxHeight, kMaxHeight, "m"}, q.pose.z},
      {{F::kPoseRoll, K::kClosed, -kMaxRoll, kMaxRoll, "rad"}, q.pose.roll},
      {{F::kPoseYaw, K::kClosed, -kMaxValidatedYaw, kMaxValidatedYaw, "rad"}, q.pose.yaw},
      {{F::kPoseX, K::kFinite, -DBL_MAX, DBL_MAX, "m"}, q.pose.x},
      {{F::kYDot, K::kClosed, -kMaxPoseRate, kMaxPoseRate, "m/s"}, q.y_dot},
      {{F::kZDot, K::kClosed, -kMaxPoseRate, kMaxPoseRate, "m/s"}, q.z_dot},
      {{F::kRollDot, K::kClosed, -kMaxPoseRate, kMaxPoseRate, "rad/s"}, q.roll_dot},
      {{F::kYawDot, K::kClosed, -kMaxPoseRate, kMaxPoseRate, "rad/s"}, q.yaw_dot},
      {{F::kSpinRate, K::kClosed, -kMaxSpinRate, kMaxSpinRate, "rad/s"}, q.spin_rate},
      {{F::kSpeed, K::kPositiveAtMost, 0.0, kMaxSpeed, "m/s"}, q.speed},
      {{F::kNormalLoadLeft, K::kClosed, 0.0, kMaxNormalLoad, "N"}, q.normal_load[0]},
      {{F::kNormalLoadRight, K::kClosed, 0.0, kMaxNormalLoad, "N"}, q.normal_load[1]},
      {{F::kSecondNormalLoadLeft, K::kClosed, 0.0, kMaxNormalLoad, "N"}, q.second_normal_load[0]},
      {{F::kSecondNormalLoadRight, K::kClosed, 0.0, kMaxNormalLoad, "N"}, q.second_normal_load[1]},
      {{F::kTrackedSWheelLeft, K::kNanOrClosed, -tracked, tracked, "m"}, q.tracked_s_wheel[0]},
      {{F::kTrackedSWheelRight, K::kNanOrClosed, -tracked, tracked, "m"}, q.tracked_s_wheel[1]},
      {{F::kSecondTrackedSWheelLeft, K::kNanOrClosed, -tracked, tracked, "m"}, q.second_tracked_s_wheel[0]},
      {{F::kSecondTrackedSWheelRight, K::kNanOrClosed, -tracked, tracked, "m"}, q.second_tracked_s_wheel[1]},
      {{F::kFormulation, K::kCount, 0.0, 1.0, ""}, static_cast<double>(static_cast<int>(q.formulation))},
      {{F::kShearModulus, K::kPositiveAtMost, 0.0, kMaxShearModulus, "Pa"}, q.material.shear_modulus},
      {{F::kPoissonRatio, K::kOpen, kMinPoissonRatio, kMaxPoissonRatio, "-"}, q.material.poisson_ratio},
      {{F::kFriction, K::kClosed, 0.0, kMaxFriction, "-"}, q.material.friction},
      {{F::kFastsimElements, K::kCount, kMinFastsimGrid, kMaxFastsimGrid, ""}, static_cast<double>(q.fastsim_elements)},
      {{F::kFastsimStrips, K::kCount, kMinFastsimGrid, kMaxFastsimGrid, ""}, static_cast<double>(q.fastsim_strips)},
      {{F::kRailLateralLeft, K::kClosed, -offset, offset, "m"}, left.lateral},
      {{F::kRailVerticalLeft, K::kClosed, -offset, offset, "m"}, left.vertical},
      {{F::kRailRollLeft, K::kClosed, -kMaxRailRoll, kMaxRailRoll, "rad"}, left.roll},
      {{F::kRailLateralRateLeft, K::kClosed, -rate, rate, "m/s"}, left.lateral_rate},
      {{F::kRailVerticalRateLeft, K::kClosed, -rate, rate, "m/s"}, left.vertical_rate},
      {{F::kRailRollRateLeft, K::kClosed, -rate, rate, "rad/s"}, left.roll_rate},
      {{F::kRailLateralRight, K::kClosed, -offset, offset, "m"}, right.lateral},
      {{F::kRailVerticalRight, K::kClosed, -offset, offset, "m"}, right.vertical},
      {{F::kRailRollRight, K::kClosed, -kMaxRailRoll, kMaxRailRoll, "rad"}, right.roll},
      {{F::kRailLateralRateRight, K::kClosed, -rate, rate, "m/s"}, right.lateral_rate},
      {{F::kRailVerticalRateRight, K::kClosed, -rate, rate, "m/s"}, right.vertical_rate},
      {{F::kRailRollRateRight, K::kClosed, -rate, rate, "rad/s"}, right.roll_rate},
  };
  for (const auto& f : fields)
    if (!keeps(f.rule, f.value)) return QueryViolation{f.rule, f.value};
  return std::nullopt;
}

const char* query_field_name(QueryField field) {
  switch (field) {
    case QueryField::kPoseY: return "pose.y";
    case QueryField::kPoseZ: return "pose.z";
    case QueryField::kPoseRoll: return "pose.roll";
    case QueryField::kPoseYaw: return "pose.yaw";
    case QueryField::kPoseX: return "pose.x";
    case QueryField::kYDot: return "y_dot";
    case QueryField::kZDot: return "z_dot";
    case QueryField::kRollDot: return "roll_dot";
    case QueryField::kYawDot: return "yaw_dot";
    case QueryField::kSpinRate: return "spin_rate";
    case QueryField::kSpeed: return "speed";
    case QueryField::kNormalLoadLeft: return "normal_load[0] (left)";
    case QueryField::kNormalLoadRight: return "normal_load[1] (right)";
    case QueryField::kSecondNormalLoadLeft: return "second_normal_load[0] (left)";
    case QueryField::kSecondNormalLoadRight: return "second_normal_load[1] (right)";
    case QueryField::kTrackedSWheelLeft: return "tracked_s_wheel[0] (left)";
    case QueryField::kTrackedSWheelRight: return "tracked_s_wheel[1] (right)";
    case QueryField::kSecondTrackedSWheelLeft: return "second_tracked_s_wheel[0] (left)";
    case QueryField::kSecondTrackedSWheelRight: return "second_tracked_s_wheel[1] (right)";
    case QueryField::kFormulation: return "formulation";
    case QueryField::kShearModulus: return "material.shear_modulus";
    case QueryField::kPoissonRatio: return "material.poisson_ratio";
    case QueryField::kFriction: return "material.friction";
    case QueryField::kFastsimElements: return "fastsim_elements";
    case QueryField::kFastsimStrips: return "fastsim_strips";
    case QueryField::kRailLateralLeft: return "rail_offsets[0].lateral (left)";
    case QueryField::kRailVerticalLeft: return "rail_offsets[0].vertical (left)";
    case QueryField::kRailRollLeft: return "rail_offsets[0].roll (left)";
    case QueryField::kRailLateralRateLeft: return "rail_offsets[0].lateral_rate (left)";
    case QueryField::kRailVerticalRateLeft: return "rail_offsets[0].vertical_rate (left)";
    case QueryField::kRailRollRateLeft: return "rail_offsets[0].roll_rate (left)";
    case QueryField::kRailLateralRight: return "rail_offsets[1].lateral (right)";
    case QueryField::kRailVerticalRight: return "rail_offsets[1].vertical (right)";
    case QueryField::kRailRollRight: return "rail_offsets[1].roll (right)";
    case QueryField::kRailLateralRateRight: return "rail_offsets[1].lateral_rate (right)";
    case QueryField::kRailVerticalRateRight: return "rail_offsets[1].vertical_rate (right)";
    case QueryField::kRailRollRateRight: return "rail_offsets[1].roll_rate (right)";
  }
  return "?";
}

std::string query_rule_breach(const QueryViolation& violation) {
  const QueryRule& rule = violation.rule;
  const double v = violation.value;
  const std::string unit =
      *rule.unit == '\0' ? "" : std::string(" ") + (std::strcmp(rule.unit, "-") == 0 ? "[-]" : rule.unit);
  auto interval = [&](const char* open, double low, const char* close) {
    return "is outside " + (open + number_text(low) + ", " + number_text(rule.high) + close) + unit;
  };
  switch (rule.kind) {
    case QueryRuleKind::kFinite: return "is not a finite number";
    case QueryRuleKind::kClosed:
    case QueryRuleKind::kNanOrClosed:
    case QueryRuleKind::kCount:
      if (std::isinf(v) || (std::isnan(v) && rule.kind == QueryRuleKind::kClosed)) return "is not a finite number";
      return interval("[", rule.low, "]");
    case QueryRuleKind::kOpen:
      if (!std::isfinite(v)) return "is not a finite number";
      return interval("(", rule.low, ")");
    case QueryRuleKind::kPositiveAtMost:
      if (!std::isfinite(v)) return "is not a finite number";
      if (v > rule.high) return interval("(", 0.0, "]");
      return "is not positive";
  }
  return "is invalid";
}

void validate_contact_query(const ContactQuery& q) {
  const std::optional<QueryViolation> violation = find_query_violation(q);
  if (!violation) return;
  const QueryRule& rule = violation->rule;
  std::string msg = std::string("contact query: ") + query_field_name(rule.field);
  if (*rule.unit) msg += std::string(" [") + rule.unit + "]";
  msg += " = " + number_text(violation->value, kDigits) + " " + library_rule_text(rule, violation->value);
  throw std::invalid_argument(msg);
}

}  // namespace wrc
