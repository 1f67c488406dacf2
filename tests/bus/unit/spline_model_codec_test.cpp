// SPDX-License-Identifier: Apache-2.0
// The spline model on the bus and on disk (services/protocol/geometry/): a fitted
// model survives encoding, the model file and decoding bit for bit; a corrupted file, a wrong
// function list or a wrong model hash are refused naming what does not match; fit options and
// track survive their messages.

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/identity/geometry_key.hpp"
#include "protocol/geometry/fit_options_codec.hpp"
#include "protocol/geometry/spline_model_codec.hpp"
#include "protocol/geometry/spline_model_file.hpp"
#include "protocol/geometry/track_codec.hpp"

namespace wrc::protocol {
namespace {

SplineFitOptions quick_options() {
  SplineFitOptions o;
  o.sample_step_y = 2.5e-4;
  o.roll_samples = 5;
  o.yaw_samples = 5;
  return o;
}

const SplineFit& quick_fit() {
  static const SplineFit fit = fit_spline_geometry(make_geometry(GeometrySpec{}), quick_options());
  return fit;
}

// Both models give identical values and derivatives at a few poses.
void expect_same_model(const SplineContactGeometry& a, const SplineContactGeometry& b) {
  for (double y : {-0.0051, 0.0, 0.0037}) {
    WheelsetPose p;
    p.y = y, p.roll = 0.0004, p.yaw = -0.002, p.z = 0.46;
    for (WheelSide side : {WheelSide::kLeft, WheelSide::kRight}) {
      SplineEvaluation ea, eb;
      a.evaluate(side, p, SplineDerivatives::kHessian, ea);
      b.evaluate(side, p, SplineDerivatives::kHessian, eb);
      EXPECT_EQ(ea.value, eb.value);
      EXPECT_EQ(ea.z_hessian, eb.z_hessian);
    }
  }
  EXPECT_EQ(a.data_hash(), b.data_hash());
  EXPECT_EQ(a.s_split(), b.s_split());
}

std::string temp_file(const std::string& name) {
  return (std::filesystem::temp_directory_path() / (name + "-" + std::to_string(::getpid()))).string();
}

TEST(SplineModelCodec, ModelSurvivesMessageAndFile) {
  const GeometrySpec spec;
  const spline_model_t message = encode_model(quick_fit(), spec, quick_options());
  EXPECT_EQ(message.geometry_key, geometry_key(spec));
  EXPECT_EQ(message.model_key, model_key(geometry_key(spec), quick_options()));
  EXPECT_EQ(message.function_names[0], "z");
  expect_same_model(*decode_model(message), *quick_fit().model);

  const std::string path = temp_file("codec.splinemodel");
  const spline_model_t reference = write_model_file(message, path);
  EXPECT_EQ(reference.wheels[0].num_coefficients, 0);  // the coefficients are in the file
  EXPECT_EQ(reference.file_size, static_cast<std::int64_t>(std::filesystem::file_size(path)));
  EXPECT_THROW(decode_model(reference), std::invalid_argument);  // not without the file
  expect_same_model(*decode_model(resolve_model(reference)), *quick_fit().model);

  // One flipped byte: the SHA-256 no longer matches and the message says so.
  {
    std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(1000);
    f.put('\x55');
  }
  try {
    resolve_model(reference);
    ADD_FAILURE() << "a corrupted model file was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("SHA-256"), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
  try {
    resolve_model(reference);
    ADD_FAILURE() << "a missing model file was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("is missing"), std::string::npos) << e.what();
  }
}

TEST(SplineModelCodec, InconsistentMessagesAreRefusedNamingTheField) {
  const spline_model_t good = encode_model(quick_fit(), GeometrySpec{}, quick_options());
  auto expect_refused = [](const spline_model_t& m, const std::string& text) {
    try {
      decode_model(m);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
  };
  spline_model_t m = good;
  m.function_names[3] = "theta";
  expect_refused(m, "function_names[3] = 'theta'");
  m = good;
  m.model_hash = std::string(64, '0');
  expect_refused(m, "model_hash = 0000");
  m = good;
  m.wheels[1].coefficients[2][5] = std::numeric_limits<double>::quiet_NaN();
  expect_refused(m, "wheels[1].coefficients[2][5] is not finite");
  m = good;
  m.wheels[0].num_breakpoints_y += 1;
  expect_refused(m, "wheels[0].breakpoints_y");
  m = good;
  m.version = 1;
  expect_refused(m, "version = 1");
}

TEST(SplineModelCodec, FitOptionsAndTrackSurviveTheirMessages) {
  SplineFitOptions o = SplineFitOptions::paper_benchmark();
  o.y_breakpoints = {-0.006, -0.002, 0.0, 0.003, 0.006};
  o.jump_weight = 0.003;
  EXPECT_EQ(from_message(to_message(o)).canonical_text(), o.canonical_text());
  spline_fit_options_t bad = to_message(o);
  bad.knot_placement = 7;
  try {
    from_message(bad);
    ADD_FAILURE() << "knot_placement 7 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("knot_placement = 7"), std::string::npos) << e.what();
  }
  GeometrySpec spec;
  spec.rail = "UIC60-MB";
  spec.rail_cant = 0.025;
  spec.track.gauge = 1.437;
  EXPECT_EQ(geometry_key(from_message(to_message(spec))), geometry_key(spec));
  track_t t = to_message(spec);
  t.rail_profile.content_hash = std::string(64, 'f');
  EXPECT_THROW(from_message(t), std::invalid_argument);
}

}  // namespace
}  // namespace wrc::protocol
