// SPDX-License-Identifier: Apache-2.0
// The CSV of `wrc sweep`: quoting and reading back, the layout's columns, the rows of an existing
// CSV for resuming (matched by their values, another sweep's CSV refused) and the comparison that
// leaves the wall time out.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <unistd.h>
#include <fstream>

#include "cli/sweep/sweep_table.hpp"
#include "unit/expect_invalid.hpp"

namespace wrc::sweep {
namespace {

using Fields = std::vector<std::string>;

SweepLayout layout() {
  return SweepLayout(Grid({parse_grid_axis("speed=10:30:10"), parse_grid_axis("wheel=S1002,conic:0.05")}),
                     {"m/s", "-"}, {"final_state.y [m]", "counters.steps [-]"});
}

SweepRow row(std::size_t point, const std::string& status, const std::string& error = "") {
  SweepRow r;
  r.point = point;
  r.status = status;
  r.results = {"1.5e-05", std::to_string(100 + point)};
  r.error = error;
  r.wall_time = "0." + std::to_string(point);
  return r;
}

TEST(SweepCsv, QuotingRoundTrips) {
  const Fields fields{"plain", "a,b", "say \"hi\"", " padded ", "", "line\nbreak", "x"};
  const Fields back = split_csv_record(csv_record(fields));
  Fields expected = fields;
  expected[5] = "line break";  // one record per line
  EXPECT_EQ(back, expected);
  EXPECT_EQ(csv_field("a,b"), "\"a,b\"");
  EXPECT_EQ(csv_field("q\""), "\"q\"\"\"");
  EXPECT_EQ(csv_field("1.5"), "1.5");
  EXPECT_EQ(split_csv_record(""), Fields{""});
  EXPECT_EQ(split_csv_record("a,"), (Fields{"a", ""}));
}

TEST(SweepCsv, MalformedRecordsAreNamed) {
  test::expect_invalid([] { split_csv_record("\"open"); }, "not closed");
  test::expect_invalid([] { split_csv_record("\"a\"b,c"); }, "after a closing quote");
  test::expect_invalid([] { split_csv_record("a\"b"); }, "quote inside");
  test::expect_invalid([] { parse_csv_text("a,b\n1,2\n3\n", "f.csv"); }, {"f.csv line 3", "1 fields", "header has 2"});
  test::expect_invalid([] { parse_csv_text("", "f.csv"); }, "no header");
}

TEST(SweepCsv, HeaderOfTheLayout) {
  EXPECT_EQ(layout().header(), (Fields{"point [-]", "speed [m/s]", "wheel [-]", "status [-]", "final_state.y [m]",
                                       "counters.steps [-]", "error [-]", "wall_time [s]"}));
  test::expect_invalid([] { SweepLayout(Grid({parse_grid_axis("speed=1")}), {}, {}); }, "0 units for 1 grid keys");
  test::expect_invalid([] { SweepLayout(Grid({parse_grid_axis("speed=1")}), {"m/s"}, {"speed [m/s]"}); }, "twice");
}

TEST(SweepCsv, RowsInGridOrderWithTheirValues) {
  const SweepLayout l = layout();
  std::map<std::size_t, SweepRow> rows;
  rows[4] = row(4, "failed", "flange climb, left wheel");
  rows[1] = row(1, "finished");
  const CsvTable t = l.table(rows);
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.rows[0], (Fields{"1", "10", "conic:0.05", "finished", "1.5e-05", "101", "", "0.1"}));
  EXPECT_EQ(t.rows[1], (Fields{"4", "30", "S1002", "failed", "1.5e-05", "104", "flange climb, left wheel", "0.4"}));
  EXPECT_NE(csv_text(t).find("\"flange climb, left wheel\""), std::string::npos);
  SweepRow wrong = row(0, "finished");
  wrong.results.pop_back();
  test::expect_invalid([&] { l.record(wrong); }, "1 results for 2 result columns");
}

TEST(SweepCsv, ResumeReadsRowsBackByTheirValues) {
  const SweepLayout l = layout();
  std::map<std::size_t, SweepRow> rows{{0, row(0, "finished")}, {3, row(3, "failed", "a \"quoted\", error")}};
  const auto back = l.rows_of(parse_csv_text(csv_text(l.table(rows)), "s.csv"), "s.csv");
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back.at(3).status, "failed");
  EXPECT_EQ(back.at(3).error, "a \"quoted\", error");
  EXPECT_EQ(back.at(3).results, rows[3].results);
  EXPECT_EQ(back.at(0).wall_time, "0.0");
}

TEST(SweepCsv, AnotherSweepsCsvIsRefused) {
  const SweepLayout l = layout();
  const std::string text = csv_text(l.table({{0, row(0, "finished")}, {5, row(5, "finished")}}));
  // Other keys or extractions: the header differs, named by its first differing column.
  const SweepLayout other(Grid({parse_grid_axis("speed=10:30:10"), parse_grid_axis("friction=0.2,0.3")}), {"m/s", "-"},
                          {"final_state.y [m]", "counters.steps [-]"});
  test::expect_invalid([&] { other.rows_of(parse_csv_text(text, "s.csv"), "s.csv"); },
                       {"s.csv is the CSV of another sweep", "column 3", "'wheel [-]'", "'friction [-]'"});
  // The same keys with other values: a row that is no point of this grid.
  const SweepLayout fewer(Grid({parse_grid_axis("speed=10,20"), parse_grid_axis("wheel=S1002,conic:0.05")}),
                          {"m/s", "-"}, {"final_state.y [m]", "counters.steps [-]"});
  test::expect_invalid([&] { fewer.rows_of(parse_csv_text(text, "s.csv"), "s.csv"); },
                       {"s.csv row 2", "speed = 30, wheel = conic:0.05", "no point"});
  // The same values in another order: the point column disagrees.
  const SweepLayout reordered(Grid({parse_grid_axis("speed=30,20,10"), parse_grid_axis("wheel=S1002,conic:0.05")}),
                              {"m/s", "-"}, {"final_state.y [m]", "counters.steps [-]"});
  test::expect_invalid([&] { reordered.rows_of(parse_csv_text(text, "s.csv"), "s.csv"); }, {"row 1", "point 0", "point 4"});
  // A point twice.
  CsvTable twice = l.table({{0, row(0, "finished")}});
  twice.rows.push_back(twice.rows[0]);
  test::expect_invalid([&] { l.rows_of(twice, "s.csv"); }, {"row 2", "twice"});
}

TEST(SweepCsv, ComparisonLeavesTheWallTimeOut) {
  const SweepLayout l = layout();
  const CsvTable a = l.table({{0, row(0, "finished")}, {1, row(1, "finished")}});
  CsvTable b = a;
  b.rows[0].back() = "99.5";  // another wall time
  EXPECT_TRUE(compare_sweep_tables(a, b).empty());
  b.rows[1][4] = "2e-05";
  const auto d = compare_sweep_tables(a, b);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0], "point [-] 1, final_state.y [m]: 1.5e-05 / 2e-05");
  b.rows.pop_back();
  EXPECT_EQ(compare_sweep_tables(a, b), (std::vector<std::string>{"point [-] 1: only in the first"}));
  CsvTable c = a;
  c.header[4] = "final_state.yaw [rad]";
  EXPECT_NE(compare_sweep_tables(a, c).at(0).find("headers differ"), std::string::npos);
}

TEST(SweepCsv, FileIsReplacedWhole) {
  const std::string path = (std::filesystem::temp_directory_path() / ("wrc_sweep_test_" + std::to_string(::getpid()) + ".csv")).string();
  const SweepLayout l = layout();
  write_csv_file(path, l.table({{0, row(0, "finished")}}));
  write_csv_file(path, l.table({{0, row(0, "finished")}, {2, row(2, "finished")}}));
  EXPECT_EQ(read_csv_file(path).rows.size(), 2u);
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
  std::remove(path.c_str());
  EXPECT_THROW(read_csv_file(path), std::runtime_error);
}

}  // namespace
}  // namespace wrc::sweep
