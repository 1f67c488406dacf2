#include "geometryd/spline_model_codec.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <vector>

#include "core/identity/geometry_key.hpp"
#include "core/identity/sha256.hpp"

namespace wrc::geometryd {
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

spline_fit_options_t to_message(const SplineFitOptions& o) {
  spline_fit_options_t m;
  m.y_min = o.y_min;
  m.y_max = o.y_max;
  m.roll_max = o.roll_max;
  m.yaw_max = o.yaw_max;
  for (int k = 0; k < 3; ++k) {
    m.intervals[k] = o.intervals[static_cast<size_t>(k)];
    m.degrees[k] = static_cast<int8_t>(o.degrees[static_cast<size_t>(k)]);
  }
  m.knot_placement =
      o.placement == KnotPlacement::kUniform ? spline_fit_options_t::UNIFORM : spline_fit_options_t::GRADED;
  m.grading = o.grading;
  m.num_y_breakpoints = static_cast<int32_t>(o.y_breakpoints.size());
  m.y_breakpoints = o.y_breakpoints;
  m.sample_step_y = o.sample_step_y;
  m.roll_samples = o.roll_samples;
  m.yaw_samples = o.yaw_samples;
  m.jump_weight = o.jump_weight;
  m.jump_band = o.jump_band;
  m.transition = o.transition;
  m.flange_angle = o.flange_angle;
  m.clearance_cap = o.clearance_cap;
  return m;
}

SplineFitOptions from_message(const spline_fit_options_t& m) {
  SplineFitOptions o;
  o.y_min = m.y_min;
  o.y_max = m.y_max;
  o.roll_max = m.roll_max;
  o.yaw_max = m.yaw_max;
  for (int k = 0; k < 3; ++k) {
    o.intervals[static_cast<size_t>(k)] = m.intervals[k];
    o.degrees[static_cast<size_t>(k)] = m.degrees[k];
  }
  if (m.knot_placement != spline_fit_options_t::UNIFORM && m.knot_placement != spline_fit_options_t::GRADED)
    throw std::invalid_argument("spline_fit_options_t: knot_placement = " + std::to_string(m.knot_placement) +
                                " is neither UNIFORM (0) nor GRADED (1)");
  o.placement = m.knot_placement == spline_fit_options_t::UNIFORM ? KnotPlacement::kUniform : KnotPlacement::kGraded;
  o.grading = m.grading;
  if (m.num_y_breakpoints < 0 || static_cast<size_t>(m.num_y_breakpoints) != m.y_breakpoints.size())
    throw std::invalid_argument("spline_fit_options_t: num_y_breakpoints = " + std::to_string(m.num_y_breakpoints) +
                                " does not match the array");
  o.y_breakpoints = m.y_breakpoints;
  o.sample_step_y = m.sample_step_y;
  o.roll_samples = m.roll_samples;
  o.yaw_samples = m.yaw_samples;
  o.jump_weight = m.jump_weight;
  o.jump_band = m.jump_band;
  o.transition = m.transition;
  o.flange_angle = m.flange_angle;
  o.clearance_cap = m.clearance_cap;
  o.validate();
  return o;
}

track_t to_message(const GeometrySpec& spec) {
  track_t t;
  t.wheel_profile.name = spec.wheel;
  t.wheel_profile.content_hash = profile_content_hash(spec.wheel);
  t.rail_profile.name = spec.rail;
  t.rail_profile.content_hash = profile_content_hash(spec.rail);
  t.rail_cant = spec.rail_cant ? *spec.rail_cant : std::numeric_limits<double>::quiet_NaN();
  t.gauge = spec.track.gauge;
  t.gauge_depth = spec.track.gauge_depth;
  t.flange_back_spacing = spec.track.flange_back_spacing;
  t.taping_line_offset = spec.track.taping_line_offset;
  t.rail_inclination = spec.track.inclination;
  t.nominal_radius = spec.track.nominal_radius;
  return t;
}

GeometrySpec from_message(const track_t& t) {
  GeometrySpec spec;
  spec.wheel = t.wheel_profile.name;
  spec.rail = t.rail_profile.name;
  if (!std::isnan(t.rail_cant)) {
    if (!std::isfinite(t.rail_cant)) throw std::invalid_argument("track_t: rail_cant is infinite");
    spec.rail_cant = t.rail_cant;
  }
  spec.track.gauge = t.gauge;
  spec.track.gauge_depth = t.gauge_depth;
  spec.track.flange_back_spacing = t.flange_back_spacing;
  spec.track.taping_line_offset = t.taping_line_offset;
  spec.track.inclination = t.rail_inclination;
  spec.track.nominal_radius = t.nominal_radius;
  spec.track.validate();
  for (const profile_ref_t* ref : {&t.wheel_profile, &t.rail_profile}) {
    if (!ref->content_hash.empty() && ref->content_hash != profile_content_hash(ref->name))
      throw std::invalid_argument("track_t: the content of profile '" + ref->name +
                                  "' here differs from the sender's (content_hash " + ref->content_hash + ")");
  }
  return spec;
}

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
    for (const JumpSurface& j : wheel.jumps) out.jump_surfaces.emplace_back(j.c.begin(), j.c.end());
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
  bool any_branches = false;
  for (int w = 0; w < 2; ++w) {
    const spline_wheel_t& in = m.wheels[w];
    const std::string name = std::string("wheels[") + std::to_string(w) + "]";
    if (in.wheel != w) bad(name + ".wheel = " + std::to_string(in.wheel));
    if (in.num_branches < 1 || static_cast<size_t>(in.num_branches) != in.branch_breakpoints_y.size() ||
        in.num_jumps != in.num_branches - 1 || static_cast<size_t>(in.num_jumps) != in.jump_surfaces.size())
      bad(name + ": " + std::to_string(in.num_branches) + " branches and " + std::to_string(in.num_jumps) +
          " jump surfaces declared (one branch more than jumps), " + std::to_string(in.branch_breakpoints_y.size()) +
          " and " + std::to_string(in.jump_surfaces.size()) + " present");
    any_branches = any_branches || in.num_branches > 1;
    SplineWheel& wheel = wheels[static_cast<size_t>(w)];
    for (size_t j = 0; j < in.jump_surfaces.size(); ++j) {
      JumpSurface surface;
      for (size_t q = 0; q < 9; ++q) {
        surface.c[q] = in.jump_surfaces[j][q];
        require_finite(surface.c[q], name + ".jump_surfaces[" + std::to_string(j) + "][" + std::to_string(q) + "]");
      }
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
      m.lateral_curvature_floor, any_branches ? options.transition : 0.0);
  const std::string hash = model->data_hash();
  if (hash != m.model_hash) bad("model_hash = " + m.model_hash + " but the data hash to " + hash);
  return model;
}

bool too_large_for_inline(const spline_model_t& message) { return message.getEncodedSize() > kMaxInlineModelBytes; }

namespace {

// The file form of a message: M with its header, request id and file fields cleared, LCM-encoded,
// written atomically (temporary file, then rename); returns the bytes written. what names the kind
// in errors.
template <class M>
std::vector<char> write_message_file(M stored, const std::string& path, const char* what) {
  stored.header = header_t{};
  stored.request_id = 0;
  stored.file_path.clear();
  stored.file_hash.clear();
  stored.file_size = 0;
  const int size = stored.getEncodedSize();
  std::vector<char> bytes(static_cast<size_t>(size));
  if (stored.encode(bytes.data(), 0, size) != size) throw std::runtime_error(std::string(what) + ": encoding failed");
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), size);
    if (!out) throw std::runtime_error(std::string(what) + ": cannot write " + temporary);
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec)
    throw std::runtime_error(std::string(what) + ": cannot rename " + temporary + " to " + path + ": " + ec.message());
  return bytes;
}

std::vector<char> read_bytes(const std::string& path, const char* what) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw std::runtime_error(std::string(what) + " " + path + " is missing");
  std::ifstream in(path, std::ios::binary);
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw std::runtime_error(std::string(what) + " " + path + ": read error");
  return bytes;
}

template <class M>
M decode_bytes(const std::vector<char>& bytes, const std::string& path, const char* what) {
  M full;
  if (full.decode(bytes.data(), 0, static_cast<int>(bytes.size())) != static_cast<int>(bytes.size()))
    throw std::runtime_error(std::string(what) + " " + path + " does not decode as a " + M::getTypeName());
  return full;
}

// The file fields of a reference to path (absolute path, size, SHA-256 of the bytes).
template <class M>
void set_file_fields(M& reference, const std::string& path, const std::vector<char>& bytes) {
  reference.file_path = std::filesystem::absolute(path).string();
  reference.file_hash = sha256_hex(bytes.data(), bytes.size());
  reference.file_size = static_cast<int64_t>(bytes.size());
}

// The bytes behind a reference, checked against its file size and SHA-256.
template <class M>
std::vector<char> checked_file(const M& reference, const char* what) {
  const std::string& path = reference.file_path;
  std::vector<char> bytes = read_bytes(path, what);
  if (static_cast<std::int64_t>(bytes.size()) != reference.file_size)
    throw std::runtime_error(std::string(what) + " " + path + " has " + std::to_string(bytes.size()) +
                             " bytes, the message says " + std::to_string(reference.file_size));
  const std::string hash = sha256_hex(bytes.data(), bytes.size());
  if (hash != reference.file_hash)
    throw std::runtime_error(std::string(what) + " " + path + ": SHA-256 " + hash + " differs from the message's " +
                             reference.file_hash);
  return bytes;
}

constexpr const char* kModelFile = "spline model file";
constexpr const char* kTableFile = "geometry table file";

// SHA-256 of a table's values as little-endian doubles.
std::string values_hash(const std::vector<double>& values) {
  return sha256_hex(values.data(), values.size() * sizeof(double));
}

// The reference to the file holding bytes (full without its coefficients, with the file fields).
spline_model_t model_reference(const spline_model_t& full, const std::string& path, const std::vector<char>& bytes) {
  spline_model_t reference = full;
  for (spline_wheel_t& w : reference.wheels) {
    w.num_coefficients = 0;
    w.coefficients.assign(static_cast<size_t>(w.num_functions), std::vector<double>());
  }
  set_file_fields(reference, path, bytes);
  return reference;
}

// The same for a table (full without its values).
geometry_table_t table_reference_to(const geometry_table_t& full, const std::string& path,
                                    const std::vector<char>& bytes) {
  geometry_table_t reference = full;
  reference.num_values = 0;
  reference.values.clear();
  set_file_fields(reference, path, bytes);
  return reference;
}

}  // namespace

spline_model_t write_model_file(const spline_model_t& message, const std::string& path) {
  return model_reference(message, path, write_message_file(message, path, kModelFile));
}

spline_model_t file_reference(const spline_model_t& full, const std::string& path) {
  return model_reference(full, path, read_bytes(path, kModelFile));
}

spline_model_t read_model_file(const std::string& path) {
  return decode_bytes<spline_model_t>(read_bytes(path, kModelFile), path, kModelFile);
}

spline_model_t resolve_model(const spline_model_t& reference) {
  if (reference.file_path.empty()) return reference;
  spline_model_t full = decode_bytes<spline_model_t>(checked_file(reference, kModelFile), reference.file_path, kModelFile);
  if (full.model_key != reference.model_key || full.model_hash != reference.model_hash)
    throw std::runtime_error(std::string(kModelFile) + " " + reference.file_path +
                             " holds another model (model_key or model_hash differ)");
  full.header = reference.header;
  full.request_id = reference.request_id;
  return full;
}

geometry_table_t encode_table(const WheelSampleGrid& grid, const GeometrySpec& spec, const std::string& model_key) {
  geometry_table_t t;
  t.request_id = 0;
  t.geometry_key = geometry_key(spec);
  t.model_key = model_key;
  t.version = kGeometryTableVersion;
  t.track = to_message(spec);
  t.wheel = grid.side == WheelSide::kLeft ? geometry_table_t::LEFT : geometry_table_t::RIGHT;
  t.y_min = grid.y.front();
  t.y_max = grid.y.back();
  t.y_count = static_cast<int32_t>(grid.y.size());
  t.roll_min = grid.roll.front();
  t.roll_max = grid.roll.back();
  t.roll_count = static_cast<int32_t>(grid.roll.size());
  t.yaw_min = grid.yaw.front();
  t.yaw_max = grid.yaw.back();
  t.yaw_count = static_cast<int32_t>(grid.yaw.size());
  for (const SplineFieldInfo& f : kSplineFields) {
    t.column_names.push_back(f.name);
    t.column_units.push_back(f.unit);
  }
  t.column_names.insert(t.column_names.end(), {"valid", "second_minimum_gap", "jump_distance"});
  t.column_units.insert(t.column_units.end(), {"-", "m", "m"});
  t.num_columns = static_cast<int32_t>(t.column_names.size());
  t.values.reserve(grid.samples.size() * static_cast<size_t>(t.num_columns));
  for (size_t j = 0; j < grid.roll.size(); ++j)
    for (size_t k = 0; k < grid.yaw.size(); ++k)
      for (size_t i = 0; i < grid.y.size(); ++i) {
        const WheelSample& s = grid.at(i, j, k);
        t.values.insert(t.values.end(), s.fields.begin(), s.fields.end());
        const double gap = std::isfinite(s.second_minimum_gap) ? s.second_minimum_gap : 1.0;
        const double jump = std::isfinite(grid.jump_distance(i, j, k)) ? grid.jump_distance(i, j, k) : 1.0;
        t.values.insert(t.values.end(), {s.valid ? 1.0 : 0.0, gap, jump});
      }
  t.num_values = static_cast<int32_t>(t.values.size());
  t.table_hash = values_hash(t.values);
  for (const auto& line : grid.line_jumps)
    for (const TreadJump& jump : line) {
      t.jump_y.push_back(jump.y);
      t.jump_roll.push_back(jump.roll);
      t.jump_yaw.push_back(jump.yaw);
    }
  t.num_jumps = static_cast<int32_t>(t.jump_y.size());
  t.file_size = 0;
  return t;
}

geometry_table_t write_table_file(const geometry_table_t& table, const std::string& path) {
  return table_reference_to(table, path, write_message_file(table, path, kTableFile));
}

geometry_table_t table_reference(const geometry_table_t& full, const std::string& path) {
  return table_reference_to(full, path, read_bytes(path, kTableFile));
}

geometry_table_t read_table_file(const std::string& path) {
  return decode_bytes<geometry_table_t>(read_bytes(path, kTableFile), path, kTableFile);
}

geometry_table_t resolve_table(const geometry_table_t& reference) {
  geometry_table_t full =
      reference.file_path.empty()
          ? reference
          : decode_bytes<geometry_table_t>(checked_file(reference, kTableFile), reference.file_path, kTableFile);
  const std::int64_t expected = static_cast<std::int64_t>(full.y_count) * full.roll_count * full.yaw_count * full.num_columns;
  if (full.version != kGeometryTableVersion || full.num_values != expected ||
      full.values.size() != static_cast<size_t>(expected) || full.column_names.size() != static_cast<size_t>(full.num_columns))
    throw std::runtime_error("geometry table " + full.model_key.substr(0, 12) + ": version " +
                             std::to_string(full.version) + ", " + std::to_string(full.values.size()) +
                             " values for a " + std::to_string(full.y_count) + " x " + std::to_string(full.roll_count) +
                             " x " + std::to_string(full.yaw_count) + " x " + std::to_string(full.num_columns) + " table");
  if (values_hash(full.values) != full.table_hash)
    throw std::runtime_error("geometry table " + full.model_key.substr(0, 12) + ": the values do not hash to table_hash");
  if (!reference.file_path.empty() && (full.model_key != reference.model_key || full.wheel != reference.wheel))
    throw std::runtime_error(std::string(kTableFile) + " " + reference.file_path + " holds another table");
  full.header = reference.header;
  full.request_id = reference.request_id;
  return full;
}

}  // namespace wrc::geometryd
