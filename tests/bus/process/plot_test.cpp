// SPDX-License-Identifier: Apache-2.0
// `wrc plot KIND` as the user runs it: each kind writes a PNG of the size asked for (read from the
// PNG header) or an SVG from a small case; for every kind what was handed to gnuplot (captured by
// a gnuplot on PATH that copies the job's script and data) is checked against the physics (the
// common point the lowest, the rigid wheelset on its rails, a cone's conicity, the area's
// outlines, roll as lift) or against the inputs drawn; a bad option and a missing gnuplot give
// one-line errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "child_process.hpp"

namespace wrc::bus::test {
namespace {

namespace fs = std::filesystem;

const std::string kCli = WRC_CLI_PATH;

bool gnuplot_installed() { return std::system("command -v gnuplot >/dev/null 2>&1") == 0; }

struct PngSize {
  bool valid = false;
  std::uint32_t width = 0, height = 0;
};

// Width and height from the IHDR chunk, which follows the 8-byte signature.
PngSize png_size(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char header[24] = {};
  in.read(reinterpret_cast<char*>(header), sizeof header);
  PngSize size;
  if (in.gcount() != 24) return size;
  const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (!std::equal(signature, signature + 8, header) || std::string(reinterpret_cast<char*>(header + 12), 4) != "IHDR")
    return size;
  auto be32 = [&](int at) {
    return std::uint32_t(header[at]) << 24 | std::uint32_t(header[at + 1]) << 16 | std::uint32_t(header[at + 2]) << 8 |
           std::uint32_t(header[at + 3]);
  };
  size.valid = true;
  size.width = be32(16);
  size.height = be32(20);
  return size;
}

class PlotTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!gnuplot_installed()) GTEST_SKIP() << "gnuplot is not installed (Debian's gnuplot-nox)";
    dir_ = fs::temp_directory_path() / ("wrc-plot-test-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ignored;
    if (!dir_.empty()) fs::remove_all(dir_, ignored);
  }

  // Runs `wrc plot ARGS --out FILE --width 640 --height 480` and checks the PNG it writes.
  void expect_png(const std::string& args, const std::string& name) {
    const std::string out = (dir_ / name).string();
    int status = -1;
    const std::string text =
        run_command(kCli + " plot " + args + " --out " + out + " --width 640 --height 480 2>&1", &status);
    ASSERT_EQ(status, 0) << text;
    EXPECT_NE(text.find("wrote " + out), std::string::npos) << text;
    ASSERT_TRUE(fs::exists(out)) << text;
    EXPECT_GT(fs::file_size(out), 1000u);
    const PngSize size = png_size(out);
    ASSERT_TRUE(size.valid) << out << " is not a PNG";
    EXPECT_EQ(size.width, 640u);
    EXPECT_EQ(size.height, 480u);
  }

  // Runs `wrc plot ARGS --out DIR/NAME` with a gnuplot on PATH that copies the job's script and
  // data to DIR/capture before running the real one; returns the command's output.
  std::string plot_captured(const std::string& args, const std::string& name) {
    const fs::path bin = dir_ / "bin";
    if (!fs::exists(bin / "gnuplot")) {
      fs::create_directories(bin);
      fs::create_directories(capture());
      int found = -1;
      const std::string real = run_command("command -v gnuplot", &found);
      std::ofstream script(bin / "gnuplot");
      script << "#!/bin/sh\ncp \"$(dirname \"$1\")\"/* " << capture().string() << "/\nexec "
             << real.substr(0, real.find('\n')) << " \"$@\"\n";
      script.close();
      fs::permissions(bin / "gnuplot", fs::perms::owner_all);
    }
    int status = -1;
    const std::string out = (dir_ / name).string();
    const std::string text =
        run_command("PATH=" + bin.string() + ":/usr/bin:/bin " + kCli + " plot " + args + " --out " + out + " 2>&1",
                    &status);
    EXPECT_EQ(status, 0) << text;
    EXPECT_TRUE(fs::exists(out)) << text;
    return text;
  }
  fs::path capture() const { return dir_ / "capture"; }

  // The rows of numbers of a captured data file (comment lines and blank lines left out).
  std::vector<std::vector<double>> data_rows(const std::string& file) const {
    std::ifstream in(capture() / file);
    EXPECT_TRUE(in) << file << " was not handed to gnuplot";
    std::vector<std::vector<double>> rows;
    for (std::string line; std::getline(in, line);) {
      if (line.empty() || line[0] == '#') continue;
      std::istringstream fields(line);
      std::vector<double> row;
      for (double v; fields >> v;) row.push_back(v);
      rows.push_back(row);
    }
    return rows;
  }
  std::string captured_script() const {
    std::ifstream in(capture() / "plot.gp");
    return std::string(std::istreambuf_iterator<char>(in), {});
  }

  fs::path dir_;
};

TEST_F(PlotTest, HelpListsTheKinds) {
  int status = -1;
  const std::string text = run_command(kCli + " plot --help", &status);
  EXPECT_EQ(status, 0);
  for (const char* kind : {"distance", "area", "geometry", "run", "conicity", "profiles", "displacement", "wheelsets"})
    EXPECT_NE(text.find(std::string("\n  ") + kind + " "), std::string::npos) << kind << " missing in\n" << text;
}

TEST_F(PlotTest, Distance) { expect_png("distance --y 0.003", "distance.png"); }

TEST_F(PlotTest, DistanceSvg) {
  const std::string out = (dir_ / "distance.svg").string();
  int status = -1;
  const std::string text = run_command(kCli + " plot distance --y 0.006 --roll 0.001 --out " + out + " 2>&1", &status);
  ASSERT_EQ(status, 0) << text;
  std::ifstream in(out);
  std::string svg((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("width=\"1200\""), std::string::npos);
}

TEST_F(PlotTest, Area) { expect_png("area --y 0.003 --grid 61", "area.png"); }

// With the spline model's ellipse (an in-process fit of a few seconds).
TEST_F(PlotTest, AreaWithSplineEllipse) { expect_png("area --y 0.003 --grid 41 --spline", "area_spline.png"); }

TEST_F(PlotTest, Geometry) { expect_png("geometry --y-from -0.008 --y-to 0.008 --y-step 2e-4", "geometry.png"); }

// A small history in the format of `wrc run --history`, two runs overlaid (as figures 5-6).
TEST_F(PlotTest, Run) {
  for (const char* model : {"onepoint", "spline"}) {
    std::ofstream out(dir_ / (std::string(model) + ".csv"));
    out << "t,y,z,roll,yaw,y_dot,z_dot,roll_dot,yaw_dot,spin_rate,s_left,s_right,angle_left,angle_right,"
           "normal_force_left,normal_force_right,model\n";
    for (int i = 0; i <= 50; ++i) {
      const double t = 0.02 * i, y = 0.004 * std::exp(-t) * std::cos(8 * t);
      out << t << "," << y << ",0.46,0,0,0,0,0,0,65,0," << -2 * y << ",0.02,0.02,75000," << 75000 + 5e6 * y << ","
          << model << "\n";
    }
  }
  expect_png("run " + (dir_ / "onepoint.csv").string() + " " + (dir_ / "spline.csv").string(), "run.png");
  // What was drawn: per history one series of (t, y, s_right, normal_force_right) as written,
  // each named by its model and file.
  plot_captured("run " + (dir_ / "onepoint.csv").string() + " " + (dir_ / "spline.csv").string(), "run2.png");
  for (const char* file : {"run_0.dat", "run_1.dat"}) {
    const auto rows = data_rows(file);
    ASSERT_EQ(rows.size(), 51u) << file;
    for (int i = 0; i <= 50; ++i) {
      const double t = 0.02 * i, y = 0.004 * std::exp(-t) * std::cos(8 * t);
      const auto& r = rows[static_cast<size_t>(i)];
      ASSERT_EQ(r.size(), 4u);
      EXPECT_NEAR(r[0], t, 1e-5) << file;  // the history's text has six significant digits
      EXPECT_NEAR(r[1], y, 1e-8) << file;
      EXPECT_NEAR(r[2], -2 * y, 2e-8) << file;
      EXPECT_NEAR(r[3], 75000 + 5e6 * y, 0.1) << file;
    }
  }
  const std::string gp = captured_script();
  EXPECT_NE(gp.find("onepoint (onepoint.csv)"), std::string::npos) << gp;
  EXPECT_NE(gp.find("spline (spline.csv)"), std::string::npos) << gp;
}

// --forces from a history with units in its headers and the force columns (as `wrc run --history`
// writes it now): Y/Q with Nadal's limit, sum Y with Prud'homme's, T gamma against the distance. A
// history without the force columns (the file of PlotTest.Run's format) is refused in one line.
TEST_F(PlotTest, RunForces) {
  std::ofstream out(dir_ / "forces.csv");
  out << "t [s],y [m],s_right [m],normal_force_right [N],distance [m],y_over_q_left [-],y_over_q_right [-],"
         "nadal_limit [-],track_shift_force [N],prudhomme_limit [N],wear_number_left [N],wear_number_right [N],"
         "model [-]\n";
  for (int i = 0; i <= 50; ++i) {
    const double t = 0.02 * i, y = 0.004 * std::exp(-t) * std::cos(8 * t);
    out << t << "," << y << "," << -2 * y << ",86000," << 30 * t << "," << -0.05 + y << "," << 0.1 - 20 * y
        << ",1.3416,-20000," << 67500 << "," << 30 + 1e3 * y << "," << 40 - 1e3 * y << ",spline\n";
  }
  out.close();
  expect_png("run " + (dir_ / "forces.csv").string() + " --forces", "forces.png");
  std::ofstream old(dir_ / "old.csv");
  old << "t,y,s_right,normal_force_right,model\n0,0,0,86000,spline\n";
  old.close();
  int status = -1;
  const std::string text =
      run_command(kCli + " plot run " + (dir_ / "old.csv").string() + " --forces 2>&1 >/dev/null", &status);
  EXPECT_NE(status, 0);
  EXPECT_NE(text.find("has no force columns"), std::string::npos) << text;
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;
}

// A vehicle run's history (two wheelsets, a row each per time, the column `wheelset`): one series
// per wheelset of (its own distance, y, yaw) as written, each titled by its number; `plot run`
// draws the first wheelset's rows alone. A history without yaw is refused in one line.
TEST_F(PlotTest, Wheelsets) {
  std::ofstream out(dir_ / "vehicle.csv");
  out << "t [s],y [m],yaw [rad],s_right [m],normal_force_right [N],distance [m],y_over_q_left [-],y_over_q_right [-],"
         "nadal_limit [-],track_shift_force [N],prudhomme_limit [N],wear_number_left [N],wear_number_right [N],"
         "wheelset [-],model [-]\n";
  auto y_of = [](int w, double t) { return 0.003 * std::exp(-t) * std::cos(8 * t - w); };
  auto yaw_of = [](int w, double t) { return 0.002 * std::sin(8 * t + w); };
  for (int i = 0; i <= 50; ++i) {
    const double t = 0.02 * i;
    for (int w = 0; w < 2; ++w)
      out << t << "," << y_of(w, t) << "," << yaw_of(w, t) << ",0,86000," << 30 * t - 2.148 * w
          << ",0.1,-0.1,1.3416,1000,67500,20,20," << w << ",spline\n";
  }
  out.close();
  expect_png("wheelsets " + (dir_ / "vehicle.csv").string(), "wheelsets.png");
  plot_captured("wheelsets " + (dir_ / "vehicle.csv").string(), "wheelsets2.png");
  for (int w = 0; w < 2; ++w) {
    const auto rows = data_rows("wheelset_" + std::to_string(w) + ".dat");
    ASSERT_EQ(rows.size(), 51u) << w;
    for (int i = 0; i <= 50; ++i) {
      const double t = 0.02 * i;
      const auto& r = rows[static_cast<size_t>(i)];
      ASSERT_EQ(r.size(), 3u);
      EXPECT_NEAR(r[0], 30 * t - 2.148 * w, 1e-4) << w;  // six significant digits in the file
      EXPECT_NEAR(r[1], y_of(w, t), 1e-8) << w;
      EXPECT_NEAR(r[2], yaw_of(w, t), 1e-8) << w;
    }
  }
  EXPECT_NE(captured_script().find("wheelset 2"), std::string::npos) << captured_script();
  // plot run: the first wheelset's 51 rows.
  plot_captured("run " + (dir_ / "vehicle.csv").string(), "run.png");
  const auto first = data_rows("run_0.dat");
  ASSERT_EQ(first.size(), 51u);
  EXPECT_NEAR(first[10][1], y_of(0, 0.2), 1e-8);
  std::ofstream old(dir_ / "old.csv");
  old << "t,y,s_right,normal_force_right,model\n0,0,0,86000,spline\n";
  old.close();
  int status = -1;
  const std::string text =
      run_command(kCli + " plot wheelsets " + (dir_ / "old.csv").string() + " 2>&1 >/dev/null", &status);
  EXPECT_NE(status, 0);
  EXPECT_NE(text.find("has no distance or yaw column"), std::string::npos) << text;
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;
}

TEST_F(PlotTest, Conicity) { expect_png("conicity --a-from 0.001 --a-to 0.008 --a-step 0.001 --samples 64", "conicity.png"); }

TEST_F(PlotTest, Profiles) { expect_png("profiles --y 0.005", "profiles.png"); }

TEST_F(PlotTest, Displacement) { expect_png("displacement --grid 21", "displacement.png"); }

// What `wrc plot conicity` and `wrc plot geometry` draw for a cone (conic:0.05 on UIC60): the
// rigid wheelset's rolling-radius difference is odd in y and, for a cone, linear in it (its points
// on the wheel move along a straight generator), so the equivalent conicity is the same at every
// amplitude and equals half the slope of delta_r: the two kinds' series agree with each other to
// 1e-6, and with the cone's slope to the few per cent by which the wheelset's roll and the rail
// head's curvature move the contact points (0.0526 here against 0.05). The
// mirror image swaps the wheels: angle_left(y) = angle_right(-y), r_left(y) = r_right(-y).
TEST_F(PlotTest, ConicityAndGeometryOfAConeDrawTheirSeries) {
  plot_captured("conicity --wheel conic:0.05 --a-from 0.001 --a-to 0.004 --a-step 0.001 --samples 64", "c.png");
  const auto conicity = data_rows("conicity.dat");
  ASSERT_EQ(conicity.size(), 4u);
  for (std::size_t i = 0; i < conicity.size(); ++i) {
    EXPECT_NEAR(conicity[i][0], 1e-3 * static_cast<double>(i + 1), 1e-15);  // [m]
    EXPECT_NEAR(conicity[i][1], conicity[0][1], 1e-6);
  }
  EXPECT_NEAR(conicity[0][1], 0.05, 0.05 * 0.06);
  EXPECT_NE(captured_script().find("using ($1*1e3):2 "), std::string::npos) << captured_script();  // A in mm

  fs::remove_all(capture());
  fs::create_directories(capture());
  plot_captured("geometry --wheel conic:0.05 --y-from -0.004 --y-to 0.004 --y-step 0.002", "g.png");
  // y delta_r angle_left angle_right r_left r_right s_left s_right u_left u_right
  const auto g = data_rows("geometry.dat");
  ASSERT_EQ(g.size(), 5u);
  for (std::size_t i = 0; i < g.size(); ++i) {
    const auto& row = g[i];
    const auto& mirror = g[g.size() - 1 - i];
    ASSERT_EQ(row.size(), 10u);
    EXPECT_NEAR(row[0], -4e-3 + 2e-3 * static_cast<double>(i), 1e-15);
    EXPECT_NEAR(row[1], -mirror[1], 1e-12);
    EXPECT_NEAR(row[2], mirror[3], 1e-9);
    EXPECT_NEAR(row[4], mirror[5], 1e-12);
    if (row[0] != 0.0) {
      EXPECT_NEAR(row[1] / (2 * row[0]), conicity[0][1], 1e-6) << "y = " << row[0];
    }
  }
  EXPECT_NE(captured_script().find("using ($1*1e3):($2*1e3)"), std::string::npos);  // y and delta_r in mm
}

// What `wrc plot distance` draws (S1002 on UIC60, y = 3 mm): the distance along the locus C above
// the common point is never negative (the common point is the lowest over the whole locus, and
// the sampled locus comes within 1 um of it), and among the potential points exactly one is the
// common point, at distance 0, none below it.
TEST_F(PlotTest, DistanceDrawsTheCommonPointAsTheLowest) {
  plot_captured("distance --y 0.003", "d.png");
  double lowest = 1e300;
  for (const auto& row : data_rows("locus.dat")) lowest = std::min(lowest, row[1]);
  EXPECT_GE(lowest, -1e-12);
  EXPECT_LT(lowest, 1e-6);
  int common = 0;
  for (const auto& row : data_rows("points.dat")) {
    ASSERT_EQ(row.size(), 4u);
    EXPECT_GE(row[1], -1e-12) << "a potential point below the common point at y = " << row[0];
    if (row[3] == 1.0) {
      ++common;
      EXPECT_EQ(row[1], 0.0);
      EXPECT_EQ(row[2], 1.0);  // a local minimum
    }
  }
  EXPECT_EQ(common, 1);
}

// What `wrc plot displacement` draws: the left wheel's vertical displacement at the nominal
// height over (y, roll). A roll phi lifts the left wheel's contact point, at y_c = 0.74 m from the
// centre, by y_c phi, less r0 tan(delta) phi for the sideways move of a point r0 = 0.46 m below the
// axle on a profile sloping at the contact angle delta (0 to 0.12 rad on the tread): at y = 0 the
// map's slope in roll (central difference over one grid step each way) lies in [0.68, 0.75] m.
// The grid is complete and finite over the default range.
TEST_F(PlotTest, DisplacementDrawsTheRollAsALift) {
  plot_captured("displacement --grid 21", "m.png");
  const auto rows = data_rows("map.dat");  // y roll s displacement
  ASSERT_EQ(rows.size(), 21u * 21u);
  for (const auto& row : rows) {
    ASSERT_EQ(row.size(), 4u);
    EXPECT_TRUE(std::isfinite(row[3])) << "y " << row[0] << " roll " << row[1];
  }
  const auto& below = rows[9 * 21 + 10];  // y = 0, one roll step below 0
  const auto& level = rows[10 * 21 + 10];
  const auto& above = rows[11 * 21 + 10];
  ASSERT_NEAR(level[0], 0.0, 1e-15);
  ASSERT_NEAR(level[1], 0.0, 1e-15);
  const double slope = (above[3] - below[3]) / (above[1] - below[1]);  // [m/rad]
  EXPECT_GT(slope, 0.68);
  EXPECT_LT(slope, 0.75);
}

// What `wrc plot profiles` draws (y = 5 mm): the rigid wheelset sits on its rails, so each
// wheel's contact point, drawn on its own, lies on the drawn rail curve and on the drawn wheel
// curve (both sampled at 801 points over their profiles: within 0.05 mm of the polylines), and it
// is one of the drawn potential points, a local minimum.
TEST_F(PlotTest, ProfilesDrawTheContactPointOnBothCurves) {
  plot_captured("profiles --y 0.005", "p.png");
  // Distance [m] from (y, z) to the polyline of rows.
  auto to_curve = [](const std::vector<std::vector<double>>& rows, double y, double z) {
    double best = 1e300;
    for (std::size_t i = 1; i < rows.size(); ++i) {
      const double ay = rows[i - 1][0], az = rows[i - 1][1], by = rows[i][0], bz = rows[i][1];
      const double ly = by - ay, lz = bz - az, l2 = ly * ly + lz * lz;
      const double t = l2 > 0 ? std::clamp(((y - ay) * ly + (z - az) * lz) / l2, 0.0, 1.0) : 0.0;
      best = std::min(best, std::hypot(y - (ay + t * ly), z - (az + t * lz)));
    }
    return best;
  };
  for (const std::string side : {"left", "right"}) {
    const auto points = data_rows(side + "_points.dat");
    ASSERT_GE(points.size(), 2u) << side;
    const auto& contact = points.back();  // the contact point, after the potential points
    ASSERT_EQ(contact.size(), 2u) << side;
    EXPECT_LT(to_curve(data_rows(side + "_rail.dat"), contact[0], contact[1]), 5e-5) << side;
    EXPECT_LT(to_curve(data_rows(side + "_wheel.dat"), contact[0], contact[1]), 5e-5) << side;
    bool among_minima = false;
    for (std::size_t i = 0; i + 1 < points.size(); ++i)
      among_minima = among_minima || (points[i][2] == 1.0 && std::hypot(points[i][0] - contact[0],
                                                                        points[i][1] - contact[1]) < 1e-12);
    EXPECT_TRUE(among_minima) << side;
  }
}

// What `wrc plot irregularities` draws: the file's own samples, every channel, in m (the script
// scales them to mm), from a file `wrc irregularities` wrote.
TEST_F(PlotTest, IrregularitiesDrawTheFilesSamples) {
  const std::string csv = (dir_ / "track.csv").string();
  int status = -1;
  run_command(kCli + " irregularities --length 20 --spacing 0.5 --fade-in 5 --out " + csv + " 2>&1", &status);
  ASSERT_EQ(status, 0);
  plot_captured("irregularities " + csv, "i.png");
  std::ifstream in(csv);
  std::vector<std::vector<double>> expected;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#' || line[0] == 's') continue;  // the command line, the header
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream fields(line);
    std::vector<double> row;
    for (double v; fields >> v;) row.push_back(v);
    expected.push_back(row);
  }
  const auto drawn = data_rows("irregularities.dat");  // s alignment vertical_level cross_level gauge
  ASSERT_EQ(drawn.size(), expected.size());
  ASSERT_EQ(drawn.size(), 41u);
  for (std::size_t i = 0; i < drawn.size(); ++i) {
    ASSERT_EQ(drawn[i].size(), 5u);
    for (std::size_t k = 0; k < 5; ++k) EXPECT_NEAR(drawn[i][k], expected[i][k], 1e-6 * (1 + std::abs(expected[i][k])));
  }
  EXPECT_NE(captured_script().find("*1e3"), std::string::npos);  // drawn in mm
}

// What `wrc plot sweep` draws: one series per value of --by, each the finished rows' (x, y) in
// increasing x; a failed row is left out; the key names the group.
TEST_F(PlotTest, SweepDrawsOneSeriesPerGroup) {
  const fs::path csv = dir_ / "sweep.csv";
  {
    std::ofstream out(csv);
    out << "point [-],speed [m/s],y0 [m],status [-],final_state.y [m],error [-],wall_time [s]\n"
        << "0,20,0.001,finished,-0.004,,1\n1,10,0.001,finished,-0.003,,1\n2,30,0.001,failed,,flange climb,1\n"
        << "3,10,0.002,finished,-0.0035,,1\n4,20,0.002,finished,-0.0045,,1\n";
  }
  plot_captured("sweep " + csv.string() + " --y final_state.y --x speed --by y0", "s.png");
  EXPECT_EQ(data_rows("line0.dat"), (std::vector<std::vector<double>>{{10, -0.003}, {20, -0.004}}));
  EXPECT_EQ(data_rows("line1.dat"), (std::vector<std::vector<double>>{{10, -0.0035}, {20, -0.0045}}));
  const std::string gp = captured_script();
  EXPECT_NE(gp.find("y0 = 0.001"), std::string::npos) << gp;
  EXPECT_NE(gp.find("y0 = 0.002"), std::string::npos) << gp;
}

// What `wrc plot area` draws (S1002 on UIC60, y = 3 mm): in the rolling direction the gap near P is
// that of the wheel's circle, xi^2 / (2 r) with r about the rolling radius 0.46 m, so the outline
// at eps0 = k 25 um reaches xi = sqrt(2 r k 25 um) (grid 61: 0.67 mm spacing, the outline
// interpolated between nodes: 1.5 %); the Hertz ellipse is the ellipse of the semi-axes its key
// names (a along xi, b along eta, printed to 0.01 mm); the common point is at the origin.
TEST_F(PlotTest, AreaDrawsTheLevelLinesAndTheHertzEllipse) {
  plot_captured("area --y 0.003 --grid 61", "a.png");
  for (int k = 1; k <= 6; ++k) {
    double reach = 0.0;  // [m]
    for (const auto& row : data_rows("level_" + std::to_string(k) + ".dat")) reach = std::max(reach, std::abs(row[1]));
    EXPECT_NEAR(reach, std::sqrt(2 * 0.46 * k * 25e-6), 0.015 * reach) << "eps0 = " << 25 * k << " um";
  }
  const std::string gp = captured_script();
  const auto at = gp.find("Hertz ellipse at P, N = 75 kN (a = ");
  ASSERT_NE(at, std::string::npos) << gp;
  double a = 0, b = 0;
  ASSERT_EQ(std::sscanf(gp.c_str() + at, "Hertz ellipse at P, N = 75 kN (a = %lf mm, b = %lf mm)", &a, &b), 2);
  a *= 1e-3;
  b *= 1e-3;
  const auto ellipse = data_rows("hertz.dat");  // eta xi
  ASSERT_EQ(ellipse.size(), 361u);
  for (const auto& row : ellipse)
    EXPECT_NEAR(std::hypot(row[1] / a, row[0] / b), 1.0, 0.005) << row[0] << " " << row[1];
  EXPECT_EQ(data_rows("common.dat"), (std::vector<std::vector<double>>{{0.0, 0.0}}));
}

// Several bifurcation diagrams in one picture (`wrc plot bifurcation A.csv B.csv --labels`): what
// is handed to gnuplot, captured by a gnuplot on PATH that copies the job's script and data
// before running the real one. Each file's stable cycles of its ramp-down are one data series in
// increasing speed, in mm (the CSV's m x 1000), tread and flange cycles together, the centred
// runs left out; its key names the label and both critical speeds; a wrong number of labels or
// a file that is no bifurcation CSV is a one-line error naming it.
TEST_F(PlotTest, SeveralBifurcationDiagramsInOnePicture) {
  const std::string header =
      "branch [-],speed [m/s],state [-],amplitude [m],mean [m],yaw_amplitude [rad],frequency [Hz],growth [-],"
      "largest_contact_angle [rad],flange_contact [-],start_y [m],simulated_time [s],wall_time [s],message [-]\n";
  auto row = [](const std::string& branch, double v, const std::string& state, double a, double angle) {
    return branch + "," + std::to_string(v) + "," + state + "," + std::to_string(a) + ",0,0,19,1," +
           std::to_string(angle) + ",0,0.002,4,1,\n";
  };
  const fs::path a = dir_ / "a.csv", b = dir_ / "b.csv";
  {
    std::ofstream out(a);
    out << header << row("centred", 150, "centred", 1e-7, 0.02) << row("ramp-down", 200, "limit-cycle", 5e-4, 0.065)
        << row("ramp-down", 150, "limit-cycle", 4e-4, 0.5) << row("ramp-down", 140, "centred", 1e-7, 0.02)
        << row("nonlinear-critical", 150, "limit-cycle", 4e-4, 0.5);
  }
  {
    std::ofstream out(b);
    out << header << row("ramp-down", 200, "limit-cycle", 4.5e-4, 0.065) << row("ramp-down", 190, "centred", 0, 0.02)
        << row("nonlinear-critical", 200, "limit-cycle", 4.5e-4, 0.065) << row("linear-critical", 385, "", 0, 0);
  }
  plot_captured("bifurcation " + a.string() + " " + b.string() + " --labels spline,multipoint", "both.png");
  const fs::path capture = this->capture();
  int status = -1;
  // Each file's (speed [m/s], amplitude [mm]) rows.
  const auto first = data_rows("0-cycles.dat"), second = data_rows("1-cycles.dat");
  ASSERT_EQ(first.size(), 2u);
  ASSERT_EQ(second.size(), 1u);
  EXPECT_EQ(first[0], (std::vector<double>{150.0, 0.4}));
  EXPECT_EQ(first[1], (std::vector<double>{200.0, 0.5}));
  EXPECT_EQ(second[0], (std::vector<double>{200.0, 0.45}));
  const std::string gp = captured_script();
  EXPECT_NE(gp.find("spline: stable cycles, V_nl = 150.00 m/s\""), std::string::npos) << gp;
  EXPECT_NE(gp.find("multipoint: stable cycles, V_nl = 200.00 m/s, V_c = 385.00 m/s\""), std::string::npos) << gp;
  EXPECT_EQ(std::count_if(fs::directory_iterator(capture), fs::directory_iterator(),
                          [](const fs::directory_entry& e) { return e.path().extension() == ".dat"; }),
            2);

  const struct {
    std::string args, message;
  } bad[] = {
      {a.string() + " " + b.string() + " --labels spline", "names 1 diagrams for 2 files"},
      {a.string() + " " + (dir_ / "history.csv").string(), "not a CSV of wrc bifurcation"},
  };
  {
    std::ofstream history(dir_ / "history.csv");
    history << "t [s],y [m]\n0,0\n";
  }
  for (const auto& c : bad) {
    const std::string error =
        run_command(kCli + " plot bifurcation " + c.args + " --out " + (dir_ / "bad.png").string() + " 2>&1 >/dev/null",
                    &status);
    EXPECT_NE(status, 0) << c.args;
    EXPECT_NE(error.find(c.message), std::string::npos) << c.args << ": " << error;
    EXPECT_EQ(std::count(error.begin(), error.end(), '\n'), 1) << error;
  }
  EXPECT_FALSE(fs::exists(dir_ / "bad.png"));
}

// Bad input: one line on stderr naming the bad value, no picture.
TEST_F(PlotTest, BadOptionsGiveOneLineErrors) {
  const struct {
    std::string args, message;
  } cases[] = {
      {"distance --y 0.003 --out " + (dir_ / "x.jpg").string(), "must end in .png or .svg"},
      {"distance --y 0.003 --width 5 --out " + (dir_ / "x.png").string(), "--width 5"},
      {"distance --y abc", "--y"},
      {"nosuchkind", "unknown kind 'nosuchkind'"},
      {"run " + (dir_ / "missing.csv").string(), "cannot read the run history"},
      {"run", "give at least one history file"},
      {"geometry --y-from 0.01 --y-to -0.01", "--y-to"},
      {"area --y 0.008 --grid 21 --spline --samples 5x5", "outside the spline model's box: y = 0.008 m"},
  };
  for (const auto& c : cases) {
    int status = -1;
    const std::string text = run_command(kCli + " plot " + c.args + " 2>&1 >/dev/null", &status);
    EXPECT_NE(status, 0) << c.args;
    EXPECT_NE(text.find(c.message), std::string::npos) << c.args << ": " << text;
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << c.args << ": " << text;
  }
  EXPECT_FALSE(fs::exists(dir_ / "x.png"));
}

// Without gnuplot on PATH: one line naming the package.
TEST_F(PlotTest, MissingGnuplotGivesOneLineError) {
  const std::string out = (dir_ / "nognuplot.png").string();
  int status = -1;
  const std::string text = run_command("PATH=/nonexistent " + kCli + " plot distance --y 0.003 --out " + out + " 2>&1", &status);
  EXPECT_NE(status, 0);
  EXPECT_NE(text.find("gnuplot-nox"), std::string::npos) << text;
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;
  EXPECT_FALSE(fs::exists(out));
}

// gnuplot failing: its exit status is checked and its stderr reported on one line, no picture.
TEST_F(PlotTest, FailingGnuplotIsReported) {
  const fs::path fake = dir_ / "bin";
  fs::create_directories(fake);
  {
    std::ofstream script(fake / "gnuplot");
    script << "#!/bin/sh\necho 'line 3: undefined variable: boom' >&2\nexit 1\n";
  }
  fs::permissions(fake / "gnuplot", fs::perms::owner_all);
  const std::string out = (dir_ / "failed.png").string();
  int status = -1;
  const std::string text = run_command("PATH=" + fake.string() + ":/usr/bin:/bin " + kCli +
                                           " plot distance --y 0.003 --out " + out + " 2>&1",
                                       &status);
  EXPECT_NE(status, 0);
  EXPECT_NE(text.find("gnuplot failed (exit status 1): line 3: undefined variable: boom"), std::string::npos) << text;
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace wrc::bus::test
