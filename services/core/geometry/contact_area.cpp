// SPDX-License-Identifier: Apache-2.0
#include "core/geometry/contact_area.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "core/numerics/brent.hpp"

namespace wrc {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Largest Newton step along the normal [m]: keeps the iteration near E on strongly curved parts.
constexpr double kMaxNewtonStep = 5e-3;
constexpr int kMaxNewtonIterations = 60;

struct ValueSlope {
  double value;  // NaN when the surface is missing there
  double slope;  // d(value)/d(lambda)
};

// The root of g(lambda) nearest to lambda = 0 (Newton from 0, switching to Brent as soon as two
// iterates bracket a root). NaN when the surface is missing or no root lies within max_lambda.
template <class G>
double nearest_root(G&& g, double tolerance, double max_lambda) {
  double lambda = 0;
  ValueSlope v = g(lambda);
  if (std::isnan(v.value)) return kNaN;
  for (int iter = 0; iter < kMaxNewtonIterations; ++iter) {
    if (v.value == 0) return lambda;
    double step;
    if (v.slope != 0 && std::isfinite(v.slope)) {
      step = -v.value / v.slope;
    } else {
      step = kMaxNewtonStep * 1e-3;  // flat: probe upwards
    }
    step = std::clamp(step, -kMaxNewtonStep, kMaxNewtonStep);
    ValueSlope next{kNaN, kNaN};
    double candidate = lambda;
    for (int halving = 0; halving < 40; ++halving) {
      candidate = lambda + step;
      if (std::fabs(candidate) > max_lambda) return kNaN;
      next = g(candidate);
      if (!std::isnan(next.value)) break;
      step *= 0.5;
    }
    if (std::isnan(next.value)) return kNaN;
    if ((next.value > 0) != (v.value > 0) && next.value != 0) {
      auto value = [&](double l) { return g(l).value; };
      const RootResult r = brent_root(value, lambda, candidate, v.value, next.value, tolerance);
      // NaN stands for a missing surface; a root not located to the tolerance is an error.
      require_converged(r, "contact area: surface along the normal line");
      return std::isfinite(r.x) && !std::isnan(r.fx) ? r.x : kNaN;
    }
    lambda = candidate;
    v = next;
    if (std::fabs(step) < tolerance) return lambda;
  }
  return kNaN;
}

// Wheel and rail surfaces of one placed wheel, intersected with lines along the common normal.
class NormalLineIntersector {
 public:
  NormalLineIntersector(const WheelsetGeometry& geometry, const ContactArea& area, const ContactAreaOptions& options)
      : wheel_(geometry.wheel_profile()),
        rail_(geometry.rail(area.side)),
        area_(area),
        sigma_(side_sign(area.side)),
        taping_(geometry.track().taping_half_distance()),
        r0_(geometry.track().nominal_radius),
        tolerance_(options.root_tolerance),
        max_lambda_(options.max_normal_distance) {
    const double cpsi = std::cos(area.pose.yaw), spsi = std::sin(area.pose.yaw);
    const double cphi = std::cos(area.pose.roll), sphi = std::sin(area.pose.roll);
    Eigen::Matrix3d a;  // body to track: Rz(yaw) * Rx(roll)
    a << cpsi, -spsi * cphi, spsi * sphi,
         spsi, cpsi * cphi, -cpsi * sphi,
         0.0, sphi, cphi;
    to_body_ = a.transpose();
    centre_ = Eigen::Vector3d(area.pose.x, area.pose.y, area.pose.z);
    normal_body_ = to_body_ * area.normal;
  }

  double distance(double xi, double eta) const {
    const Eigen::Vector3d q = area_.point(xi, eta);
    const double lambda_rail = rail_root(q);
    if (std::isnan(lambda_rail)) return kNaN;
    const double lambda_wheel = wheel_root(q);
    if (std::isnan(lambda_wheel)) return kNaN;
    return lambda_wheel - lambda_rail;
  }

 private:
  // Height of the line above the rail surface: > 0 above the rail.
  double rail_root(const Eigen::Vector3d& q) const {
    const Eigen::Vector3d& n = area_.normal;
    auto g = [&](double lambda) -> ValueSlope {
      const RailSample r = rail_.at(q.y() + lambda * n.y());
      if (!r.valid) return {kNaN, kNaN};
      return {q.z() + lambda * n.z() - r.z, n.z() - r.slope * n.y()};
    };
    return nearest_root(g, tolerance_, max_lambda_);
  }

  // Distance of the line point from the axle minus the wheel radius there: > 0 outside the wheel.
  double wheel_root(const Eigen::Vector3d& q) const {
    const Eigen::Vector3d qb = to_body_ * (q - centre_);
    const Eigen::Vector3d& nb = normal_body_;
    auto g = [&](double lambda) -> ValueSlope {
      const Eigen::Vector3d b = qb + lambda * nb;
      const double s = sigma_ * b.y() - taping_;
      if (!(s >= wheel_.lower() && s <= wheel_.upper())) return {kNaN, kNaN};
      const ProfileSample f = wheel_.evaluate(s);
      const double rho = std::hypot(b.x(), b.z());
      const double radial_slope = rho > 0 ? (b.x() * nb.x() + b.z() * nb.z()) / rho : 0.0;
      return {rho - (r0_ + f.height), radial_slope - f.slope * sigma_ * nb.y()};
    };
    return nearest_root(g, tolerance_, max_lambda_);
  }

  const Profile& wheel_;
  const PlacedRail& rail_;
  const ContactArea& area_;
  double sigma_, taping_, r0_, tolerance_, max_lambda_;
  Eigen::Matrix3d to_body_;
  Eigen::Vector3d centre_;
  Eigen::Vector3d normal_body_;
};

void check_options(const ContactAreaOptions& o) {
  std::ostringstream msg;
  if (o.n_xi < 2 || o.n_eta < 2) {
    msg << "contact area: at least 2 grid nodes per direction are needed (got " << o.n_xi << " x " << o.n_eta << ")";
  } else if (!(o.half_width_xi > 0 && std::isfinite(o.half_width_xi)) ||
             !(o.half_width_eta > 0 && std::isfinite(o.half_width_eta))) {
    msg << "contact area: grid half widths must be positive and finite (got " << o.half_width_xi << ", "
        << o.half_width_eta << " m)";
  } else if (!(o.root_tolerance > 0) || !(o.max_normal_distance > 0)) {
    msg << "contact area: root tolerance and max normal distance must be positive";
  } else {
    return;
  }
  throw std::invalid_argument(msg.str());
}

std::vector<double> uniform(double half_width, int n) {
  std::vector<double> v(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) v[static_cast<size_t>(i)] = -half_width + 2 * half_width * i / (n - 1.0);
  if (n % 2 == 1) v[static_cast<size_t>(n / 2)] = 0.0;  // exactly on P
  return v;
}

// One run of consecutive nodes below eps0 along a grid line, with interpolated end coordinates.
struct Run {
  size_t first, last;  // node indices along the line
  double lower, upper; // interpolated coordinates of the ends [m]
  bool truncated;      // an end lies on the grid border or next to a missing node
};

// Crossing of eps0 between node `out` (>= eps0) and node `in` (< eps0), adjacent on one line:
// quadratic interpolation through these two nodes and a third one (the next node beyond `in`, else
// the one beyond `out`), linear when no third node exists or the parabola has no crossing between
// the two nodes. Exact for a gap that is quadratic along the line.
template <class V>
double crossing(V&& value, const std::vector<double>& coord, size_t out, size_t in, double eps0) {
  const size_t n = coord.size();
  const double x0 = coord[out], x1 = coord[in];
  const double f0 = value(out) - eps0, f1 = value(in) - eps0;
  const double linear = x0 + (x1 - x0) * f0 / (f0 - f1);
  size_t third = n;  // none
  if (in > out ? in + 1 < n : in > 0) third = in > out ? in + 1 : in - 1;
  if (third == n || std::isnan(value(third))) {
    if (out > in ? out + 1 < n : out > 0) third = out > in ? out + 1 : out - 1;
    else return linear;
  }
  const double x2 = coord[third], f2 = value(third) - eps0;
  if (std::isnan(f2)) return linear;
  // Newton form f(x) = f0 + c1 (x - x0) + c2 (x - x0)(x - x1).
  const double c1 = (f1 - f0) / (x1 - x0);
  const double c2 = ((f2 - f1) / (x2 - x1) - c1) / (x2 - x0);
  // In t = x - x0: c2 t^2 + (c1 - c2 (x1 - x0)) t + f0 = 0.
  const double qa = c2, qb = c1 - c2 * (x1 - x0), qc = f0;
  const double lo = std::min(x0, x1), hi = std::max(x0, x1);
  if (std::fabs(qa) * (hi - lo) < 1e-12 * std::fabs(qb)) return linear;
  const double disc = qb * qb - 4 * qa * qc;
  if (disc < 0) return linear;
  // Numerically stable pair of roots.
  const double qq = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
  const double roots[2] = {qq != 0 ? qc / qq : 0.0, qq / qa};
  for (double t : roots) {
    const double x = x0 + t;
    if (x >= lo && x <= hi) return x;
  }
  return linear;
}

// Runs of below-threshold nodes along one line; value(k) is the distance at node k, coord the
// node coordinates.
template <class V>
std::vector<Run> runs_along(V&& value, const std::vector<double>& coord, double eps0) {
  std::vector<Run> runs;
  const size_t n = coord.size();
  auto below = [&](size_t k) { const double d = value(k); return d < eps0; };  // false for NaN
  size_t k = 0;
  while (k < n) {
    if (!below(k)) {
      ++k;
      continue;
    }
    Run r{k, k, coord[k], coord[k], false};
    while (r.last + 1 < n && below(r.last + 1)) ++r.last;
    if (r.first > 0 && !std::isnan(value(r.first - 1))) {
      r.lower = crossing(value, coord, r.first - 1, r.first, eps0);
    } else {
      r.truncated = true;
    }
    if (r.last + 1 < n && !std::isnan(value(r.last + 1))) {
      r.upper = crossing(value, coord, r.last + 1, r.last, eps0);
    } else {
      r.truncated = true;
    }
    runs.push_back(r);
    k = r.last + 1;
  }
  return runs;
}

// Connected components of the nodes below eps0 (4-neighbour flood fill): label[k] the component
// of node k (-1: not below eps0); returns their number.
int label_components(const std::vector<double>& distance, size_t nx, size_t ny, double eps0, std::vector<int>& label) {
  label.assign(nx * ny, -1);
  std::vector<size_t> stack;
  int count = 0;
  for (size_t start = 0; start < nx * ny; ++start) {
    if (!(distance[start] < eps0) || label[start] >= 0) continue;
    label[start] = count;
    stack.push_back(start);
    while (!stack.empty()) {
      const size_t k = stack.back();
      stack.pop_back();
      const size_t i = k % nx, j = k / nx;
      const size_t neighbours[4] = {i > 0 ? k - 1 : k, i + 1 < nx ? k + 1 : k, j > 0 ? k - nx : k,
                                    j + 1 < ny ? k + nx : k};
      for (size_t m : neighbours) {
        if (m != k && label[m] < 0 && distance[m] < eps0) {
          label[m] = count;
          stack.push_back(m);
        }
      }
    }
    ++count;
  }
  return count;
}

// One patch per component with its node count and least distance, extents still empty.
std::vector<ContactAreaPatch> count_patches(const std::vector<double>& distance, const std::vector<int>& label,
                                            int count) {
  std::vector<ContactAreaPatch> patches(static_cast<size_t>(count));
  const double inf = std::numeric_limits<double>::infinity();
  for (auto& p : patches) {
    p.xi_min = p.eta_min = p.min_distance = inf;
    p.xi_max = p.eta_max = -inf;
  }
  for (size_t k = 0; k < distance.size(); ++k) {
    if (label[k] < 0) continue;
    ContactAreaPatch& p = patches[static_cast<size_t>(label[k])];
    ++p.nodes;
    p.min_distance = std::min(p.min_distance, distance[k]);
  }
  return patches;
}

// Columns (fixed xi): chord lengths give area, eta extent and moments.
void add_columns(const ContactAreaGrid& grid, double eps0, const std::vector<int>& label,
                 std::vector<ContactAreaPatch>& patches, std::vector<double>& moment_xi,
                 std::vector<double>& moment_eta) {
  const size_t nx = grid.xi.size();
  const double h_xi = (grid.xi.back() - grid.xi.front()) / static_cast<double>(nx - 1);
  for (size_t i = 0; i < nx; ++i) {
    auto value = [&](size_t j) { return grid.distance[j * nx + i]; };
    for (const Run& r : runs_along(value, grid.eta, eps0)) {
      const size_t id = static_cast<size_t>(label[r.first * nx + i]);
      ContactAreaPatch& p = patches[id];
      const double length = r.upper - r.lower;
      p.area += h_xi * length;
      moment_xi[id] += h_xi * length * grid.xi[i];
      moment_eta[id] += h_xi * 0.5 * (r.upper * r.upper - r.lower * r.lower);
      p.eta_min = std::min(p.eta_min, r.lower);
      p.eta_max = std::max(p.eta_max, r.upper);
      if (r.truncated || i == 0 || i + 1 == nx) p.truncated = true;
    }
  }
}

// Rows (fixed eta): the xi extent.
void add_rows(const ContactAreaGrid& grid, double eps0, const std::vector<int>& label,
              std::vector<ContactAreaPatch>& patches) {
  const size_t nx = grid.xi.size(), ny = grid.eta.size();
  for (size_t j = 0; j < ny; ++j) {
    auto value = [&](size_t i) { return grid.distance[j * nx + i]; };
    for (const Run& r : runs_along(value, grid.xi, eps0)) {
      ContactAreaPatch& p = patches[static_cast<size_t>(label[j * nx + r.first])];
      p.xi_min = std::min(p.xi_min, r.lower);
      p.xi_max = std::max(p.xi_max, r.upper);
      if (r.truncated || j == 0 || j + 1 == ny) p.truncated = true;
    }
  }
}

// The patches' centroids, and the whole area's size, extent and centroid from its patches.
void add_totals(std::vector<ContactAreaPatch>& patches, const std::vector<double>& moment_xi,
                const std::vector<double>& moment_eta, ContactAreaSummary& out) {
  const double inf = std::numeric_limits<double>::infinity();
  double total_xi = 0, total_eta = 0;
  out.xi_min = out.eta_min = inf;
  out.xi_max = out.eta_max = -inf;
  for (size_t id = 0; id < patches.size(); ++id) {
    ContactAreaPatch& p = patches[id];
    if (p.area > 0) {
      p.xi_centroid = moment_xi[id] / p.area;
      p.eta_centroid = moment_eta[id] / p.area;
    }
    out.area += p.area;
    total_xi += moment_xi[id];
    total_eta += moment_eta[id];
    out.xi_min = std::min(out.xi_min, p.xi_min);
    out.xi_max = std::max(out.xi_max, p.xi_max);
    out.eta_min = std::min(out.eta_min, p.eta_min);
    out.eta_max = std::max(out.eta_max, p.eta_max);
    out.truncated = out.truncated || p.truncated;
  }
  if (out.area > 0) {
    out.xi_centroid = total_xi / out.area;
    out.eta_centroid = total_eta / out.area;
  }
}

}  // namespace

ContactAreaSummary ContactAreaGrid::summary(double eps0) const {
  const size_t nx = xi.size(), ny = eta.size();
  if (nx < 2 || ny < 2 || distance.size() != nx * ny)
    throw std::invalid_argument("contact area grid: needs at least 2 x 2 nodes and one distance per node");
  ContactAreaSummary out;
  out.eps0 = eps0;
  std::vector<int> label;
  const int count = label_components(distance, nx, ny, eps0, label);
  if (count == 0) return out;
  std::vector<ContactAreaPatch> patches = count_patches(distance, label, count);
  std::vector<double> moment_xi(patches.size(), 0.0), moment_eta(patches.size(), 0.0);
  add_columns(*this, eps0, label, patches, moment_xi, moment_eta);
  add_rows(*this, eps0, label, patches);
  add_totals(patches, moment_xi, moment_eta, out);
  std::sort(patches.begin(), patches.end(),
            [](const ContactAreaPatch& a, const ContactAreaPatch& b) { return a.eta_centroid < b.eta_centroid; });
  out.patches = std::move(patches);
  return out;
}

double normal_distance(const WheelsetGeometry& geometry, const ContactArea& area, double xi, double eta,
                       const ContactAreaOptions& options) {
  return NormalLineIntersector(geometry, area, options).distance(xi, eta);
}

ContactArea compute_contact_area(const WheelsetGeometry& geometry, WheelSide side, const WheelsetPose& pose,
                                 const ContactAreaOptions& options) {
  check_options(options);
  const ContactLocus locus = geometry.locus(side, pose);
  const std::vector<ContactPoint> points = find_potential_points(locus, options.search);
  const std::optional<ContactPoint> common = select_common_point(points);
  if (!common) {
    std::ostringstream msg;
    msg << "contact area: the " << side_name(side) << " wheel has no common point with its rail at y = " << pose.y
        << " m, roll = " << pose.roll << " rad, yaw = " << pose.yaw << " rad";
    throw std::runtime_error(msg.str());
  }

  ContactArea area;
  area.side = side;
  area.pose = pose;
  const double lift = common->distance;  // lower the wheelset by this to touch
  area.pose.z = pose.z - lift;
  area.common = *common;
  area.common.wheel_point.z() -= lift;
  area.common.distance = 0;
  area.origin = common->rail_point;
  area.normal = common->normal.normalized();
  const Eigen::Vector3d ex(1, 0, 0);
  area.t1 = (ex - ex.dot(area.normal) * area.normal).normalized();
  area.t2 = area.normal.cross(area.t1);

  for (const ContactPoint& p : points) {
    if (!p.is_minimum) continue;
    const Eigen::Vector3d r = p.rail_point - area.origin;
    area.minima.push_back({p.s, r.dot(area.t1), r.dot(area.t2), p.distance - lift});
  }

  area.grid.xi = uniform(options.half_width_xi, options.n_xi);
  area.grid.eta = uniform(options.half_width_eta, options.n_eta);
  area.grid.distance.resize(area.grid.xi.size() * area.grid.eta.size());
  const NormalLineIntersector intersector(geometry, area, options);
  for (size_t j = 0; j < area.grid.eta.size(); ++j)
    for (size_t i = 0; i < area.grid.xi.size(); ++i)
      area.grid.distance[j * area.grid.xi.size() + i] = intersector.distance(area.grid.xi[i], area.grid.eta[j]);
  return area;
}

std::vector<LocusDistanceSample> sample_locus_distance(const ContactLocus& locus, double common_distance, int n) {
  if (n < 2) throw std::invalid_argument("sample_locus_distance: at least 2 samples are needed");
  std::vector<LocusDistanceSample> out(static_cast<size_t>(n));
  const double lo = locus.s_lower(), hi = locus.s_upper();
  for (int k = 0; k < n; ++k) {
    const LocusPoint p = locus.at(lo + (hi - lo) * k / (n - 1.0));
    LocusDistanceSample& o = out[static_cast<size_t>(k)];
    o.s = p.s;
    o.y = p.wheel.y();
    o.distance = p.over_rail ? p.distance - common_distance : kNaN;
  }
  return out;
}

}  // namespace wrc
