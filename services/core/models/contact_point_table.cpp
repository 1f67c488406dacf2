// SPDX-License-Identifier: Apache-2.0
#include "core/models/contact_point_table.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/geometry/contact_point_fields.hpp"
#include "core/geometry/rigid_wheelset.hpp"
#include "core/model_interface/contact_model.hpp"
#include "core/model_interface/jump_transition.hpp"
#include "core/models/flange_climb.hpp"
#include "core/models/jump_transitions.hpp"
#include "core/models/one_point_model.hpp"
#include "core/models/wheel_constraint.hpp"

namespace wrc {
namespace {

// The table's fields: the contact point's (ContactPointField order), then the distance's two.
enum Field {
  kMonotoneFields = kContactPointFieldCount,  // the point's: monotone slopes in y, monotone Hermite in delta
  kDistance0 = kMonotoneFields,  // distance at z = 0: exact y slope, Hermite in delta with kDistanceRoll
  kDistanceRoll,              // d distance / droll (exact at the nodes): monotone slopes in y
  kFieldCount
};
constexpr int kMaxNodes = 9;  // roll_points and yaw_points (InterpolationGrid::validate())
// The other point in a band is the minimum within this of the previous node's other point in s
// [m]: from node to node (1/6 mm) it moves by up to 1.05 mm on S1002/UIC60 (fastest near a band's
// end, towards a fold), while the two points of a jump lie 9 mm or more apart.
constexpr double kFollowShift = 3e-3;

// Monotone (Fritsch-Carlson) slopes of f sampled at the increasing nodes x: at an interior node
// the weighted harmonic mean of the neighbouring secants (0 where they differ in sign; Fritsch and
// Butland's weights for unequal cells), at the ends the three-point formula limited to keep the
// shape. Exact for linear functions; no overshoot at a jump.
void monotone_slopes(const double* f, size_t stride, const double* x, int n, double* d) {
  auto width = [&](int i) { return x[i + 1] - x[i]; };
  auto secant = [&](int i) { return (f[(i + 1) * stride] - f[i * stride]) / width(i); };
  if (n == 2) {
    d[0] = d[stride] = secant(0);
    return;
  }
  for (int i = 1; i < n - 1; ++i) {
    const double a = secant(i - 1), b = secant(i), ha = width(i - 1), hb = width(i);
    d[i * stride] = a * b > 0 ? 3.0 * (ha + hb) / ((2.0 * hb + ha) / a + (hb + 2.0 * ha) / b) : 0.0;
  }
  auto end = [](double near, double far, double h_near, double h_far) {
    double s = ((2.0 * h_near + h_far) * near - h_near * far) / (h_near + h_far);
    if (s * near <= 0) return 0.0;
    if (near * far <= 0 && std::fabs(s) > 3.0 * std::fabs(near)) s = 3.0 * near;
    return s;
  };
  d[0] = end(secant(0), secant(1), width(0), width(1));
  d[(n - 1) * stride] = end(secant(n - 2), secant(n - 3), width(n - 2), width(n - 3));
}

// Cubic Hermite basis on a cell of length h at local t in [0, 1]: weights of f0, d0, f1, d1 for the
// value (w) and for the derivative along the cell (dw, per unit length).
struct HermiteBasis {
  double w[4];
  double dw[4];
  HermiteBasis(double t, double h) {
    const double t2 = t * t, t3 = t2 * t;
    w[0] = 2 * t3 - 3 * t2 + 1;
    w[1] = (t3 - 2 * t2 + t) * h;
    w[2] = -2 * t3 + 3 * t2;
    w[3] = (t3 - t2) * h;
    dw[0] = (6 * t2 - 6 * t) / h;
    dw[1] = 3 * t2 - 4 * t + 1;
    dw[2] = (6 * t - 6 * t2) / h;
    dw[3] = 3 * t2 - 2 * t;
  }
  double value(double f0, double d0, double f1, double d1) const {
    return w[0] * f0 + w[1] * d0 + w[2] * f1 + w[3] * d1;
  }
  double derivative(double f0, double d0, double f1, double d1) const {
    return dw[0] * f0 + dw[1] * d0 + dw[2] * f1 + dw[3] * d1;
  }
};

[[noreturn]] void outside(const char* name, double value, const char* unit, double low, double high,
                          const char* what) {
  std::ostringstream msg;
  msg << "interp: " << name << " = " << value << " " << unit << " is outside the interpolation table [" << low << ", "
      << high << "] " << unit << what;
  throw OutsideModelError(msg.str());
}

// Lagrange weights L_k(x) and their derivatives through count equally spaced nodes on [-half, half].
void lagrange(double x, int count, double half, double* l, double* dl) {
  double nodes[kMaxNodes];
  for (int k = 0; k < count; ++k) nodes[k] = -half + 2.0 * half * k / (count - 1);
  for (int k = 0; k < count; ++k) {
    double value = 1.0, derivative = 0.0;
    for (int m = 0; m < count; ++m) {
      if (m == k) continue;
      const double denom = nodes[k] - nodes[m];
      derivative = derivative * (x - nodes[m]) / denom + value / denom;
      value *= (x - nodes[m]) / denom;
    }
    l[k] = value;
    dl[k] = derivative;
  }
}

// The y nodes: the equally spaced ones, less those within a quarter cell of a jump's band end, and
// the ends of every band (ends closer than 0.1 um, one jump's band at neighbouring yaw nodes, are
// one node).
std::vector<double> y_nodes_around(const std::vector<double>& uniform, const std::vector<JumpTransition>& jumps) {
  const double keep_off = 0.25 * (uniform[1] - uniform[0]);
  std::vector<double> nodes;
  for (double y : uniform) {
    bool kept = true;
    for (const JumpTransition& t : jumps)
      kept = kept && std::fabs(y - t.y_low) > keep_off && std::fabs(y - t.y_high) > keep_off;
    if (kept) nodes.push_back(y);
  }
  for (const JumpTransition& t : jumps) {
    nodes.push_back(t.y_low);
    nodes.push_back(t.y_high);
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end(), [](double a, double b) { return b - a < 1e-7; }), nodes.end());
  return nodes;
}

// The node nearest to y.
int nearest_node(const std::vector<double>& nodes, double y) {
  int best = 0;
  for (int i = 1; i < static_cast<int>(nodes.size()); ++i)
    if (std::fabs(nodes[static_cast<size_t>(i)] - y) < std::fabs(nodes[static_cast<size_t>(best)] - y)) best = i;
  return best;
}

// The same pose with another roll.
WheelsetPose with_roll(double y, double z, double roll, double yaw) {
  WheelsetPose p;
  p.y = y;
  p.z = z;
  p.roll = roll;
  p.yaw = yaw;
  return p;
}

// The rigid wheelset at node (y, yaw), warm-started from near when given; a failure names the node.
RigidContact solve_node(const RigidWheelsetSolver& solver, double y, double yaw, const RigidContact* near) {
  try {
    return near ? solver.solve(y, yaw, *near) : solver.solve(y, yaw);
  } catch (const std::runtime_error& e) {
    std::ostringstream msg;
    msg << "interp table node y = " << y << " m, yaw = " << yaw << " rad: " << e.what() << " (reduce y_max)";
    throw ContactConfigurationError(msg.str());
  }
}

}  // namespace

static_assert(kFieldCount == kContactPointFieldCount + 2, "ContactPointTable::kFields must match the field list");

ContactPointTable::ContactPointTable(const WheelsetGeometry& geometry, const ContactModelOptions& options)
    : grid_(options.interp) {
  options.validate();
  const double steepest = steepest_flange_point(geometry.wheel_profile());
  RigidSolverOptions rigid_options;
  rigid_options.search = options.search;
  rigid_options.all_potential_points = false;
  const RigidWheelsetSolver solver(geometry, rigid_options);

  // The rigid wheelset at the equally spaced nodes, and the jumps between them at every yaw node.
  std::vector<double> uniform(static_cast<size_t>(grid_.y_points));
  for (int i = 0; i < grid_.y_points; ++i) uniform[static_cast<size_t>(i)] = node(i, grid_.y_points, grid_.y_max);
  const std::vector<std::vector<RigidContact>> rigid_uniform = find_jumps(solver, options, uniform);
  // The y nodes, and the jumps' bands on them.
  place_bands(uniform);

  const int nk = grid_.yaw_points, ny = y_node_count();
  roll_.assign(static_cast<size_t>(nk) * static_cast<size_t>(ny) * 2, 0.0);
  for (auto& v : values_) v.assign(offset(nk, 0, 0), 0.0);
  for (int k = 0; k < nk; ++k) {
    // Per yaw node: the node values, their slopes in y, and the other point in each band.
    tabulate_nodes(geometry, solver, options.search, steepest, k, rigid_uniform[static_cast<size_t>(k)]);
    add_monotone_slopes(k);
    follow_other_points(geometry, options.search, k);
  }
}

std::vector<std::vector<RigidContact>> ContactPointTable::find_jumps(const RigidWheelsetSolver& solver,
                                                                     const ContactModelOptions& options,
                                                                     const std::vector<double>& uniform) {
  const int nk = grid_.yaw_points;
  std::vector<std::vector<RigidContact>> rigid_uniform(static_cast<size_t>(nk));
  JumpTransitionOptions jump_options;
  jump_options.transition = grid_.transition;
  jump_options.transition_load = grid_.transition_load;
  jump_options.lateral_curvature_floor = options.lateral_curvature_floor;
  jump_options.search = options.search;
  for (int k = 0; k < nk; ++k) {
    std::vector<RigidContact>& line = rigid_uniform[static_cast<size_t>(k)];
    for (double y : uniform) line.push_back(solve_node(solver, y, yaw_node(k), line.empty() ? nullptr : &line.back()));
    try {
      // A folded jump keeps the one-cell ramp: a smooth maximum of two branches that end within
      // the load-sharing range would share the load over the fold's height, a tenth of the
      // approach, and give the centre a rolling-radius difference no other model has
      // (docs/contact-mechanics.md).
      for (const JumpTransition& found : find_jump_transitions(solver, line, yaw_node(k), jump_options)) {
        if (found.folded) continue;
        transitions_.push_back(found);
        transition_yaw_node_.push_back(k);
      }
    } catch (const std::runtime_error& e) {
      throw ContactConfigurationError(std::string("interp table, following a jump's branch: ") + e.what() +
                                      " (reduce y_max)");
    }
  }
  return rigid_uniform;
}

void ContactPointTable::place_bands(const std::vector<double>& uniform) {
  y_nodes_ = y_nodes_around(uniform, transitions_);
  for (size_t n = 0; n < transitions_.size(); ++n) {
    Band band;
    band.yaw_node = transition_yaw_node_[n];
    band.low = nearest_node(y_nodes_, transitions_[n].y_low);
    band.high = nearest_node(y_nodes_, transitions_[n].y_high);
    double unused;
    locate_y(transitions_[n].y, band.jump_cell, unused);
    bands_.push_back(band);
  }
}

void ContactPointTable::tabulate_nodes(const WheelsetGeometry& geometry, const RigidWheelsetSolver& solver,
                                       const PotentialPointSearch& search, double steepest, int k,
                                       const std::vector<RigidContact>& line) {
  const double z_ref = geometry.track().nominal_radius;
  const int nr = grid_.roll_points, ny = y_node_count();
  const double yaw = yaw_node(k);
  RigidContact rigid;
  for (int i = 0; i < ny; ++i) {
    const double y = y_node(i);
    const auto same = std::find_if(line.begin(), line.end(), [y](const RigidContact& c) { return c.pose.y == y; });
    rigid = same != line.end() ? *same : solve_node(solver, y, yaw, i == 0 ? nullptr : &rigid);
    // Implicit differentiation of gap_L = gap_R = 0 at fixed yaw: dz + g_roll dphi = -g_y dy.
    const Eigen::Vector4d gl = vertical_gap_gradient(rigid.left(), rigid.pose);
    const Eigen::Vector4d gr = vertical_gap_gradient(rigid.right(), rigid.pose);
    const double roll_slope = -(gl[0] - gr[0]) / (gl[2] - gr[2]);
    roll_[index(k, i) * 2] = rigid.pose.roll;
    roll_[index(k, i) * 2 + 1] = roll_slope;
    for (WheelSide side : {WheelSide::kLeft, WheelSide::kRight}) {
      std::vector<double>& v = values_[static_cast<int>(side)];
      for (int j = 0; j < nr; ++j) {
        const WheelsetPose pose = with_roll(y, z_ref, rigid.pose.roll + roll_offset(j), yaw);
        ContactPoint p;
        try {
          p = require_common_point(geometry, side, pose, search, steepest);
        } catch (const ContactConfigurationError& e) {
          throw ContactConfigurationError(std::string("interp table node: ") + e.what() +
                                          " (reduce the table's y_max, roll_band or yaw_max)");
        }
        const Eigen::Vector4d g = vertical_gap_gradient(p, pose);
        const ContactPointFields fields = contact_point_fields(p, pose);
        double* node = &v[offset(k, j, i)];
        std::copy(fields.begin(), fields.end(), node);
        node[kDistance0] = p.distance - z_ref;
        node[kDistanceRoll] = g[2];
        // The distance's exact slope along y at fixed delta (envelope gradient).
        node[kFields + kDistance0] = g[0] + g[2] * roll_slope;
      }
    }
  }
}

void ContactPointTable::add_monotone_slopes(int k) {
  const int nr = grid_.roll_points, ny = y_node_count();
  for (auto& v : values_) {
    for (int j = 0; j < nr; ++j) {
      for (int f = 0; f < kFields; ++f) {
        if (f == kDistance0) continue;
        double* first = &v[offset(k, j, 0)];
        monotone_slopes(first + f, 2 * kFields, y_nodes_.data(), ny, first + kFields + f);
      }
    }
  }
}

void ContactPointTable::follow_other_points(const WheelsetGeometry& geometry, const PotentialPointSearch& search,
                                            int k) {
  const double z_ref = geometry.track().nominal_radius;
  const int nr = grid_.roll_points;
  const double yaw = yaw_node(k);
  for (size_t n = 0; n < bands_.size(); ++n) {
    Band& band = bands_[n];
    if (band.yaw_node != k) continue;
    const WheelSide side = transitions_[n].side;
    const std::vector<double>& v = values_[static_cast<int>(side)];
    const int j = nr / 2;
    band.other.assign(static_cast<size_t>(band.high - band.low + 1) * kBandValues, 0.0);
    band.usable = true;
    for (int direction : {+1, -1}) {
      // Upwards the lower-y point continues, starting from its s at the jump cell's lower node.
      const int first = direction > 0 ? band.jump_cell + 1 : band.jump_cell;
      double s_near = v[offset(k, j, direction > 0 ? band.jump_cell : band.jump_cell + 1) + kPointS];
      for (int i = first; band.usable && i >= band.low && i <= band.high; i += direction) {
        const double roll = roll_[index(k, i) * 2], roll_slope = roll_[index(k, i) * 2 + 1];
        const WheelsetPose pose = with_roll(y_node(i), z_ref, roll, yaw);
        const double own_s = v[offset(k, j, i) + kPointS];
        const std::vector<ContactPoint> points = geometry.potential_points(side, pose, search);
        const ContactPoint* other = nullptr;
        for (const ContactPoint& p : points) {
          if (!p.is_minimum || std::fabs(p.s - own_s) < 1e-9 || std::fabs(p.s - s_near) >= kFollowShift) continue;
          if (!other || std::fabs(p.s - s_near) < std::fabs(other->s - s_near)) other = &p;
        }
        if (!other) {
          band.usable = false;  // folded away inside the band (at a coarser walk's resolution)
          break;
        }
        s_near = other->s;
        const Eigen::Vector4d g = vertical_gap_gradient(*other, pose);
        const ContactPointFields fields = contact_point_fields(*other, pose);
        double* o = &band.other[static_cast<size_t>(i - band.low) * kBandValues];
        std::copy(fields.begin(), fields.end(), o);
        o[kDistance0] = other->distance - z_ref;
        o[kDistanceRoll] = g[2];
        o[kFields] = g[0] + g[2] * roll_slope;
      }
    }
  }
}

const ContactPointTable::Band* ContactPointTable::band_at(int k, WheelSide side, int cell) const {
  for (size_t n = 0; n < bands_.size(); ++n) {
    const Band& b = bands_[n];
    if (b.usable && b.yaw_node == k && transitions_[n].side == side && cell >= b.low && cell < b.high) return &b;
  }
  return nullptr;
}

void ContactPointTable::blend_branches(const Band& band, const JumpTransition& jump, int k, WheelSide side, int cell,
                                       double y, double* f, double* fy, double (*branch)[kFields]) const {
  const std::vector<double>& v = values_[static_cast<int>(side)];
  const int j = grid_.roll_points / 2;
  const double y0 = y_node(cell), y1 = y_node(cell + 1), width = y1 - y0;
  const HermiteBasis basis(std::clamp((y - y0) / width, 0.0, 1.0), width);
  // The lower-y point (a) and the higher-y one (b) at a band node: the common point on its own
  // side of the jump, the other point (the continuation) on the far side. Each as (values, slope
  // of the distance along y).
  auto branch_at = [&](int i, bool upper) -> std::pair<const double*, double> {
    const bool own = upper ? i > band.jump_cell : i <= band.jump_cell;
    if (own) {
      const double* node = &v[offset(k, j, i)];
      return {node, node[kFields + kDistance0]};
    }
    const double* o = &band.other[static_cast<size_t>(i - band.low) * kBandValues];
    return {o, o[kFields]};
  };
  double value[2][kFields], dy[2][kFields];
  for (int b = 0; b < 2; ++b) {
    const auto [p0, s0] = branch_at(cell, b == 1);
    const auto [p1, s1] = branch_at(cell + 1, b == 1);
    // The distance: Hermite with the exact slopes; every other field linear along the branch.
    for (int q = 0; q < kFields; ++q) {
      if (q == kDistance0) {
        value[b][q] = basis.value(p0[q], s0, p1[q], s1);
        dy[b][q] = basis.derivative(p0[q], s0, p1[q], s1);
      } else {
        dy[b][q] = (p1[q] - p0[q]) / width;
        value[b][q] = p0[q] + dy[b][q] * (y - y0);
      }
    }
  }
  // The elastic gap: the smooth minimum of the two points' distances (the smooth maximum of their
  // touching heights -distance), the fields blended with the upper point's load share w.
  const SmoothMaximum m =
      smooth_maximum(-value[0][kDistance0], -value[1][kDistance0], jump.height_half_width);
  const double w = m.share;
  for (int q = 0; q < kFields; ++q) f[q] = value[0][q] + w * (value[1][q] - value[0][q]);
  f[kDistance0] = -m.value;
  // d/dy of the distance and of its roll derivative; d = (-D_b) - (-D_a), so dw/dy = share_slope
  // (D_a' - D_b').
  const double dw = m.share_slope * (dy[0][kDistance0] - dy[1][kDistance0]);
  fy[0] = dy[0][kDistance0] + w * (dy[1][kDistance0] - dy[0][kDistance0]);
  fy[1] = dy[0][kDistanceRoll] + w * (dy[1][kDistanceRoll] - dy[0][kDistanceRoll]) +
          dw * (value[1][kDistanceRoll] - value[0][kDistanceRoll]);
  for (int b = 0; b < 2; ++b) std::copy(value[b], value[b] + kFields, branch[b]);
}

void ContactPointTable::locate_y(double y, int& cell, double& t) const {
  const double low = y_nodes_.front(), high = y_nodes_.back(), slack = 1e-9 * (high - low);
  if (!(y >= low - slack && y <= high + slack)) outside("y", y, "m", low, high, "");
  const auto above = std::upper_bound(y_nodes_.begin(), y_nodes_.end(), y);
  cell = std::clamp(static_cast<int>(above - y_nodes_.begin()) - 1, 0, y_node_count() - 2);
  const double width = y_nodes_[static_cast<size_t>(cell) + 1] - y_nodes_[static_cast<size_t>(cell)];
  t = std::clamp((y - y_nodes_[static_cast<size_t>(cell)]) / width, 0.0, 1.0);
}

TableContact ContactPointTable::evaluate(WheelSide side, const WheelsetPose& pose) const {
  const int nr = grid_.roll_points, nk = grid_.yaw_points;
  int iy;
  double ty;
  locate_y(pose.y, iy, ty);
  if (!(std::fabs(pose.yaw) <= grid_.yaw_max * (1 + 1e-9)))
    outside("yaw", pose.yaw, "rad", -grid_.yaw_max, grid_.yaw_max, "");
  if (!(std::fabs(pose.roll) <= grid_.roll_max * (1 + 1e-9)))
    outside("roll", pose.roll, "rad", -grid_.roll_max, grid_.roll_max, " (InterpolationGrid::roll_max)");
  const HermiteBasis by(ty, y_node(iy + 1) - y_node(iy));
  double l[kMaxNodes], dl[kMaxNodes];
  lagrange(pose.yaw, nk, grid_.yaw_max, l, dl);

  // Rigid roll phi_r(y, yaw) and its partial derivatives.
  double roll_r = 0, roll_r_y = 0, roll_r_yaw = 0;
  for (int k = 0; k < nk; ++k) {
    const double* a = &roll_[index(k, iy) * 2];
    const double value = by.value(a[0], a[1], a[2], a[3]);
    roll_r += l[k] * value;
    roll_r_yaw += dl[k] * value;
    roll_r_y += l[k] * by.derivative(a[0], a[1], a[2], a[3]);
  }

  // Position in delta = roll - phi_r among the roll nodes; beyond the band the distance goes on
  // linearly from the edge node and the other fields are held there.
  const double delta = pose.roll - roll_r, band = grid_.roll_band, h_r = 2.0 * band / (nr - 1);
  const double u = std::clamp((delta + band) / h_r, 0.0, static_cast<double>(nr - 1));
  const int jr = std::min(static_cast<int>(std::floor(u)), nr - 2);
  const double tr = u - jr;
  const double beyond = delta - (-band + h_r * u);  // 0 inside the band
  const HermiteBasis br(tr, h_r);
  double roll_nodes[kMaxNodes];
  for (int j = 0; j < nr; ++j) roll_nodes[j] = roll_offset(j);

  const std::vector<double>& v = values_[static_cast<int>(side)];
  ContactPointFields out{};
  double dist = 0, dist_delta = 0, dist_y = 0, dist_yaw = 0;
  // In a band: per branch, the sum over yaw nodes of l_k (branch field - blended field) on the
  // manifold line (0 at a yaw node without a band, whose one point is both branches there).
  bool in_band = false;
  double branch_shift[2][kFields] = {};
  for (int k = 0; k < nk; ++k) {
    // The y interpolants at every roll node of yaw node k (value; for the distance fields also d/dy).
    // In a jump's band the manifold's line (delta = 0) is the two points' smooth blend.
    const Band* jump_band = band_at(k, side, iy);
    double f[kMaxNodes][kFields], fy[kMaxNodes][2];
    for (int j = 0; j < nr; ++j) {
      const double* n0 = &v[offset(k, j, iy)];
      const double* n1 = n0 + 2 * kFields;
      for (int q = 0; q < kFields; ++q) f[j][q] = by.value(n0[q], n0[kFields + q], n1[q], n1[kFields + q]);
      if (jump_band && j == nr / 2) {
        double branch[2][kFields];
        blend_branches(*jump_band, transitions_[static_cast<size_t>(jump_band - bands_.data())], k, side, iy, pose.y,
                       f[j], fy[j], branch);
        in_band = true;
        for (int b = 0; b < 2; ++b)
          for (int q = 0; q < kFields; ++q) branch_shift[b][q] += l[k] * (branch[b][q] - f[j][q]);
        continue;
      }
      for (int q = 0; q < 2; ++q) {
        const int field = kDistance0 + q;
        fy[j][q] = by.derivative(n0[field], n0[kFields + field], n1[field], n1[kFields + field]);
      }
    }
    // Distance: Hermite in delta with the roll derivative as slope, linear beyond the band.
    const double* a = f[jr];
    const double* b = f[jr + 1];
    double value = br.value(a[kDistance0], a[kDistanceRoll], b[kDistance0], b[kDistanceRoll]);
    double d_delta = br.derivative(a[kDistance0], a[kDistanceRoll], b[kDistance0], b[kDistanceRoll]);
    double d_y = br.value(fy[jr][0], fy[jr][1], fy[jr + 1][0], fy[jr + 1][1]);
    if (beyond != 0.0) {
      value += d_delta * beyond;
      d_y += br.derivative(fy[jr][0], fy[jr][1], fy[jr + 1][0], fy[jr + 1][1]) * beyond;
    }
    dist += l[k] * value;
    dist_yaw += dl[k] * value;
    dist_delta += l[k] * d_delta;
    dist_y += l[k] * d_y;
    // The other fields: monotone Hermite in delta over the roll nodes.
    for (int q = 0; q < kMonotoneFields; ++q) {
      double column[kMaxNodes], slopes[kMaxNodes];
      for (int j = 0; j < nr; ++j) column[j] = f[j][q];
      monotone_slopes(column, 1, roll_nodes, nr, slopes);
      out[q] += l[k] * br.value(column[jr], slopes[jr], column[jr + 1], slopes[jr + 1]);
    }
  }

  TableContact c;
  c.point = contact_point_from_fields(out, side, pose, dist + pose.z);
  // distance = z + D(y, roll - phi_r(y, yaw), yaw).
  c.gap_gradient = Eigen::Vector4d(dist_y - dist_delta * roll_r_y, 1.0, dist_delta, dist_yaw - dist_delta * roll_r_yaw);
  if (in_band) add_branches(branch_shift, side, pose, dist + pose.z, out, c);
  return c;
}

void ContactPointTable::add_branches(const double (*branch_shift)[kFields], WheelSide side, const WheelsetPose& pose,
                                     double distance, const ContactPointFields& blended, TableContact& c) const {
  // Each branch's point: the blended fields moved by the branch's shift on the manifold line.
  std::array<ContactPoint, 2> points;
  for (int b = 0; b < 2; ++b) {
    ContactPointFields fields = blended;
    for (int q = 0; q < kContactPointFieldCount; ++q) fields[static_cast<size_t>(q)] += branch_shift[b][q];
    points[static_cast<size_t>(b)] = contact_point_from_fields(fields, side, pose, distance + branch_shift[b][kDistance0]);
  }
  // The shares for which the branches' normals, weighted by them, incline as the blend's: the
  // normal forces share_k N cos(gamma) / cos(gamma_k) then add up to N along the blend's normal.
  auto inclination = [](const ContactPoint& p) { return p.normal.y() / p.normal.z(); };
  const double t0 = inclination(points[0]), t1 = inclination(points[1]);
  if (!(std::fabs(t1 - t0) > 1e-9)) return;
  const double share = std::clamp((inclination(c.point) - t0) / (t1 - t0), 0.0, 1.0);
  if (!(share > 0.0 && share < 1.0)) return;
  c.shared = true;
  c.branch_points = points;
  c.branch_shares = {1.0 - share, share};
  c.branch_inclinations = {t0, t1};
  c.inclination = inclination(c.point);
}

double ContactPointTable::rigid_roll(double y, double yaw) const {
  int iy;
  double ty;
  locate_y(y, iy, ty);
  if (!(std::fabs(yaw) <= grid_.yaw_max * (1 + 1e-9))) outside("yaw", yaw, "rad", -grid_.yaw_max, grid_.yaw_max, "");
  const HermiteBasis by(ty, y_node(iy + 1) - y_node(iy));
  double l[kMaxNodes], dl[kMaxNodes];
  lagrange(yaw, grid_.yaw_points, grid_.yaw_max, l, dl);
  double roll = 0;
  for (int k = 0; k < grid_.yaw_points; ++k) {
    const double* a = &roll_[index(k, iy) * 2];
    roll += l[k] * by.value(a[0], a[1], a[2], a[3]);
  }
  return roll;
}

double ContactPointTable::rigid_height(double y, double yaw) const {
  return -evaluate(WheelSide::kLeft, with_roll(y, 0.0, rigid_roll(y, yaw), yaw)).point.distance;
}

std::vector<double> ContactPointTable::data() const {
  std::vector<double> out{static_cast<double>(grid_.y_points), grid_.y_max,
                          static_cast<double>(grid_.roll_points), grid_.roll_band,
                          grid_.roll_max, static_cast<double>(grid_.yaw_points),
                          grid_.yaw_max, grid_.transition, grid_.transition_load};
  out.insert(out.end(), y_nodes_.begin(), y_nodes_.end());
  out.insert(out.end(), roll_.begin(), roll_.end());
  for (const auto& v : values_) out.insert(out.end(), v.begin(), v.end());
  for (size_t n = 0; n < bands_.size(); ++n) {
    out.insert(out.end(), {transitions_[n].height_half_width, static_cast<double>(bands_[n].usable)});
    out.insert(out.end(), bands_[n].other.begin(), bands_[n].other.end());
  }
  return out;
}

}  // namespace wrc
