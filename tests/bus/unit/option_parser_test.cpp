// SPDX-License-Identifier: Apache-2.0
// The option parser's declared-only lookups and declared defaults (options/options.hpp).
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
                 {{"--yaw", true, "yaw angle [rad]", "0.01"},
                  {"--grid", true, "grid nodes [-]", "61"},
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
  EXPECT_EQ(o.number("--yaw", {-0.06, 0.06}), 0.01);
  EXPECT_EQ(o.integer("--grid", {2, 2001}), 61);
  EXPECT_EQ(o.choice("--format", {"csv", "table"}), "table");
  EXPECT_NE(o.help().find("(default 0.01)"), std::string::npos);
  EXPECT_THROW(o.number("--params"), std::logic_error);  // a described default is the caller's to handle
  const Options given = parse({"--grid", "2.5"});
  EXPECT_THROW(given.integer("--grid"), UsageError);
  EXPECT_THROW(parse({"--yaw", "0.07"}).number("--yaw", {-0.06, 0.06}), UsageError);
}

// The default obeys the range as a typed value does: an absent option whose default lies outside
// the range of the call (a range another option moved, say) is refused naming it.
TEST(OptionParser, TheDefaultIsRangeChecked) {
  const Options o = parse({});
  for (auto lookup : std::vector<std::function<void()>>{[&] { o.number("--yaw", {0.02, 1.0}); },
                                                        [&] { o.integer("--grid", {100, 200}); }}) {
    try {
      lookup();
      ADD_FAILURE() << "an out-of-range default passed";
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find("its default"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("give --"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(o.number("--yaw", {0.01, 1.0}), 0.01);  // the range's end included
}

}  // namespace
}  // namespace wrc
