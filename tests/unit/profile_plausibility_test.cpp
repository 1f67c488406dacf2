// SPDX-License-Identifier: Apache-2.0
// Profile files that cannot be a wheel or rail profile are refused with "file: reason" naming the
// value (profile_limits.hpp): a length unit off by 1000, an upside-down wheel or rail, a spike, an
// excessive flange, an absurd value (with its line), and files that are not regular or too large.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "core/profile/profile_error.hpp"
#include "core/profile/profile_file.hpp"
#include "core/profile/profile_limits.hpp"

namespace wrc {
namespace {

namespace fs = std::filesystem;

class ProfilePlausibility : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("wrc-plausibility-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Writes a text profile file (header lines, then "lateral height" per point) and returns its path.
  std::string write(const std::string& name, const std::string& header, const std::vector<std::pair<double, double>>& points) {
    const std::string path = (dir_ / name).string();
    std::ofstream out(path);
    out << header;
    out.precision(17);
    for (const auto& [a, b] : points) out << a << " " << b << "\n";
    return path;
  }

  // Reads path as side and expects a ProfileError at line whose reason holds every word of reasons.
  static void expect_error(const std::string& path, ProfileSide side, int line, std::vector<std::string> reasons) {
    try {
      read_profile_file(path, side);
      ADD_FAILURE() << path << ": no error";
    } catch (const ProfileError& e) {
      EXPECT_EQ(e.source(), path);
      EXPECT_EQ(e.line(), line) << e.what();
      EXPECT_EQ(std::string(e.what()).rfind(path + ":", 0), 0u) << e.what();
      for (const std::string& r : reasons) EXPECT_NE(e.reason().find(r), std::string::npos) << r << " in " << e.what();
    }
  }

  fs::path dir_;
};

// A 1:40 cone wheel over s = -70..60 mm: F = -s/40 (plus a flange of flange_mm at s = -35 mm when given).
std::vector<std::pair<double, double>> cone_mm(double sign = 1.0, double flange_mm = 0.0) {
  std::vector<std::pair<double, double>> p;
  for (int s = -70; s <= 60; s += 2) {
    double f = -s / 40.0;
    if (flange_mm > 0 && s < -20) f += flange_mm * std::exp(-std::pow((s + 45) / 10.0, 2));
    p.emplace_back(s, sign * f);
  }
  return p;
}

// A rail head of crown radius 300 mm over u = -35..35 mm: v = -u^2 / 600 (mm).
std::vector<std::pair<double, double>> rail_mm(double sign = 1.0) {
  std::vector<std::pair<double, double>> p;
  for (int u = -35; u <= 35; ++u) p.emplace_back(u, sign * -u * u / 600.0);
  return p;
}

TEST_F(ProfilePlausibility, PlausibleWheelAndRailAreRead) {
  EXPECT_NO_THROW(read_profile_file(write("cone.txt", "", cone_mm(1.0, 28.0)), ProfileSide::kWheel));
  EXPECT_NO_THROW(read_profile_file(write("rail.txt", "", rail_mm()), ProfileSide::kRail));
}

// A wheel in metres read as millimetres: 0.14 mm wide.
TEST_F(ProfilePlausibility, LengthUnitOffByAThousand) {
  std::vector<std::pair<double, double>> metres;
  for (const auto& [s, f] : cone_mm()) metres.emplace_back(s * 1e-3, f * 1e-3);
  expect_error(write("wheel_m_as_mm.txt", "# units: mm\n", metres), ProfileSide::kWheel, 0,
               {"implausible wheel profile", "width 0.13 mm", "below 5 mm", "length unit"});
  // Millimetres read as metres: the first point already lies 70 m out.
  expect_error(write("wheel_mm_as_m.txt", "# units: m\n", cone_mm()), ProfileSide::kWheel, 2,
               {"value -70 m", "beyond +-1 m", "length unit"});
}

TEST_F(ProfilePlausibility, UpsideDownProfiles) {
  expect_error(write("wheel_upside_down.txt", "", cone_mm(-1.0, 28.0)), ProfileSide::kWheel, 0,
               {"implausible wheel profile", "mean slope", "upside down", "negative contact angles"});
  expect_error(write("rail_upside_down.txt", "", rail_mm(-1.0)), ProfileSide::kRail, 0,
               {"implausible rail profile", "below the chord", "upside down"});
}

// A 100 mm spike on one point of a rail head (file line 36: the 36th point), and on a wheel.
TEST_F(ProfilePlausibility, SpikeNamesItsLine) {
  std::vector<std::pair<double, double>> rail = rail_mm();
  rail[35].second += 100.0;
  expect_error(write("rail_spike.txt", "", rail), ProfileSide::kRail, 36, {"spike of 100", "mm above"});
  std::vector<std::pair<double, double>> wheel = cone_mm();
  wheel[50].second -= 100.0;
  expect_error(write("wheel_spike.txt", "", wheel), ProfileSide::kWheel, 0, {"height range", "above 60 mm"});
}

TEST_F(ProfilePlausibility, FlangeTooHigh) {
  expect_error(write("wheel_flange.txt", "", cone_mm(1.0, 45.0)), ProfileSide::kWheel, 0,
               {"flange height 4", "above 40 mm"});
}

// 1e300 (mm) fails at its line, as every malformed value does.
TEST_F(ProfilePlausibility, AbsurdValueNamesItsLine) {
  std::vector<std::pair<double, double>> p = cone_mm();
  p[3].second = 1e300;
  expect_error(write("wheel_1e300.txt", "# a header comment\n", p), ProfileSide::kWheel, 5,
               {"value 1e+297 m", "beyond +-1 m"});
}

// A FIFO and a character device are refused at once (no blocking, no endless read: either would
// hang this test until CTest's timeout stops it; the time taken is printed).
TEST_F(ProfilePlausibility, OnlyRegularFiles) {
  const std::string fifo = (dir_ / "wheel.fifo").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const auto t0 = std::chrono::steady_clock::now();
  expect_error(fifo, ProfileSide::kWheel, 0, {"not a regular file (a FIFO)"});
  expect_error("/dev/urandom", ProfileSide::kWheel, 0, {"not a regular file (a character device)"});
  expect_error(dir_.string(), ProfileSide::kWheel, 0, {"not a regular file (a directory)"});
  std::cout << "[ measured ] refusing a FIFO, a device and a directory: "
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s\n";
}

TEST_F(ProfilePlausibility, SizeLimit) {
  const std::string path = (dir_ / "huge.txt").string();
  {
    std::ofstream out(path);
    const std::string comment = "# " + std::string(1000, 'x') + "\n";
    for (std::size_t written = 0; written <= kMaxProfileFileBytes; written += comment.size()) out << comment;
  }
  expect_error(path, ProfileSide::kWheel, 0, {"file too large", "bytes (at most 4194304)"});
}

}  // namespace
}  // namespace wrc
