// SPDX-License-Identifier: Apache-2.0
// The option parser's declared-only lookups, declared defaults and declared ranges
// (options/options.hpp).
#include <stdexcept>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "options/options.hpp"

namespace wrc {
namespace {

Options parse(const std::vector<std::string>& args) {
  return Options("test", "[options]",
                 {{"--yaw", true, "yaw angle [rad]", "0.01", NumberRange{-0.06, 0.06}},
                  {"--grid", true, "grid nodes [-]", "61", NumberRange{2, 2001}},
                  {"--format", true, "csv or table", "table"},
                  {"--params", true, "a file", "the benchmark"}},
                 args);
}

TEST(OptionParser, LookupOfAnUndeclaredOptionIsAProgrammingError) {
  const Options o = parse({"--yaw", "0.02"});
  for (auto lookup : std::vector<std::function<void()>>{
           [&] { o.has("--yaww"); }, [&] { o.text("--yaww"); }, [&] { o.number("--yaww"); },
           [&] { o.integer("--yaww"); }, [&] { o.choice("--yaww", {"a"}); }, [&] { o.required_text("--yaww"); },
           [&] { o.required_number("--yaww"); }}) {
    try {
      lookup();
      ADD_FAILURE() << "an undeclared lookup passed";
    } catch (const std::logic_error& e) {
      EXPECT_NE(std::string(e.what()).find("--yaww"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(o.number("--yaw"), 0.02);
}

TEST(OptionParser, TheDeclaredDefaultIsTheValueOfAnAbsentOption) {
  const Options o = parse({});
  EXPECT_EQ(o.number("--yaw"), 0.01);
  EXPECT_EQ(o.integer("--grid"), 61);
  EXPECT_EQ(o.choice("--format", {"csv", "table"}), "table");
  EXPECT_NE(o.help().find("(default 0.01)"), std::string::npos);
  EXPECT_THROW(o.number("--params"), std::logic_error);  // a described default is the caller's to handle
  const Options given = parse({"--grid", "2.5"});
  EXPECT_THROW(given.integer("--grid"), UsageError);
}

// A typed value outside the declared range is refused naming the option, the value and the range;
// the range's ends are included.
TEST(OptionParser, AValueOutsideItsDeclaredRangeIsRefused) {
  try {
    parse({"--yaw", "0.07"}).number("--yaw");
    ADD_FAILURE() << "--yaw 0.07 passed";
  } catch (const UsageError& e) {
    EXPECT_EQ(std::string(e.what()), "--yaw: 0.07 is outside [-0.06, 0.06]");
  }
  EXPECT_EQ(parse({"--yaw", "0.06"}).number("--yaw"), 0.06);
  EXPECT_THROW(parse({"--grid", "1"}).integer("--grid"), UsageError);
  EXPECT_EQ(parse({"--grid", "2001"}).integer("--grid"), 2001);
}

// A declared default outside its own declared range is a programming error, found when the
// options are parsed (any --help of the command).
TEST(OptionParser, ADeclaredDefaultOutsideItsRangeIsAProgrammingError) {
  try {
    Options("test", "", {{"--speed", true, "speed [m/s]", "500", NumberRange{0.0, 400.0}}}, {});
    ADD_FAILURE() << "a default outside its range was declared";
  } catch (const std::logic_error& e) {
    EXPECT_EQ(std::string(e.what()), "wrc test: the default 500 of --speed is outside its range [0, 400]");
  }
}

// A range that depends on another option (number_within) applies to the default as to a typed
// value: an absent option whose default lies outside it is refused naming it.
TEST(OptionParser, TheDefaultIsCheckedAgainstARangeOtherOptionsMove) {
  const Options o = parse({});
  try {
    o.number_within("--yaw", {0.02, 1.0});
    ADD_FAILURE() << "an out-of-range default passed";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("its default"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("give --"), std::string::npos) << e.what();
  }
  EXPECT_EQ(o.number_within("--yaw", {0.01, 1.0}), 0.01);  // the range's end included
}

}  // namespace
}  // namespace wrc
