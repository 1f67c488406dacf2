// SPDX-License-Identifier: Apache-2.0
// The parameter tables and every entry point they drive agree: each key set to a non-default
// valid value reads the same through the parameter file, the command line and the message; a
// value just outside each range is refused by all of them, and by the library, with the table's
// rule; every counter crosses integrator_stats_t.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/dynamics/run_counter_table.hpp"
#include "core/dynamics/run_parameter_table.hpp"
#include "core/dynamics/run_parameters_file.hpp"
#include "core/geometry/track_table.hpp"
#include "core/identity/geometry_key.hpp"
#include "core/numerics/number_text.hpp"
#include "core/spline/spline_fit_table.hpp"
#include "protocol/geometry/fit_options_codec.hpp"
#include "options/geometry_options.hpp"
#include "protocol/geometry/track_codec.hpp"
#include "options/parameter_options.hpp"
#include "protocol/run/run_command_codec.hpp"
#include "protocol/run/run_output_codec.hpp"
#include "protocol/run/run_request_table.hpp"

namespace wrc {
namespace {

// A valid value of p other than default_value.
double other_valid_value(const ParameterInfo& p, double default_value) {
  if (p.kind == ParameterKind::kBoolean) return default_value != 0.0 ? 0.0 : 1.0;
  const ParameterRange& r = p.range;
  std::vector<double> candidates;
  if (std::isfinite(r.min) && std::isfinite(r.max)) candidates.push_back(0.5 * (r.min + r.max));
  if (std::isfinite(r.max)) candidates.push_back(0.5 * r.max);
  candidates.insert(candidates.end(), {2.0 * default_value, default_value + 1.0, 0.5 * default_value});
  for (double c : candidates) {
    if (p.kind == ParameterKind::kInteger) c = std::floor(c);
    if (c != default_value && !p.violation(c)) return c;
  }
  ADD_FAILURE() << p.key << ": no other valid value";
  return default_value;
}

// Values just outside each finite end of p's range (the end itself when open).
std::vector<double> values_just_outside(const ParameterInfo& p) {
  std::vector<double> out;
  const ParameterRange& r = p.range;
  const bool whole = p.kind == ParameterKind::kInteger;
  auto step = [&](double end) { return whole ? 1.0 : 1e-9 * std::max(1.0, std::abs(end)); };
  if (std::isfinite(r.min)) out.push_back(r.lower == Bound::kOpen ? r.min : r.min - step(r.min));
  if (std::isfinite(r.max)) out.push_back(r.upper == Bound::kOpen ? r.max : r.max + step(r.max));
  return out;
}

protocol::RunRequest valid_request() {
  protocol::RunRequest request;
  request.model = "onepoint";
  request.run_id = "tables";
  return request;
}

std::string file_with(const ParameterInfo& p, double value) {
  return "{\"" + std::string(p.key) + "\": " + p.value_text(value) + "}";
}

Options command_line_with(const std::vector<Parameter<protocol::RunRequest>>& table, const ParameterInfo& p,
                          double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", value);
  const std::string text = p.kind == ParameterKind::kBoolean ? p.value_text(value) : std::string(buf);
  return Options("run", "", parameter_option_specs(table, protocol::RunRequest{}), {p.option_name(), text});
}

TEST(ParameterTables, EveryRunKeyRoundTripsThroughFileCommandLineAndMessage) {
  const auto& table = protocol::run_request_table();
  for (const auto& p : table) {
    SCOPED_TRACE(p.key);
    const protocol::RunRequest defaults = valid_request();
    const double value = other_valid_value(p, p.get(defaults));
    // the command line
    protocol::RunRequest from_cli = defaults;
    apply_parameter_options(table, command_line_with(table, p, value), from_cli);
    EXPECT_EQ(p.get(from_cli), value);
    // the message
    protocol::RunRequest set = defaults;
    p.set(set, value);
    const protocol::RunRequest from_message = protocol::from_message(protocol::to_message(set));
    for (const auto& q : table) EXPECT_EQ(q.get(from_message), q.get(set)) << q.key;
    // the parameter file (the run parameters; the contact client's settings are no file keys)
    if (const RunParameter* r = find_parameter(run_parameter_table(), p.key)) {
      RunSpec from_file;
      apply_run_parameters(file_with(p, value), "p.json", from_file);
      EXPECT_EQ(r->get(from_file), value);
      RunSpec written;
      r->set(written, value);
      RunSpec read;
      apply_run_parameters(run_parameter_text(written), "written", read);
      EXPECT_EQ(r->get(read), value);
    }
  }
}

TEST(ParameterTables, ValueJustOutsideEachRangeIsRefusedEverywhereWithTheSameRule) {
  const auto& table = protocol::run_request_table();
  int checked = 0;
  for (const auto& p : table) {
    for (double bad : values_just_outside(p)) {
      SCOPED_TRACE(std::string(p.key) + " = " + p.value_text(bad));
      const std::string rule = p.range.text();
      ++checked;
      try {
        apply_parameter_options(table, command_line_with(table, p, bad), *std::make_unique<protocol::RunRequest>());
        ADD_FAILURE() << "the command line took it";
      } catch (const UsageError& e) {
        EXPECT_NE(std::string(e.what()).find(p.option_name() + ": "), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(rule), std::string::npos) << e.what();
      }
      protocol::RunRequest request = valid_request();
      p.set(request, bad);
      run_command_t message = protocol::to_message(request);
      try {
        protocol::from_message(message);
        ADD_FAILURE() << "the message codec took it";
      } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(std::string(p.key) + " = "), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(rule), std::string::npos) << e.what();
      }
      const RunParameter* r = find_parameter(run_parameter_table(), p.key);
      if (!r) continue;
      try {
        request.spec.validate();
        ADD_FAILURE() << "RunSpec::validate took it";
      } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(rule), std::string::npos) << e.what();
      }
      try {
        RunSpec s;
        apply_run_parameters(file_with(*r, bad), "p.json", s);
        ADD_FAILURE() << "the parameter file took it";
      } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("p.json: " + std::string(p.key)), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(rule), std::string::npos) << e.what();
      }
    }
  }
  EXPECT_GT(checked, 20);
}

// The drift this table ended: --yaw0 0.06 passed `wrc run` and failed in the library.
TEST(ParameterTables, YawLimitIsOpenAtEveryEntryPoint) {
  const auto& table = protocol::run_request_table();
  const auto* yaw0 = find_parameter(table, "yaw0");
  ASSERT_NE(yaw0, nullptr);
  protocol::RunRequest request = valid_request();
  EXPECT_THROW(apply_parameter_options(table, command_line_with(table, *yaw0, 0.06), request), UsageError);
  apply_parameter_options(table, command_line_with(table, *yaw0, 0.0599), request);
  EXPECT_EQ(request.spec.initial.yaw, 0.0599);
}

// An output period far below the steps would have one step emit samples for ever (found by the
// signed campaign: a run command with output_period 1e-300 s hung wrc-dynamicsd): at most
// kMaxOutputSamples samples up to t_end, in the library and in the message codec.
TEST(ParameterTables, OutputSamplesAreBounded) {
  protocol::RunRequest request = valid_request();
  request.spec.integrator.t_end = 2.0;
  request.spec.integrator.output_period = 2.0 / IntegratorSettings::kMaxOutputSamples;
  EXPECT_NO_THROW(request.spec.validate());
  EXPECT_NO_THROW(protocol::from_message(protocol::to_message(request)));
  for (double period : {1e-300, 1.9 / IntegratorSettings::kMaxOutputSamples}) {
    request.spec.integrator.output_period = period;
    try {
      request.spec.validate();
      ADD_FAILURE() << "RunSpec::validate took output_period " << period;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("output samples"), std::string::npos) << e.what();
    }
    EXPECT_THROW(protocol::from_message(protocol::to_message(request)), std::invalid_argument);
  }
}

TEST(ParameterTables, DefaultsOfTheOptionsAreTheLibrarys) {
  const auto& table = protocol::run_request_table();
  const Options none("run", "", parameter_option_specs(table, protocol::RunRequest{}), {});
  protocol::RunRequest request;
  apply_parameter_options(table, none, request);
  for (const auto& spec : parameter_option_specs(table, protocol::RunRequest{})) {
    const auto* p = [&]() -> const Parameter<protocol::RunRequest>* {
      for (const auto& q : table)
        if (q.option_name() == spec.name) return &q;
      return nullptr;
    }();
    ASSERT_NE(p, nullptr) << spec.name;
    EXPECT_EQ(p->parse(spec.default_text, spec.name), p->get(protocol::RunRequest{})) << spec.name;
  }
}

TEST(ParameterTables, EveryCounterCrossesTheStatsMessage) {
  RunCounters counters;
  double value = 1.0;
  for (const RunCounter& c : run_counter_table()) c.set(counters, value += 1.0);
  const RunCounters read = protocol::from_stats_message(protocol::to_stats_message(counters, "r", 1.0, 2.0));
  for (const RunCounter& c : run_counter_table()) EXPECT_EQ(c.get(read), c.get(counters)) << c.key;
  RunCounters sum = counters;
  sum += counters;
  for (const RunCounter& c : run_counter_table()) {
    const double expected = c.sum == CounterSum::kSum ? 2.0 * c.get(counters) : c.get(counters);
    EXPECT_EQ(c.get(sum), expected) << c.key;
  }
}

}  // namespace
}  // namespace wrc

namespace wrc {
namespace {

GeometrySpec geometry_from_command_line(const std::vector<std::string>& args) {
  return geometry_spec_from_options(Options("geometry", "", geometry_option_specs(), args));
}

// Track: every key through the command line, track_t and geometry_arguments (the command line a
// contact service is started with); just outside each range refused by all and by validate().
TEST(ParameterTables, EveryTrackKeyRoundTripsAndEveryRangeIsOneRule) {
  for (const auto& p : track_parameter_table()) {
    SCOPED_TRACE(p.key);
    const double value = other_valid_value(p, p.get(TrackParameters{}));
    GeometrySpec set;
    p.set(set.track, value);
    if (set.track.flange_back_spacing >= set.track.gauge) set.track.flange_back_spacing = 0.5 * set.track.gauge;
    EXPECT_EQ(p.get(geometry_from_command_line({p.option_name(), exact_number_text(value)}).track), value);
    const GeometrySpec from_message = protocol::from_message(protocol::to_message(set));
    const GeometrySpec from_arguments = geometry_from_command_line(geometry_arguments(set));
    for (const auto& q : track_parameter_table()) {
      EXPECT_EQ(q.get(from_message.track), q.get(set.track)) << q.key;
      EXPECT_EQ(q.get(from_arguments.track), q.get(set.track)) << q.key;
    }
    for (double bad : values_just_outside(p)) {
      SCOPED_TRACE(exact_number_text(bad));
      const std::string rule = p.range.text();
      GeometrySpec outside;
      p.set(outside.track, bad);
      auto expect_rule = [&](const std::function<void()>& entry, const std::string& name) {
        try {
          entry();
          ADD_FAILURE() << "taken";
        } catch (const std::exception& e) {
          EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
          EXPECT_NE(std::string(e.what()).find(rule), std::string::npos) << e.what();
        }
      };
      expect_rule([&] { geometry_from_command_line({p.option_name(), exact_number_text(bad)}); }, p.option_name());
      expect_rule([&] { protocol::from_message(protocol::to_message(outside)); }, p.key);
      expect_rule([&] { outside.track.validate(); }, p.key);
    }
  }
}

}  // namespace
}  // namespace wrc

namespace wrc {
namespace {

// Spline fit options: every scalar key through spline_fit_options_t and, where it has an option of
// its own, `wrc fit`'s options; just outside each range refused by the codec, validate() and the
// option.
TEST(ParameterTables, EveryFitKeyRoundTripsAndEveryRangeIsOneRule) {
  const auto& table = spline_fit_table();
  const std::vector<OptionSpec> specs = parameter_option_specs(table, SplineFitOptions{});
  for (const auto& p : table) {
    SCOPED_TRACE(p.key);
    const double value = other_valid_value(p, p.get(SplineFitOptions{}));
    SplineFitOptions set;
    p.set(set, value);
    const SplineFitOptions from_message = protocol::from_message(protocol::to_message(set));
    for (const auto& q : table) EXPECT_EQ(q.get(from_message), q.get(set)) << q.key;
    if (p.has_option()) {
      SplineFitOptions from_cli;
      apply_parameter_options(table, Options("fit", "", specs, {p.option_name(), exact_number_text(value)}), from_cli);
      EXPECT_EQ(p.get(from_cli), value);
    }
    for (double bad : values_just_outside(p)) {
      SCOPED_TRACE(exact_number_text(bad));
      const std::string rule = p.range.text();
      SplineFitOptions outside;
      p.set(outside, bad);
      for (const auto& entry : std::vector<std::function<void()>>{
               [&] { outside.validate(); }, [&] { protocol::from_message(protocol::to_message(outside)); }}) {
        try {
          entry();
          ADD_FAILURE() << "taken";
        } catch (const std::invalid_argument& e) {
          EXPECT_NE(std::string(e.what()).find(std::string(p.key) + " = "), std::string::npos) << e.what();
          EXPECT_NE(std::string(e.what()).find(rule), std::string::npos) << e.what();
        }
      }
      if (p.has_option()) {
        SplineFitOptions o;
        EXPECT_THROW(apply_parameter_options(table, Options("fit", "", specs, {p.option_name(), exact_number_text(bad)}), o),
                     UsageError);
      }
    }
  }
}

}  // namespace
}  // namespace wrc

namespace wrc {
namespace {

// The error apply_run_parameters gives for text as "p.json", or "no error".
std::string parameter_file_error(const std::string& text) {
  RunSpec spec;
  try {
    apply_run_parameters(text, "p.json", spec);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "no error";
}

// Issue 21 item 8: a number beyond the range of a double (1e999) in a parameter file was reported
// by the JSON library without the file or the key. Now, for every key, the error names the file,
// the key and, for a number, the value as written and the table's range (when it has an end).
TEST(ParameterTables, NumberBeyondDoubleRangeInAFileNamesTheFileKeyAndRange) {
  for (const RunParameter& p : run_parameter_table()) {
    SCOPED_TRACE(p.key);
    for (const std::string token : {"1e999", "-1e999"}) {
      const std::string error = parameter_file_error("{\"" + std::string(p.key) + "\": " + token + "}");
      EXPECT_EQ(error.rfind("p.json: " + std::string(p.key), 0), 0u) << error;
      if (p.kind == ParameterKind::kBoolean) {
        EXPECT_NE(error.find("must be true or false"), std::string::npos) << error;
      } else {
        EXPECT_NE(error.find(std::string(p.key) + " = " + token + " is not a finite number"), std::string::npos)
            << error;
        if (std::isfinite(p.range.min) || std::isfinite(p.range.max)) {
          EXPECT_NE(error.find("(valid: " + p.range.text() + " [" + p.unit + "])"), std::string::npos) << error;
        }
      }
    }
  }
  // Inside an array, and a syntax error after a key: the file and the key it is under.
  EXPECT_EQ(parameter_file_error(R"({"speed": [1e999]})"), "p.json: speed: 1e999 is not a finite number");
  const std::string syntax = parameter_file_error(R"({"mass": 1500 "speed": 3})");
  EXPECT_EQ(syntax.rfind("p.json: not valid JSON after the key mass: ", 0), 0u) << syntax;
}

// Issue 21 item 8: `max_steps: 1e30` was called "not a whole number". A whole number too large for
// a count is outside its range, in the file and on the command line, and every count of every
// table has a finite range of whole numbers a double holds exactly (so none can overflow its
// member).
TEST(ParameterTables, TooLargeCountIsOutsideItsRangeNotFractional) {
  const RunParameter* max_steps = find_parameter(run_parameter_table(), "max_steps");
  ASSERT_NE(max_steps, nullptr);
  const std::string rule = max_steps->range.text();
  EXPECT_EQ(rule, "[1, 1e+12]");
  EXPECT_EQ(parameter_file_error(R"({"max_steps": 1e30})"), "p.json: max_steps = 1e+30 is outside " + rule + " [-]");
  EXPECT_NE(parameter_file_error(R"({"max_steps": 2.5})").find("max_steps = 2.5 is not a whole number"),
            std::string::npos);
  const auto& table = protocol::run_request_table();
  try {
    protocol::RunRequest request;
    apply_parameter_options(table, Options("run", "", parameter_option_specs(table, protocol::RunRequest{}),
                                           {"--max-steps", "1e30"}),
                            request);
    ADD_FAILURE() << "--max-steps 1e30 taken";
  } catch (const UsageError& e) {
    EXPECT_EQ(std::string(e.what()), "--max-steps: 1e30 is outside " + rule + " [-]");
  }
  constexpr double kExact = 9007199254740992.0;  // 2^53
  auto check_counts = [&](const auto& entries) {
    for (const auto& p : entries) {
      if (p.kind != ParameterKind::kInteger) continue;
      SCOPED_TRACE(p.key);
      EXPECT_TRUE(std::isfinite(p.range.min) && std::isfinite(p.range.max)) << p.range.text();
      EXPECT_LE(std::abs(p.range.min), kExact);
      EXPECT_LE(std::abs(p.range.max), kExact);
    }
  };
  check_counts(protocol::run_request_table());
  check_counts(track_parameter_table());
  check_counts(spline_fit_table());
}

// Issue 21 item 8: a key given twice was taken silently (the last one won). Refused, naming the
// file and the key, in the top-level object and in any nested one, with equal or different values.
TEST(ParameterTables, DuplicateKeyInAFileIsRefusedNamingTheFileAndTheKey) {
  EXPECT_EQ(parameter_file_error(R"({"speed": 10, "mass": 1500, "speed": 20})"),
            "p.json: speed: duplicate key (each key may appear once)");
  EXPECT_EQ(parameter_file_error("{\"mass\": 1500, // comment\n \"mass\": 1500}"),
            "p.json: mass: duplicate key (each key may appear once)");
  EXPECT_EQ(parameter_file_error(R"({"speed": {"a": 1, "a": 2}})"),
            "p.json: speed.a: duplicate key (each key may appear once)");
  // Equal keys in different objects are not duplicates (and a nested object is no parameter value).
  EXPECT_EQ(parameter_file_error(R"({"speed": {"a": 1}, "mass": {"a": 1}})"), "p.json: speed: must be a number");
  EXPECT_EQ(parameter_file_error(R"({"speed": 10, "mass": 1500})"), "no error");
}

}  // namespace
}  // namespace wrc
