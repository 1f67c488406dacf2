// SPDX-License-Identifier: Apache-2.0
#include "core/spline/spline_fit_options.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/numerics/number_text.hpp"
#include "core/spline/spline_fit_table.hpp"
#include "core/spline/spline_fields.hpp"
#include "core/spline/wheel_sample.hpp"

namespace wrc {
namespace {

[[noreturn]] void bad(const std::string& what) { throw std::invalid_argument("spline fit: " + what); }

std::string num(double v) { return exact_number_text(v); }

void require_positive(double v, const char* name, const char* unit) {
  if (!(v > 0.0) || !std::isfinite(v)) bad(std::string(name) + " = " + num(v) + " " + unit + " must be positive and finite");
}

}  // namespace

SplineFitOptions SplineFitOptions::paper_benchmark() {
  SplineFitOptions o;
  o.intervals = {15, 4, 1};
  o.degrees = {3, 3, 2};
  o.yaw_samples = 3;
  return o;
}

// Each scalar's rule is its table's (core/spline/spline_fit_table.cpp); what is left here are the
// triples, the breakpoints and the rules between members.
void SplineFitOptions::validate() const {
  try {
    validate_parameters(spline_fit_table(), *this);
  } catch (const std::invalid_argument& e) {
    bad(e.what());
  }
  if (!(y_min < y_max)) bad("the box in y [" + num(y_min) + ", " + num(y_max) + "] m must be increasing");
  const char* names[3] = {"y", "roll", "yaw"};
  for (int k = 0; k < 3; ++k) {
    if (intervals[k] < 1 || intervals[k] > 200)
      bad(std::string("knot intervals in ") + names[k] + " = " + std::to_string(intervals[k]) + " must be 1..200");
    if (degrees[k] < 0 || degrees[k] > 3)
      bad(std::string("degree in ") + names[k] + " = " + std::to_string(degrees[k]) + " must be 0..3");
  }
  if (!y_breakpoints.empty()) {
    if (y_breakpoints.size() < 2) bad("y_breakpoints needs at least 2 values");
    if (std::abs(y_breakpoints.front() - y_min) > 1e-12 || std::abs(y_breakpoints.back() - y_max) > 1e-12)
      bad("y_breakpoints must start at y_min = " + num(y_min) + " m and end at y_max = " + num(y_max) + " m");
    for (size_t i = 1; i < y_breakpoints.size(); ++i)
      if (!(y_breakpoints[i] > y_breakpoints[i - 1]))
        bad("y_breakpoints[" + std::to_string(i) + "] = " + num(y_breakpoints[i]) + " m is not above the previous one");
  }
  const int y_basis = (y_breakpoints.empty() ? intervals[0] : static_cast<int>(y_breakpoints.size()) - 1) + degrees[0];
  if ((y_max - y_min) / sample_step_y < 2.0 * y_basis)
    bad("sample_step_y = " + num(sample_step_y) + " m gives fewer than two samples per basis function in y");
  if (roll_samples < intervals[1] + degrees[1] || roll_samples > 101)
    bad("roll_samples = " + std::to_string(roll_samples) + " must be at least intervals + degree in roll (" +
        std::to_string(intervals[1] + degrees[1]) + ") and at most 101");
  if (yaw_samples < intervals[2] + degrees[2] || yaw_samples > 101)
    bad("yaw_samples = " + std::to_string(yaw_samples) + " must be at least intervals + degree in yaw (" +
        std::to_string(intervals[2] + degrees[2]) + ") and at most 101");
  require_positive(search.step, "search.step", "m");
  if (const double bytes = fit_memory_bytes(); !(bytes <= kMaxFitMemory)) {
    std::ostringstream msg;
    msg << "sample_step_y = " << shortest_number_text(sample_step_y) << " m (--sample-step) over the box y in ["
        << shortest_number_text(y_min) << ", " << shortest_number_text(y_max) << "] m (--box) with " << roll_samples << " x " << yaw_samples
        << " lines (--samples) needs about " << number_text(bytes / 1073741824.0, 3)
        << " GiB; a fit may take at most " << number_text(kMaxFitMemory / 1073741824.0, 3)
        << " GiB (a coarser step, a smaller box or fewer lines)";
    bad(msg.str());
  }
  if (threads < 0 || threads > 64) bad("threads = " + std::to_string(threads) + " must be 0..64");
}

std::array<int, 3> SplineFitOptions::parse_triple(const std::string& text, const std::string& what, int lo, int hi) {
  std::array<int, 3> out{};
  std::vector<std::string> parts;
  std::string part;
  for (char c : text + "x") {
    if (c == 'x' || c == 'X') {
      parts.push_back(part);
      part.clear();
    } else {
      part += c;
    }
  }
  if (parts.size() == 1) parts = {parts[0], parts[0], parts[0]};
  if (parts.size() != 3)
    throw std::invalid_argument(what + ": '" + text + "' is not of the form NxMxK (y, roll, yaw) or a single number");
  for (size_t k = 0; k < 3; ++k) {
    size_t used = 0;
    int v = 0;
    try {
      v = std::stoi(parts[k], &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != parts[k].size() || v < lo || v > hi)
      throw std::invalid_argument(what + ": '" + parts[k] + "' in '" + text + "' is not a whole number in [" +
                                  std::to_string(lo) + ", " + std::to_string(hi) + "]");
    out[k] = v;
  }
  return out;
}

double SplineFitOptions::fit_memory_bytes() const {
  // In doubles, so that no count overflows: (y_max - y_min) / sample_step_y may be anything.
  const double per_line = std::floor((y_max - y_min) / sample_step_y + 0.5) + 1.0;
  const double samples = per_line * roll_samples * yaw_samples;  // per wheel
  const double sample_bytes = static_cast<double>(sizeof(WheelSample));
  // Coefficients per function: a branch's basis in y reaches past its jumps at the same spacing,
  // at most twice its intervals (spline_geometry_fit.cpp).
  const int y_intervals = y_breakpoints.empty() ? intervals[0] : static_cast<int>(y_breakpoints.size()) - 1;
  const double coefficients = (2.0 * y_intervals + degrees[0]) * (intervals[1] + degrees[1]) * (intervals[2] + degrees[2]);
  const double band = (2.0 * degrees[0] + 1) * (2.0 * degrees[1] + 1) * (2.0 * degrees[2] + 1);
  constexpr double kFixed = 16.0 * 1048576.0;  // sampling threads' heaps and stacks, the profiles' tables
  return kFixed + samples * sample_bytes * (2.0 + kMaxFitBranches)  // grids of both wheels, continuations
         + samples * (kSplineFieldCount + 4) * 8.0                   // one branch's values, points, weight
         + coefficients * band * 16.0 + coefficients * kSplineFieldCount * 8.0;  // normal equations, solution
}

int SplineFitOptions::y_samples() const {
  return static_cast<int>(std::lround((y_max - y_min) / sample_step_y)) + 1;
}

std::string SplineFitOptions::canonical_text() const {
  std::ostringstream t;
  t << "spline-fit-v2|box " << num(y_min) << ' ' << num(y_max) << ' ' << num(roll_max) << ' ' << num(yaw_max)
    << "|intervals " << intervals[0] << ' ' << intervals[1] << ' ' << intervals[2] << "|degrees " << degrees[0] << ' '
    << degrees[1] << ' ' << degrees[2] << "|placement " << (placement == KnotPlacement::kUniform ? "uniform" : "graded")
    << ' ' << num(grading) << "|breakpoints";
  for (double b : y_breakpoints) t << ' ' << num(b);
  t << "|samples " << num(sample_step_y) << ' ' << roll_samples << ' ' << yaw_samples << "|weights " << num(jump_weight)
    << ' ' << num(jump_band) << "|transition " << num(transition) << ' ' << num(transition_load) << "|flange " << num(flange_angle) << ' ' << num(clearance_cap) << "|search "
    << num(search.step) << ' ' << num(search.min_step) << ' ' << num(search.tolerance);
  return t.str();
}

}  // namespace wrc
