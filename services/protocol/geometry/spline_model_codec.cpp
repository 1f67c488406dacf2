// SPDX-License-Identifier: Apache-2.0
#include "protocol/geometry/spline_model_codec.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/identity/geometry_key.hpp"
#include "core/identity/sha256.hpp"
#include "protocol/geometry/fit_options_codec.hpp"
#include "protocol/geometry/track_codec.hpp"

namespace wrc::protocol {
namespace {

[[noreturn]] void bad(const std::string& what) { throw std::invalid_argument("spline_model_t: " + what); }

void require_finite(double v, const std::string& name) {
  if (!std::isfinite(v)) bad(name + " = " + std::to_string(v) + " is not finite");
}

std::vector<double> checked_breakpoints(const std::vector<double>& b, int32_t count, const std::string& name) {
  if (count < 2 || static_cast<size_t>(count) != b.size())
    bad(name + ": " + std::to_string(count) + " breakpoints declared, " + std::to_string(b.size()) + " present");
  for (size_t i = 0; i < b.size(); ++i) require_finite(b[i], name + "[" + std::to_string(i) + "]");
  return b;  // BSplineBasis checks the order
}

}  // namespace

std::string model_key(const std::string& geometry_key, const SplineFitOptions& options) {
  return sha256_hex("wrc-spline-model-v" + std::to_string(kSplineModelVersion) + "\n" + geometry_key + "\n" +
                    options.canonical_text());
}

spline_model_t encode_model(const SplineFit& fit, const GeometrySpec& spec, const SplineFitOptions& options) {
  const SplineContactGeometry& model = *fit.model;
  spline_model_t m;
  m.request_id = 0;
  m.geometry_key = geometry_key(spec);
  m.model_key = model_key(m.geometry_key, options);
  m.model_hash = model.data_hash();
  m.version = kSplineModelVersion;
  m.track = to_message(spec);
  m.fit = to_message(options);
  m.flange_split_s = model.s_split();
  m.lateral_curvature_floor = model.lateral_curvature_floor();
  m.num_functions = kSplineFieldCount;
  for (const SplineFieldInfo& f : kSplineFields) {
    m.function_names.push_back(f.name);
    m.function_units.push_back(f.unit);
  }
  for (WheelSide side : {WheelSide::kLeft, WheelSide::kRight}) {
    const int w = static_cast<int>(side);
    const SplineWheel& wheel = model.wheel(side);
    const WheelFitReport& report = fit.wheels[static_cast<size_t>(w)];
    spline_wheel_t& out = m.wheels[w];
    out.wheel = static_cast<int8_t>(w);
    out.num_branches = static_cast<int32_t>(wheel.branches.size());
    out.num_jumps = static_cast<int32_t>(wheel.jumps.size());
    for (const JumpSurface& j : wheel.jumps) {
      out.jump_surfaces.emplace_back(j.c.begin(), j.c.end());
      out.jump_height_half_widths.push_back(j.height_half_width);
      out.jump_y_reaches.push_back(j.y_reach);
    }
    out.basis_size_y = 0;
    out.num_coefficients = 0;
    out.num_functions = kSplineFieldCount;
    out.coefficients.assign(static_cast<size_t>(kSplineFieldCount), {});
    for (const TensorSplineSet& set : wheel.branches) {
      const auto& b = set.basis();
      out.branch_breakpoints_y.push_back(static_cast<int32_t>(b.basis(0).breakpoints().size()));
      out.breakpoints_y.insert(out.breakpoints_y.end(), b.basis(0).breakpoints().begin(), b.basis(0).breakpoints().end());
      out.breakpoints_roll = b.basis(1).breakpoints();
      out.breakpoints_yaw = b.basis(2).breakpoints();
      out.basis_size_y += b.basis(0).size();
      out.basis_size_roll = b.basis(1).size();
      out.basis_size_yaw = b.basis(2).size();
      out.num_coefficients += b.size();
      const Eigen::MatrixXd c = set.coefficients();
      for (int f = 0; f < kSplineFieldCount; ++f)
        for (int i = 0; i < b.size(); ++i) out.coefficients[static_cast<size_t>(f)].push_back(c(i, f));
    }
    out.num_breakpoints_y = static_cast<int32_t>(out.breakpoints_y.size());
    out.num_breakpoints_roll = static_cast<int32_t>(out.breakpoints_roll.size());
    out.num_breakpoints_yaw = static_cast<int32_t>(out.breakpoints_yaw.size());
    for (const FieldError& e : report.residuals) {
      out.fit_rms_error.push_back(e.rms_error);
      out.fit_max_error.push_back(e.max_error);
    }
    out.samples = report.samples;
    out.samples_near_jumps = report.samples_near_jumps;
    out.jumps = static_cast<int32_t>(report.jumps.size());
  }
  m.sampling_seconds = fit.sampling_seconds;
  m.fitting_seconds = fit.fitting_seconds;
  m.file_size = 0;
  return m;
}

std::shared_ptr<const SplineContactGeometry> decode_model(const spline_model_t& m) {
  if (m.version != kSplineModelVersion)
    bad("version = " + std::to_string(m.version) + ", this reader knows " + std::to_string(kSplineModelVersion));
  if (m.num_functions != kSplineFieldCount || m.function_names.size() != static_cast<size_t>(kSplineFieldCount))
    bad("num_functions = " + std::to_string(m.num_functions) + ", expected " + std::to_string(kSplineFieldCount));
  for (int f = 0; f < kSplineFieldCount; ++f) {
    if (m.function_names[static_cast<size_t>(f)] != kSplineFields[static_cast<size_t>(f)].name)
      bad("function_names[" + std::to_string(f) + "] = '" + m.function_names[static_cast<size_t>(f)] + "', expected '" +
          kSplineFields[static_cast<size_t>(f)].name + "'");
  }
  const SplineFitOptions options = from_message(m.fit);
  require_finite(m.flange_split_s, "flange_split_s");
  require_finite(m.lateral_curvature_floor, "lateral_curvature_floor");
  std::array<SplineWheel, 2> wheels;
  for (int w = 0; w < 2; ++w) {
    const spline_wheel_t& in = m.wheels[w];
    const std::string name = std::string("wheels[") + std::to_string(w) + "]";
    if (in.wheel != w) bad(name + ".wheel = " + std::to_string(in.wheel));
    if (in.num_branches < 1 || static_cast<size_t>(in.num_branches) != in.branch_breakpoints_y.size() ||
        in.num_jumps != in.num_branches - 1 || static_cast<size_t>(in.num_jumps) != in.jump_surfaces.size() ||
        static_cast<size_t>(in.num_jumps) != in.jump_height_half_widths.size() ||
        static_cast<size_t>(in.num_jumps) != in.jump_y_reaches.size())
      bad(name + ": " + std::to_string(in.num_branches) + " branches and " + std::to_string(in.num_jumps) +
          " jump surfaces declared (one branch more than jumps), " + std::to_string(in.branch_breakpoints_y.size()) +
          " and " + std::to_string(in.jump_surfaces.size()) + " present");
    SplineWheel& wheel = wheels[static_cast<size_t>(w)];
    for (size_t j = 0; j < in.jump_surfaces.size(); ++j) {
      JumpSurface surface;
      for (size_t q = 0; q < 9; ++q) {
        surface.c[q] = in.jump_surfaces[j][q];
        require_finite(surface.c[q], name + ".jump_surfaces[" + std::to_string(j) + "][" + std::to_string(q) + "]");
      }
      surface.height_half_width = in.jump_height_half_widths[j];
      surface.y_reach = in.jump_y_reaches[j];
      wheel.jumps.push_back(surface);
    }
    const std::vector<double> all_y = checked_breakpoints(in.breakpoints_y, in.num_breakpoints_y, name + ".breakpoints_y");
    const BSplineBasis roll(options.degrees[1], checked_breakpoints(in.breakpoints_roll, in.num_breakpoints_roll,
                                                                    name + ".breakpoints_roll"));
    const BSplineBasis yaw(options.degrees[2], checked_breakpoints(in.breakpoints_yaw, in.num_breakpoints_yaw,
                                                                   name + ".breakpoints_yaw"));
    if (in.num_functions != kSplineFieldCount || in.coefficients.size() != static_cast<size_t>(kSplineFieldCount))
      bad(name + ": " + std::to_string(in.num_functions) + " functions, expected " + std::to_string(kSplineFieldCount));
    size_t y_offset = 0;
    int coefficient_offset = 0, basis_y = 0;
    for (int b = 0; b < in.num_branches; ++b) {
      const int32_t n = in.branch_breakpoints_y[static_cast<size_t>(b)];
      if (n < 2 || y_offset + static_cast<size_t>(n) > all_y.size())
        bad(name + ".branch_breakpoints_y[" + std::to_string(b) + "] = " + std::to_string(n) +
            " does not fit the breakpoints_y present");
      const std::vector<double> y_breaks(all_y.begin() + static_cast<std::ptrdiff_t>(y_offset),
                                         all_y.begin() + static_cast<std::ptrdiff_t>(y_offset + static_cast<size_t>(n)));
      y_offset += static_cast<size_t>(n);
      TensorBasis basis({BSplineBasis(options.degrees[0], y_breaks), roll, yaw});
      basis_y += basis.basis(0).size();
      if (coefficient_offset + basis.size() > in.num_coefficients)
        bad(name + ": " + std::to_string(in.num_functions) + " x " + std::to_string(in.num_coefficients) +
            " coefficients do not hold branch " + std::to_string(b) +
            (in.num_coefficients == 0 ? " (the coefficients are in the file: resolve_model() first)" : ""));
      Eigen::MatrixXd c(basis.size(), kSplineFieldCount);
      for (int f = 0; f < kSplineFieldCount; ++f) {
        const auto& row = in.coefficients[static_cast<size_t>(f)];
        if (row.size() != static_cast<size_t>(in.num_coefficients))
          bad(name + ".coefficients[" + std::to_string(f) + "] has " + std::to_string(row.size()) + " entries, expected " +
              std::to_string(in.num_coefficients));
        for (int i = 0; i < basis.size(); ++i) {
          c(i, f) = row[static_cast<size_t>(coefficient_offset + i)];
          if (!std::isfinite(c(i, f)))
            bad(name + ".coefficients[" + std::to_string(f) + "][" + std::to_string(coefficient_offset + i) +
                "] is not finite");
        }
      }
      coefficient_offset += basis.size();
      wheel.branches.emplace_back(std::move(basis), c);
    }
    if (y_offset != all_y.size() || coefficient_offset != in.num_coefficients || basis_y != in.basis_size_y ||
        in.basis_size_roll != roll.size() || in.basis_size_yaw != yaw.size())
      bad(name + ": basis sizes " + std::to_string(in.basis_size_y) + " x " + std::to_string(in.basis_size_roll) +
          " x " + std::to_string(in.basis_size_yaw) + ", " + std::to_string(in.num_coefficients) +
          " coefficients and " + std::to_string(all_y.size()) +
          " breakpoints in y do not match the branches, breakpoints and degrees");
  }
  auto model = std::make_shared<const SplineContactGeometry>(
      std::move(wheels), SplineBox{options.y_min, options.y_max, options.roll_max, options.yaw_max}, m.flange_split_s,
      m.lateral_curvature_floor);
  const std::string hash = model->data_hash();
  if (hash != m.model_hash) bad("model_hash = " + m.model_hash + " but the data hash to " + hash);
  return model;
}

bool too_large_for_inline(const spline_model_t& message) { return message.getEncodedSize() > kMaxInlineModelBytes; }
}  // namespace wrc::protocol
