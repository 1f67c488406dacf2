#include "contactd/model_hash.hpp"

#include <cstdint>
#include <cstring>
#include <vector>

#include "core/identity/sha256.hpp"
#include "core/models/interpolated_model.hpp"
#include "core/models/spline_model.hpp"

namespace wrc::contactd {
namespace {

// Appends value as 8 little-endian bytes.
void put(std::vector<unsigned char>& out, double value) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  for (int i = 0; i < 8; ++i) out.push_back(static_cast<unsigned char>(bits >> (8 * i)));
}

void put(std::vector<unsigned char>& out, const ContactPoint& p) {
  for (double v : {p.s, p.s_rail, p.theta, p.wheel_point.x(), p.wheel_point.y(), p.wheel_point.z(), p.rail_point.x(),
                   p.rail_point.y(), p.rail_point.z(), p.normal.x(), p.normal.y(), p.normal.z(), p.distance,
                   p.contact_angle, p.rolling_radius, p.wheel_curvature_lateral, p.wheel_curvature_rolling,
                   p.rail_curvature_lateral, p.rail_curvature_rolling, p.distance_curvature}) {
    put(out, v);
  }
}

std::string table_hash(const ContactPointTable& table) {
  const InterpolationGrid& g = table.grid();
  std::vector<unsigned char> data;
  for (double v : {static_cast<double>(g.y_points), g.y_max, static_cast<double>(g.roll_points), g.roll_max,
                   static_cast<double>(g.yaw_points), g.yaw_max, static_cast<double>(static_cast<int>(g.y_method))}) {
    put(data, v);
  }
  for (int i = 0; i < g.y_points; ++i) {
    for (int j = 0; j < g.roll_points; ++j) {
      for (int k = 0; k < g.yaw_points; ++k) {
        WheelsetPose pose;
        pose.y = table.y_node(i);
        pose.roll = table.roll_node(j);
        pose.yaw = table.yaw_node(k);
        for (WheelSide side : {WheelSide::kLeft, WheelSide::kRight}) put(data, table.at(side, pose));
      }
    }
  }
  return sha256_hex(data.data(), data.size());
}

}  // namespace

std::string model_hash(const ContactModel& model) {
  if (const auto* interp = dynamic_cast<const InterpolatedModel*>(&model)) return table_hash(interp->table());
  if (const auto* spline = dynamic_cast<const SplineModel*>(&model)) return spline->splines().data_hash();
  return "";
}

}  // namespace wrc::contactd
