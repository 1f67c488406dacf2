// SPDX-License-Identifier: Apache-2.0
// `wrc geometry`, `points`, `area`, `conicity` and `creep` as the user runs them (the built front end,
// WRC_CLI_PATH): exit status, the CSV header as docs/cli.md / --help document it, and the values against
// independent references: closed forms of a conic wheel on a circular rail head (derived in
// tests/unit/geometry_cone_circle_test.cpp and geometry_contact_area_test.cpp and re-derived here
// from elementary geometry, not from the library), mirror symmetry of S1002/UIC60, Kalker's linear
// theory evaluated by hand with the coefficients tabulated in docs/contact-mechanics.md, and the
// FASTSIM discretisation error documented in docs/validation.md. Bad input fails with one line naming the value.
// None of these tests needs the bus; they run in the process-test binary because they run processes.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "bus_fixture.hpp"

namespace wrc::bus::test {
namespace {

const std::string kCli = WRC_CLI_PATH;

// The cone-on-circle track of the unit tests: gauge 1.5 m at the top of rail, no inclination, so
// the crown tops lie at y = +-0.75 m, right below the taping lines (taping half distance a =
// 1.360 / 2 + 0.070 = 0.75 m with the default flange-back spacing and taping-line offset).
const std::string kConeTrack = " --gauge 1.5 --gauge-depth 0 --inclination none";
constexpr double kA = 0.75;   // taping half distance [m]
constexpr double kR0 = 0.46;  // nominal radius [m] (default --r0)
constexpr double kYc = 0.75;  // lateral position of the rail crown [m]

// ---------------------------------------------------------------------------------------------
// Output parsing.

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, sep);) parts.push_back(item);
  return parts;
}

struct Csv {
  std::string header;
  std::map<std::string, size_t> column;
  std::vector<std::vector<double>> rows;
  double at(size_t row, const std::string& name) const {
    const auto it = column.find(name);
    if (it == column.end()) {
      ADD_FAILURE() << "no column " << name << " in " << header;
      return NAN;
    }
    return rows.at(row).at(it->second);
  }
};

Csv parse_csv(const std::string& out) {
  Csv csv;
  const auto lines = split(out, '\n');
  if (lines.empty()) return csv;
  csv.header = lines[0];
  const auto names = split(lines[0], ',');
  for (size_t i = 0; i < names.size(); ++i) csv.column[names[i]] = i;
  for (size_t l = 1; l < lines.size(); ++l) {
    if (lines[l].empty()) continue;
    std::vector<double> row;
    for (const auto& field : split(lines[l], ',')) row.push_back(std::strtod(field.c_str(), nullptr));
    EXPECT_EQ(row.size(), names.size()) << lines[l];
    csv.rows.push_back(row);
  }
  return csv;
}

// Runs `wrc-cli args` and returns its standard output; expects exit status 0.
std::string run_ok(const std::string& args) {
  int status = -1;
  const std::string out = run_command(kCli + " " + args, &status);
  EXPECT_EQ(status, 0) << "wrc " << args << "\n" << out;
  return out;
}

// ---------------------------------------------------------------------------------------------
// Closed form of a cone F(s) = -lambda s on a circular rail head of radius rho, zero yaw (the
// derivation of tests/unit/geometry_cone_circle_test.cpp): the left wheel's bottom generator has
// track slope tan(gamma + roll), gamma = atan(lambda); the circle has that slope at
// y_c - rho sin(gamma + roll); the right wheel mirrors with gamma - roll.

struct ConeOnCircle {
  double lambda, rho;

  struct Point {
    double s, distance, angle, radius;
  };

  Point left(double y, double z, double roll) const {
    const double c = std::cos(roll), sn = std::sin(roll);
    Point p;
    p.angle = std::atan(lambda) + roll;
    const double y_rail = kYc - rho * std::sin(p.angle);
    p.s = (y_rail - y - kA * c - kR0 * sn) / (c - lambda * sn);
    const double z_wheel = z + (kA + p.s) * sn - (kR0 - lambda * p.s) * c;
    p.distance = z_wheel - (-rho + rho * std::cos(p.angle));
    p.radius = kR0 - lambda * p.s;
    return p;
  }
  Point right(double y, double z, double roll) const {
    const double c = std::cos(roll), sn = std::sin(roll);
    Point p;
    p.angle = std::atan(lambda) - roll;
    const double y_rail = -kYc + rho * std::sin(p.angle);
    p.s = (y_rail - y + kA * c - kR0 * sn) / (-c - lambda * sn);
    const double z_wheel = z - (kA + p.s) * sn - (kR0 - lambda * p.s) * c;
    p.distance = z_wheel - (-rho + rho * std::cos(p.angle));
    p.radius = kR0 - lambda * p.s;
    return p;
  }

  // Rigid wheelset: the roll at which both wheels' distances are equal (bisection to round-off),
  // and the height at which they are zero.
  struct Rigid {
    double roll, z;
    Point l, r;
  };
  Rigid rigid(double y) const {
    double lo = -0.05, hi = 0.05;
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      (left(y, 0, mid).distance - right(y, 0, mid).distance > 0 ? hi : lo) = mid;
    }
    Rigid g;
    g.roll = 0.5 * (lo + hi);
    g.z = -left(y, 0, g.roll).distance;
    g.l = left(y, g.z, g.roll);
    g.r = right(y, g.z, g.roll);
    return g;
  }

  // Small-shift limit (first order in y and roll): K = rho cos(gamma) + r0 is the lever of roll
  // about the rail head centre; roll = lambda y / (a - lambda K), delta_r = 2 lambda a y / (a - lambda K).
  double lever() const { return rho * std::cos(std::atan(lambda)) + kR0; }
  double roll_per_y() const { return lambda / (kA - lambda * lever()); }
  double delta_r_per_y() const { return 2 * lambda * kA / (kA - lambda * lever()); }
};

// ---------------------------------------------------------------------------------------------
// geometry

const char* const kGeometryHeader =
    "y,z,roll,r_left,r_right,delta_r,angle_left,angle_right,s_left,s_right,u_left,u_right,x_left,x_right,"
    "n_left,n_right,minima_left,minima_right";

// Verifies the documented CSV header (docs/cli.md and the column list of --help), and
// that the centred S1002/UIC60 wheelset (y = 0) is level: roll 0, equal radii, contact angles and
// wheel coordinates, delta_r 0. Tolerances: the solver makes the two wheels' heights equal to
// 1e-12 m, and a roll error changes that difference with a lever of about 2a = 1.5 m, so roll is 0
// to 1e-12 rad; delta_r and the radii move by at most lambda K roll with K < 1 m (1e-12 m); s
// (per wheel, its own mirrored coordinate) by K roll / lambda_e < 1e-10 m.
TEST(GeometryCommand, CentredWheelsetIsLevel) {
  const std::string help = run_ok("geometry --help");
  for (const auto& name : split(kGeometryHeader, ','))
    EXPECT_NE(help.find(name), std::string::npos) << name << " missing from --help";
  const Csv csv = parse_csv(run_ok("geometry --y-from 0 --y-to 0 --y-step 0.001 --format csv"));
  EXPECT_EQ(csv.header, kGeometryHeader);
  ASSERT_EQ(csv.rows.size(), 1u);
  EXPECT_EQ(csv.at(0, "y"), 0.0);
  EXPECT_NEAR(csv.at(0, "roll"), 0.0, 1e-12);
  EXPECT_NEAR(csv.at(0, "delta_r"), 0.0, 1e-12);
  EXPECT_NEAR(csv.at(0, "r_left"), csv.at(0, "r_right"), 1e-12);
  EXPECT_NEAR(csv.at(0, "angle_left"), csv.at(0, "angle_right"), 1e-9);
  EXPECT_NEAR(csv.at(0, "s_left"), csv.at(0, "s_right"), 1e-10);
  EXPECT_EQ(csv.at(0, "n_left"), csv.at(0, "n_right"));
  EXPECT_EQ(csv.at(0, "minima_left"), csv.at(0, "minima_right"));
  // The centre of the wheelset lies about r0 above the top of rail (tread contact, r close to r0).
  EXPECT_NEAR(csv.at(0, "z"), kR0, 1e-3);
  EXPECT_NEAR(csv.at(0, "r_left"), kR0, 1e-3);
}

// Verifies mirror symmetry of S1002/UIC60 (both profiles and the track are symmetric): the row at
// -y is the row at y with the wheels swapped: z equal, roll and delta_r opposite, r, contact angle,
// s, u, x, and the point counts of left and right exchanged. Range +-6 mm (tread and flange root,
// both jumps near 0.2 and 5.2 mm inside), step 0.5 mm. Tolerance 1e-10 (m, rad), the symmetry the
// unit tests assert for the solver; the rows are solved with different warm starts (from -6 mm
// upwards), so this also checks that the warm start does not change the answer. Printed precision
// (12 digits for z and radii, 10 for the rest) is far below it.
TEST(GeometryCommand, MirrorSymmetry) {
  const Csv csv = parse_csv(run_ok("geometry --y-from -0.006 --y-to 0.006 --y-step 0.0005 --format csv"));
  EXPECT_EQ(csv.header, kGeometryHeader);
  ASSERT_EQ(csv.rows.size(), 25u);
  const size_t n = csv.rows.size();
  for (size_t i = 0; i < n; ++i) {
    const size_t j = n - 1 - i;
    const double y = csv.at(i, "y");
    ASSERT_NEAR(csv.at(j, "y"), -y, 1e-15);
    EXPECT_NEAR(csv.at(j, "z"), csv.at(i, "z"), 1e-10) << y;
    EXPECT_NEAR(csv.at(j, "roll"), -csv.at(i, "roll"), 1e-10) << y;
    EXPECT_NEAR(csv.at(j, "delta_r"), -csv.at(i, "delta_r"), 1e-10) << y;
    for (const char* q : {"r", "angle", "s", "u", "x", "n", "minima"}) {
      const std::string l = std::string(q) + "_left", r = std::string(q) + "_right";
      EXPECT_NEAR(csv.at(j, l), csv.at(i, r), 1e-10) << q << " y=" << y;
      EXPECT_NEAR(csv.at(j, r), csv.at(i, l), 1e-10) << q << " y=" << y;
    }
    // Zero yaw: both contacts lie below the axle.
    EXPECT_EQ(csv.at(i, "x_left"), 0.0);
    EXPECT_EQ(csv.at(i, "x_right"), 0.0);
    // delta_r is the difference of the printed radii; its sign follows y (y > 0: the left wheel
    // runs on a larger radius, roll > 0 raises the left wheel).
    EXPECT_NEAR(csv.at(i, "delta_r"), csv.at(i, "r_left") - csv.at(i, "r_right"), 1e-11) << y;
    if (y > 1e-9) {
      EXPECT_GT(csv.at(i, "delta_r"), 0.0) << y;
      EXPECT_GT(csv.at(i, "roll"), 0.0) << y;
    }
  }
}

// Verifies `geometry --wheel conic:0.025 --rail circle:0.3` on the cone track against the closed
// form above (an independent bisection on the closed-form distances, to round-off): z, roll, both
// radii, delta_r, contact angles (gamma +- roll) and wheel coordinates, one potential point per
// wheel. Tolerances as in the unit test: the solver's height tolerance is 1e-12 m and roll enters
// with a lever of 0.75 m, so 1e-10 m / rad; the contact angle 1e-9 (printed with 9 digits: 5e-11).
// Then the small-shift limit roll / y = lambda / (a - lambda K), delta_r / y = 2 lambda a / (a -
// lambda K) to 1e-4 relative: what the first-order formulas neglect are products of two small
// quantities, lambda roll <= 0.025 * 1.4e-4 = 3.4e-6 and lambda^2 rho / a = 2.5e-4 before the two
// wheels' terms cancel (the unit test observes 1.7e-5 at lambda = 0.05, rho = 0.1); the closed form
// itself is compared with the formula here too, so a wrong formula cannot pass unnoticed.
TEST(GeometryCommand, ConeOnCircleMatchesClosedForm) {
  const ConeOnCircle cone{0.025, 0.3};
  const Csv csv = parse_csv(run_ok("geometry --wheel conic:0.025 --rail circle:0.3" + kConeTrack +
                                   " --y-from -0.004 --y-to 0.004 --y-step 0.001 --format csv"));
  EXPECT_EQ(csv.header, kGeometryHeader);
  ASSERT_EQ(csv.rows.size(), 9u);
  for (size_t i = 0; i < csv.rows.size(); ++i) {
    const double y = csv.at(i, "y");
    const ConeOnCircle::Rigid f = cone.rigid(y);
    EXPECT_NEAR(csv.at(i, "z"), f.z, 1e-10) << y;
    EXPECT_NEAR(csv.at(i, "roll"), f.roll, 1e-10) << y;
    EXPECT_NEAR(csv.at(i, "r_left"), f.l.radius, 1e-10) << y;
    EXPECT_NEAR(csv.at(i, "r_right"), f.r.radius, 1e-10) << y;
    EXPECT_NEAR(csv.at(i, "delta_r"), f.l.radius - f.r.radius, 1e-10) << y;
    EXPECT_NEAR(csv.at(i, "angle_left"), f.l.angle, 1e-9) << y;
    EXPECT_NEAR(csv.at(i, "angle_right"), f.r.angle, 1e-9) << y;
    EXPECT_NEAR(csv.at(i, "s_left"), f.l.s, 1e-10) << y;
    EXPECT_NEAR(csv.at(i, "s_right"), f.r.s, 1e-10) << y;
    for (const char* q : {"n_left", "n_right", "minima_left", "minima_right"}) EXPECT_EQ(csv.at(i, q), 1.0) << q;
    if (std::fabs(y) > 1e-9) {
      EXPECT_NEAR(csv.at(i, "roll") / y, cone.roll_per_y(), 1e-4 * cone.roll_per_y()) << y;
      EXPECT_NEAR(csv.at(i, "delta_r") / y, cone.delta_r_per_y(), 1e-4 * cone.delta_r_per_y()) << y;
      EXPECT_NEAR(f.roll / y, cone.roll_per_y(), 1e-4 * cone.roll_per_y()) << y;
    } else {
      EXPECT_NEAR(csv.at(i, "roll"), 0.0, 1e-12);
      EXPECT_NEAR(csv.at(i, "delta_r"), 0.0, 1e-12);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// points

const char* const kPointsHeader =
    "s,u,x,y,z,distance,angle,rolling_radius,wheel_curvature,rail_curvature,local_min,common";

// Verifies `points --y 0.005` (S1002/UIC60, left wheel, tread and flange root both close): several
// potential points (docs/cli.md: 3 on S1002/UIC60 at 5 mm), flange first (s increasing); exactly one
// common point, which is a local minimum and the lowest one (on a tie the one farthest from the
// flange, i.e. the largest s). Consecutive critical points of the smooth distance along C alternate
// between minima and maxima. Independent geometry at zero roll and yaw: the wheel point lies below
// the axle (x = 0), at the lateral position y + a + s (s is the lateral coordinate from the taping
// line) and at z - r (z = r0 by default); printed with 13 digits, so 1e-12 m. The right wheel at
// -y is the mirror image: the same rows with the lateral position negated (1e-10, the symmetry the
// unit tests assert).
TEST(PointsCommand, CommonPointIsTheLowestMinimum) {
  const Csv csv = parse_csv(run_ok("points --y 0.005 --format csv"));
  EXPECT_EQ(csv.header, kPointsHeader);
  const std::string help = run_ok("points --help");
  for (const char* name : {"local_min", "common", "distance", "rolling radius", "contact angle"})
    EXPECT_NE(help.find(name), std::string::npos) << name;
  ASSERT_GE(csv.rows.size(), 3u);
  int commons = 0;
  size_t common = 0;
  for (size_t i = 0; i < csv.rows.size(); ++i) {
    if (csv.at(i, "common") == 1.0) {
      ++commons;
      common = i;
    }
    if (i > 0) {
      EXPECT_GT(csv.at(i, "s"), csv.at(i - 1, "s")) << "rows not ordered flange first";
      EXPECT_NE(csv.at(i, "local_min"), csv.at(i - 1, "local_min")) << "minima and maxima do not alternate at " << i;
    }
    EXPECT_EQ(csv.at(i, "x"), 0.0);
    EXPECT_NEAR(csv.at(i, "y"), 0.005 + kA + csv.at(i, "s"), 1e-12) << i;
    EXPECT_NEAR(csv.at(i, "z"), kR0 - csv.at(i, "rolling_radius"), 1e-12) << i;
  }
  ASSERT_EQ(commons, 1);
  EXPECT_EQ(csv.at(common, "local_min"), 1.0);
  int minima = 0;
  for (size_t i = 0; i < csv.rows.size(); ++i) {
    if (csv.at(i, "local_min") != 1.0) continue;
    ++minima;
    const double d = csv.at(i, "distance"), dc = csv.at(common, "distance");
    EXPECT_TRUE(d > dc || (d == dc && csv.at(i, "s") <= csv.at(common, "s")))
        << "minimum at s = " << csv.at(i, "s") << " lies lower than the common point";
  }
  EXPECT_GE(minima, 2);  // the flange root and the tread

  const Csv mirror = parse_csv(run_ok("points --y -0.005 --wheel-side right --format csv"));
  ASSERT_EQ(mirror.rows.size(), csv.rows.size());
  for (size_t i = 0; i < csv.rows.size(); ++i) {
    for (const char* q : {"s", "distance", "angle", "rolling_radius", "z", "local_min", "common"})
      EXPECT_NEAR(mirror.at(i, q), csv.at(i, q), 1e-10) << q << " row " << i;
    EXPECT_NEAR(mirror.at(i, "y"), -csv.at(i, "y"), 1e-10) << i;
  }
}

// Verifies that `points` and `geometry` agree: at the rigid pose `geometry` prints for y = 5 mm
// (roll, z), each wheel's common point touches (distance 0) at the wheel coordinate `geometry`
// reports. Tolerance: z is printed with 12 digits (5e-13 m) and roll with 10 (5e-10 relative of
// 6e-4 rad, times a lever of 0.75 m: 2e-13 m), so 1e-11 m; s to 1e-9 m (the tread's conicity near
// 0.1 turns 1e-11 m of height into 1e-10 m along the profile).
TEST(PointsCommand, TouchesAtTheRigidPose) {
  const Csv g = parse_csv(run_ok("geometry --y-from 0.005 --y-to 0.005 --y-step 0.001 --format csv"));
  ASSERT_EQ(g.rows.size(), 1u);
  char pose[160];
  std::snprintf(pose, sizeof pose, " --y 0.005 --roll %.9e --z %.12g --format csv", g.at(0, "roll"), g.at(0, "z"));
  for (const char* side : {"left", "right"}) {
    const Csv p = parse_csv(run_ok(std::string("points --wheel-side ") + side + pose));
    int found = 0;
    for (size_t i = 0; i < p.rows.size(); ++i) {
      if (p.at(i, "common") != 1.0) continue;
      ++found;
      EXPECT_NEAR(p.at(i, "distance"), 0.0, 1e-11) << side;
      EXPECT_NEAR(p.at(i, "s"), g.at(0, std::string("s_") + side), 1e-9) << side;
      EXPECT_NEAR(p.at(i, "rolling_radius"), g.at(0, std::string("r_") + side), 1e-9) << side;
    }
    EXPECT_EQ(found, 1) << side;
  }
}

// ---------------------------------------------------------------------------------------------
// area

// Verifies `area` for the cone (lambda = 0.025) on the circle (rho = 0.3 m) at y = 0 and at
// y = 3 mm with roll 2 mrad (left wheel) against the Hertz ellipse of the local curvatures, all in
// closed form: near P the gap is A xi^2 + B eta^2 with A = cos(gamma) / (2 r) (Meusnier: the
// rolling circle of radius r seen in the normal section; rail straight along x) and B = 1 / (2 rho)
// (cone generator straight), r = r0 - lambda s from the closed-form contact point. {gap < eps0} is
// the ellipse with semi-axes a = sqrt(eps0 / A), b = sqrt(eps0 / B), area pi eps0 / sqrt(A B).
// Tolerances, from tests/unit/geometry_contact_area_test.cpp:
//  * grid: the column sum misses at most 0.21 * 2 b sqrt(2/a) h^1.5 (1 + h/a) per tip of the
//    ellipse (two tips), h the node spacing; taken for whichever direction the sum runs (the larger
//    of the two), since this test does not know it;
//  * higher-order terms of the gap: eta^4/(8 rho^3), xi^4/(8 Rn^3) and the cone radius changing
//    across eta, relative b^2/(4 rho^2) + a^2/(4 Rn^2) + (lambda b / r)^2, times 2 of margin; the
//    extents move by half of it (they come from the row and column through P, an odd grid, and are
//    exact for the quadratic);
//  * printing: area in mm^2 and extents in mm with 4 decimals (5e-11 m^2, 5e-8 m).
TEST(AreaCommand, ConeOnCircleIsTheHertzEllipse) {
  const ConeOnCircle cone{0.025, 0.3};
  const double eps0 = 5e-6;
  struct Pose {
    double y, roll;
  };
  for (const Pose pose : {Pose{0.0, 0.0}, Pose{0.003, 0.002}}) {
    const ConeOnCircle::Point p = cone.left(pose.y, 0.0, pose.roll);
    const double A = std::cos(std::atan(cone.lambda)) / (2 * p.radius), B = 1 / (2 * cone.rho);
    const double a = std::sqrt(eps0 / A), b = std::sqrt(eps0 / B);
    const double exact = M_PI * eps0 / std::sqrt(A * B);
    const int nodes = 121;
    const double half_width = 1.25 * std::max(a, b);
    char args[256];
    std::snprintf(args, sizeof args, " --y %.17g --roll %.17g --eps0 %.17g --grid %d --half-width %.17g", pose.y,
                  pose.roll, eps0, nodes, half_width);
    const std::string out =
        run_ok("area --wheel conic:0.025 --rail circle:0.3" + kConeTrack + args);
    // The summary row: eps0[um] area[mm2] xi_min xi_max eta_min eta_max xi_c eta_c patches ...
    const auto header = out.find("eps0[um]");
    ASSERT_NE(header, std::string::npos) << out;
    const auto row = out.find('\n', header);
    ASSERT_NE(row, std::string::npos) << out;
    double e, area, xi_min, xi_max, eta_min, eta_max, xi_c, eta_c;
    int patches = 0;
    ASSERT_EQ(std::sscanf(out.c_str() + row + 1, "%lf %lf %lf %lf %lf %lf %lf %lf %d", &e, &area, &xi_min, &xi_max,
                          &eta_min, &eta_max, &xi_c, &eta_c, &patches),
              9)
        << out;
    EXPECT_NEAR(e, 5.0, 1e-12);
    area *= 1e-6;
    xi_min *= 1e-3, xi_max *= 1e-3, eta_min *= 1e-3, eta_max *= 1e-3, xi_c *= 1e-3, eta_c *= 1e-3;

    const double h = 2 * half_width / (nodes - 1);
    auto tips = [&](double along, double across) {
      return 2 * 0.21 * 2 * across * std::sqrt(2 / along) * std::pow(h, 1.5) * (1 + h / along);
    };
    const double grid_bound = std::max(tips(a, b), tips(b, a));
    const double rn = 1 / (2 * A);
    const double rel_geom = 2 * (b * b / (4 * cone.rho * cone.rho) + a * a / (4 * rn * rn) +
                                 std::pow(cone.lambda * b / p.radius, 2));
    EXPECT_NEAR(area, exact, grid_bound + rel_geom * exact + 5e-11) << "y=" << pose.y;
    EXPECT_LT(grid_bound / exact, 2.5e-3);  // the bound itself is tight enough to mean something
    const double tol_xi = 0.5 * rel_geom * a + 5e-8, tol_eta = 0.5 * rel_geom * b + 5e-8;
    EXPECT_NEAR(xi_max, a, tol_xi) << "y=" << pose.y;
    EXPECT_NEAR(-xi_min, a, tol_xi) << "y=" << pose.y;
    EXPECT_NEAR(eta_max, b, tol_eta) << "y=" << pose.y;
    EXPECT_NEAR(-eta_min, b, tol_eta) << "y=" << pose.y;
    // Symmetric about P to the printed precision (along eta up to the odd cubic term, 1e-3 b).
    EXPECT_NEAR(xi_c, 0.0, 5e-8);
    EXPECT_NEAR(eta_c, 0.0, 1e-3 * b + 5e-8);
    EXPECT_EQ(patches, 1);
    std::printf("area y=%g: %.6e m^2, exact %.6e (tolerance %.2e); a %.6e / %.6e, b %.6e / %.6e\n", pose.y, area,
                exact, grid_bound + rel_geom * exact, xi_max, a, eta_max, b);
  }
}

// Verifies `area --format csv` (header xi,eta,distance as --help documents it, one row per node,
// eta outer, xi inner): the distance is 0 at P (the centre node of an odd grid; the intersections
// are solved to 1e-12 m, printed with 10 digits) and, at every node inside the box of the
// ellipse, the quadratic A xi^2 + B eta^2 of the test above to within its higher-order terms: at a
// node, relative eta^2/(4 rho^2) + xi^2/(4 Rn^2) from the quartic terms and lambda |eta| / r from the
// cone radius changing across eta (odd, so it cancels in the area but not at a node), times 2.
TEST(AreaCommand, GridIsTheGapAroundTheCommonPoint) {
  const ConeOnCircle cone{0.025, 0.3};
  const std::string help = run_ok("area --help");
  EXPECT_NE(help.find("xi,eta,distance"), std::string::npos) << help;
  const int nodes = 41;
  const double half_width = 0.003;
  const Csv csv = parse_csv(run_ok("area --wheel conic:0.025 --rail circle:0.3" + kConeTrack +
                                   " --y 0 --grid 41 --half-width 0.003 --format csv"));
  EXPECT_EQ(csv.header, "xi,eta,distance");
  ASSERT_EQ(csv.rows.size(), static_cast<size_t>(nodes * nodes));
  const ConeOnCircle::Point p = cone.left(0.0, 0.0, 0.0);
  const double A = std::cos(std::atan(cone.lambda)) / (2 * p.radius), B = 1 / (2 * cone.rho), rn = 1 / (2 * A);
  const double a = std::sqrt(5e-6 / A), b = std::sqrt(5e-6 / B);
  int checked = 0;
  for (size_t k = 0; k < csv.rows.size(); ++k) {
    const double xi = csv.at(k, "xi"), eta = csv.at(k, "eta"), d = csv.at(k, "distance");
    EXPECT_NEAR(xi, -half_width + 2 * half_width * static_cast<double>(k % nodes) / (nodes - 1), 1e-12);
    EXPECT_NEAR(eta, -half_width + 2 * half_width * static_cast<double>(k / nodes) / (nodes - 1), 1e-12);
    if (k == csv.rows.size() / 2) {
      EXPECT_NEAR(d, 0.0, 1e-10);
    }
    if (std::fabs(xi) > a || std::fabs(eta) > b) continue;
    const double q = A * xi * xi + B * eta * eta;
    const double rel = 2 * (eta * eta / (4 * cone.rho * cone.rho) + xi * xi / (4 * rn * rn) +
                            cone.lambda * std::fabs(eta) / p.radius);
    EXPECT_NEAR(d, q, rel * q + 1e-12) << "xi=" << xi << " eta=" << eta;
    ++checked;
  }
  EXPECT_GT(checked, 200);
}

// ---------------------------------------------------------------------------------------------
// conicity

// Verifies `conicity` of a cone of slope 0.025 on a knife-edge rail (circle:0.0001) on the cone
// track, header amplitude,conicity (docs/cli.md, --help), one row per amplitude:
//  * against the harmonic linearisation computed here from the closed-form rigid wheelset
//    (lambda_e = 1/(2 pi A) integral delta_r(A sin t) sin t dt, midpoint rule on 512 points, exact
//    to round-off for this smooth, nearly linear delta_r): the solver's 1e-12 m in height gives at
//    most ~1e-13 m in delta_r, divided by 2A >= 2 mm, plus 9 printed digits: 1e-8 relative;
//  * against lambda a / (a - lambda r0) (services/core/geometry/conicity.hpp, derived in
//    tests/unit/geometry_cone_circle_test.cpp) to 1e-4 relative: it neglects the knife edge's radius
//    in the lever (lambda rho / (a - lambda K) = 3.4e-6 relative) and products lambda roll
//    (<= 0.025 * 0.0342 * 6 mm = 5e-6);
//  * delta_r of a cone is linear in y (to 1e-7 relative over +-7 mm, unit test), so the conicity does
//    not depend on the amplitude: 1e-6 relative between 1 and 6 mm.
TEST(ConicityCommand, KnifeEdgeMatchesClosedForm) {
  const std::string help = run_ok("conicity --help");
  EXPECT_NE(help.find("amplitude,conicity"), std::string::npos) << help;
  const Csv csv = parse_csv(
      run_ok("conicity --wheel conic:0.025 --rail circle:0.0001" + kConeTrack + " --amplitude 0.001,0.003,0.006"));
  EXPECT_EQ(csv.header, "amplitude,conicity");
  ASSERT_EQ(csv.rows.size(), 3u);
  const double lambda = 0.025;
  const double formula = lambda * kA / (kA - lambda * kR0);
  const ConeOnCircle knife{lambda, 0.0001};
  const double amplitudes[] = {0.001, 0.003, 0.006};
  double harmonic_3mm = 0;
  for (size_t i = 0; i < 3; ++i) {
    const double amp = amplitudes[i];
    EXPECT_DOUBLE_EQ(csv.at(i, "amplitude"), amp);
    const int n = 512;
    double sum = 0;
    for (int k = 0; k < n; ++k) {
      const double t = 2 * M_PI * (k + 0.5) / n;
      const ConeOnCircle::Rigid g = knife.rigid(amp * std::sin(t));
      sum += (g.l.radius - g.r.radius) * std::sin(t);
    }
    const double harmonic = sum * (2 * M_PI / n) / (2 * M_PI * amp);
    const double c = csv.at(i, "conicity");
    if (i == 1) harmonic_3mm = harmonic;
    EXPECT_NEAR(c, harmonic, 1e-8 * harmonic) << amp;
    EXPECT_NEAR(c, formula, 1e-4 * formula) << amp;
    EXPECT_NEAR(c, csv.at(0, "conicity"), 1e-6 * formula) << amp;
  }
  std::printf("knife-edge conicity %.9g, closed-form harmonic %.9g, lambda a / (a - lambda r0) = %.9g\n",
              csv.at(1, "conicity"), harmonic_3mm, formula);
}

// ---------------------------------------------------------------------------------------------
// creep

// Kalker's coefficients at nu = 0.28 as docs/contact-mechanics.md tabulates them (Kalker 1990,
// Table E.3 interpolated; the reference values of tests/unit/contact_kalker_test.cpp), given to
// 3 decimals; 1e-3 absolute is the tolerance the unit test gives them.
struct Kalker {
  double c11, c22, c23;
};
constexpr Kalker kKalkerRound{4.226, 3.705, 1.488};     // a/b = 1
constexpr Kalker kKalkerBOverA05{5.204, 4.971, 2.657};  // b/a = 0.5 (a/b = 2)
constexpr double kG = 8.2e10;                           // default --shear-modulus

struct Forces {
  double fx, fy, mz;
};

Forces creep(const std::string& args) {
  const Csv csv = parse_csv(run_ok("creep " + args));
  EXPECT_EQ(csv.header, "fx,fy,mz");
  EXPECT_EQ(csv.rows.size(), 1u);
  if (csv.rows.size() != 1) return {NAN, NAN, NAN};
  return {csv.at(0, "fx"), csv.at(0, "fy"), csv.at(0, "mz")};
}

// Verifies `creep --model linear` against Kalker's linear theory by hand (forces on the wheel,
// c = sqrt(a b)): Fx = -G c^2 C11 xi_x, Fy = -G c^2 C22 xi_y - G c^3 C23 phi, Mz = +G c^3 C23 xi_y
// (spin 0; with spin Mz needs C33, which the document does not tabulate, so only Fy is checked
// then), for a circular patch and for b/a = 0.5 (which also catches a/b and b/a confused: the a/b =
// 0.5 row has C11 = 3.67). Tolerance: the coefficients' 1e-3, relative 1e-3 / C, plus 10 printed
// digits.
TEST(CreepCommand, LinearTheoryMatchesKalker) {
  struct Case {
    double a, b;
    Kalker k;
  };
  for (const Case& c : {Case{5e-3, 5e-3, kKalkerRound}, Case{6e-3, 3e-3, kKalkerBOverA05}}) {
    const double cc = std::sqrt(c.a * c.b);
    const double xi_x = 1e-4, xi_y = -2e-4, phi = 0.3;
    char patch[160];
    std::snprintf(patch, sizeof patch, "--a %.17g --b %.17g --normal-force 80000 --model linear", c.a, c.b);
    const Forces f = creep(std::string(patch) + " --xi-x 1e-4 --xi-y -2e-4");
    const double fx = -kG * cc * cc * c.k.c11 * xi_x;
    const double fy = -kG * cc * cc * c.k.c22 * xi_y;
    const double mz = kG * cc * cc * cc * c.k.c23 * xi_y;
    EXPECT_NEAR(f.fx, fx, (1e-3 / c.k.c11 + 1e-9) * std::fabs(fx)) << c.a / c.b;
    EXPECT_NEAR(f.fy, fy, (1e-3 / c.k.c22 + 1e-9) * std::fabs(fy)) << c.a / c.b;
    EXPECT_NEAR(f.mz, mz, (1e-3 / c.k.c23 + 1e-9) * std::fabs(mz)) << c.a / c.b;
    const Forces s = creep(std::string(patch) + " --xi-y -2e-4 --spin 0.3");
    const double fy_spin = fy - kG * cc * cc * cc * c.k.c23 * phi;
    const double tol = 1e-3 * (kG * cc * cc * std::fabs(xi_y) + kG * cc * cc * cc * phi) + 1e-9 * std::fabs(fy_spin);
    EXPECT_NEAR(s.fy, fy_spin, tol) << c.a / c.b;
    EXPECT_NEAR(s.fx, 0.0, 1e-9);
  }
}

// Verifies `creep --model fastsim` in the linear regime against the linear theory: docs/validation.md documents
// the FASTSIM (centre-value) discretisation error there as +0.125 % at 20x20 and +0.50 % at 10x10,
// i.e. +1/(2 n^2) with n strips (the midpoint rule over the strips of the parabolic strip areas;
// along a strip the centre value integrates the linear traction exactly). The creepage 1e-7 keeps
// the slip zone at the trailing edge far below one element (t = xi / (2 L1 mu k a) ~ 1e-5 for the
// central strip, 3e-5 for the outermost one, against 1/(2 m) = 0.025), so the linear regime holds
// to ~1e-5. Tolerance against the printed linear result: the documented error, 1e-5 below it for
// slip, 1e-7 above; against the hand evaluation add the coefficients' 1e-3 / C.
// Mz from xi_y: FASTSIM's simplified theory gives (3 pi / 32) G C22 a^2 b xi_y (docs/contact-
// mechanics.md), not the linear theory's; its first moment along x is a midpoint rule on a quadratic
// (-1/m^2 = -0.25 %) and across strips +0.026 % (midpoint rule on (1 - u^2)^1.5, 20 strips), so
// -0.224 %; asserted within 0.3 % (plus C22's rounding).
TEST(CreepCommand, FastsimLinearRegimeWithinDiscretisationError) {
  const double a = 5e-3, b = 5e-3, c = 5e-3, xi = 1e-7;
  const std::string patch = "--a 5e-3 --b 5e-3 --normal-force 80000 --mu 0.3 --xi-x 1e-7 --xi-y 1e-7";
  const Forces lin = creep(patch + " --model linear");
  for (const auto& [grid, error] : {std::pair<std::string, double>{"", 0.00125}, {" --grid 10x10", 0.005}}) {
    const Forces fs = creep(patch + " --model fastsim" + grid);
    EXPECT_NEAR(fs.fx / lin.fx - 1, error, 1e-5) << grid;
    EXPECT_LE(fs.fx / lin.fx - 1, error + 1e-7) << grid;
    EXPECT_NEAR(fs.fy / lin.fy - 1, error, 1e-5) << grid;
    EXPECT_LE(fs.fy / lin.fy - 1, error + 1e-7) << grid;
    const double fx = -kG * c * c * kKalkerRound.c11 * xi, fy = -kG * c * c * kKalkerRound.c22 * xi;
    EXPECT_NEAR(fs.fx / fx - 1, error, 1e-5 + 1e-3 / kKalkerRound.c11) << grid;
    EXPECT_NEAR(fs.fy / fy - 1, error, 1e-5 + 1e-3 / kKalkerRound.c22) << grid;
    std::printf("fastsim%s: fx/linear - 1 = %.6e, fy/linear - 1 = %.6e\n", grid.c_str(), fs.fx / lin.fx - 1,
                fs.fy / lin.fy - 1);
  }
  const Forces fs = creep(patch);  // fastsim and 20x20 are the defaults
  const double mz = 3 * M_PI / 32 * kG * kKalkerRound.c22 * a * a * b * xi;
  EXPECT_NEAR(fs.mz, mz, (3e-3 + 1e-3 / kKalkerRound.c22) * mz);
  std::printf("fastsim mz / (3 pi / 32) G C22 a^2 b xi_y - 1 = %.4e\n", fs.mz / mz - 1);
}

// ---------------------------------------------------------------------------------------------
// Bad input

// Runs a command that must fail; expects a non-zero exit status and exactly one line of output
// (stdout and stderr together) that contains every one of `names`.
void expect_one_line_error(const std::string& args, const std::vector<std::string>& names) {
  int status = 0;
  const std::string out = run_command(kCli + " " + args + " 2>&1", &status);
  EXPECT_NE(status, 0) << args;
  EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), 1) << args << "\n" << out;
  for (const auto& name : names) EXPECT_NE(out.find(name), std::string::npos) << args << ": " << out;
}

// Verifies that an unknown option, a NaN and a stray argument (a word, or a mistyped single-dash
// option) make every one of the five commands fail with one line naming the option and the value.
TEST(CommandErrors, BadInputFailsWithOneLine) {
  const std::string geometry = "geometry --y-from 0 --y-to 0.001 --y-step 0.001";
  const std::string points = "points --y 0.001";
  const std::string area = "area --y 0.001";
  const std::string conicity = "conicity --amplitude 0.003";
  const std::string creep = "creep --a 5e-3 --b 5e-3 --normal-force 80000";
  for (const std::string& cmd : {geometry, points, area, conicity, creep})
    expect_one_line_error(cmd + " --bogus 1", {"unknown option --bogus"});
  expect_one_line_error("geometry --y-from nan --y-to 0.001 --y-step 0.001", {"--y-from", "'nan'"});
  expect_one_line_error("points --y nan", {"--y", "'nan'"});
  expect_one_line_error("area --y 0.001 --eps0 nan", {"--eps0", "'nan'"});
  expect_one_line_error("conicity --amplitude 0.003,nan", {"--amplitude", "'nan'"});
  expect_one_line_error(creep + " --xi-x nan", {"--xi-x", "'nan'"});
  for (const std::string& cmd : {geometry, points, area, conicity, creep}) {
    expect_one_line_error(cmd + " stray", {"unexpected argument 'stray'"});
    expect_one_line_error(cmd + " -yaw 0.05", {"unexpected argument '-yaw'", "options start with --"});
  }
  // Out of range and malformed values name the value as well.
  expect_one_line_error("conicity --amplitude 0.03", {"--amplitude", "0.03"});
  expect_one_line_error(creep + " --grid 20y20", {"--grid", "'20y20'"});
  expect_one_line_error(points + " --wheel-side middle", {"--wheel-side", "'middle'"});
}

// `wrc geometry` refuses a yaw beyond the validated 0.06 rad as `points` does; a single-dash word
// is an error even for the commands that take positional words (swap, launch).
TEST(CommandErrors, YawRangeAndSingleDashWords) {
  const std::string geometry = "geometry --y-from 0 --y-to 0.001 --y-step 0.001";
  expect_one_line_error(geometry + " --yaw 0.1", {"--yaw", "0.1", "0.06"});
  expect_one_line_error(geometry + " --yaw -0.07", {"--yaw", "-0.07"});
  EXPECT_NE(run_ok(geometry + " --yaw 0.06 --format csv").find("y,z,roll"), std::string::npos);
  expect_one_line_error("points --y 0.001 --yaw 0.1", {"--yaw", "0.1"});
  expect_one_line_error("swap onepoint -yaw", {"unexpected argument '-yaw'", "options start with --"});
  expect_one_line_error("launch -yaw 0.05", {"unexpected argument '-yaw'", "options start with --"});
}

// ---------------------------------------------------------------------------------------------
// Mistakes found before any work starts (issue 21 item 8): `wrc run`, `wrc fit` and `wrc plot`
// check what they will write, read and send before they start a service, a run, a fit or gnuplot.

// Fails within this time or it started something: RunSession alone listens to the bus for
// kServiceDiscoveryTime = 1.5 s (clients/cli/service_starter.hpp) before it starts any service.
constexpr double kBeforeAnyService = 1.5;  // [s]

class EarlyErrors : public BusTest {
 protected:
  // Runs `wrc-cli args`, which must fail before any work: a non-zero status, exactly one line
  // (stdout and stderr together) holding every one of names, and no heartbeat of any service on
  // the test's private bus. "Before any work" is checked without a clock: the command runs with
  // an LCM URL whose provider does not exist, so a command that opened the bus (to discover or
  // start a service) would fail with the bus's error instead of the one expected. The time it
  // took is printed (it stays far below kBeforeAnyService).
  void expect_one_line_error_at_once(const std::string& args, const std::vector<std::string>& names) {
    SCOPED_TRACE(args.substr(0, 300));
    int status = 0;
    const auto start = std::chrono::steady_clock::now();
    const std::string out = run_command("LCM_DEFAULT_URL=nosuchprovider://nowhere " + kCli + " " + args + " 2>&1", &status);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_NE(status, 0);
    EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), 1) << out.substr(0, 2000);
    for (const auto& name : names) EXPECT_NE(out.find(name), std::string::npos) << out.substr(0, 2000);
    std::cout << "[ measured ] failed after " << seconds << " s (service discovery would take " << kBeforeAnyService
              << " s)\n";
    handle_until([] { return false; }, 0.2);  // what arrived while the command ran
    EXPECT_EQ(monitor_->size(), 0u) << "a service sent heartbeats";
  }

  std::string write_file(const std::string& name, const std::string& text) {
    const std::string path = temp_path(name);
    std::ofstream(path) << text;
    return path;
  }

  // A short run on the test's own bus (t_end keeps the run short if one did start).
  const std::string run_ = "run --model onepoint --t-end 0.01 --channel-prefix early";
};

// `wrc run --summary /nonexistent/x.json` started the services and integrated the whole run before
// it failed. Now every output path is checked first: one line naming the option, the path and why;
// a file that did not exist is not left behind, an existing one is not changed.
TEST_F(EarlyErrors, RunChecksItsOutputPathsBeforeAnyServiceStarts) {
  const std::string no_folder = "the folder /nonexistent-wrc does not exist";
  expect_one_line_error_at_once(run_ + " --summary /nonexistent-wrc/x.json",
                                {"wrc run: --summary /nonexistent-wrc/x.json: " + no_folder});
  const std::string summary = temp_path("s.json");
  expect_one_line_error_at_once(run_ + " --summary " + summary + " --history /nonexistent-wrc/h.csv",
                                {"--history /nonexistent-wrc/h.csv: " + no_folder});
  EXPECT_FALSE(std::filesystem::exists(summary)) << "the check left the summary file behind";
  write_file("s.json", "kept");
  expect_one_line_error_at_once(run_ + " --summary " + summary + " --history " + temp_dir_,
                                {"--history " + temp_dir_ + ": is a directory"});
  std::ifstream kept(summary);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(kept), {}), "kept");
  const std::string not_a_folder = write_file("plain", "");
  expect_one_line_error_at_once(run_ + " --summary " + not_a_folder + "/x.json",
                                {"--summary " + not_a_folder + "/x.json: " + not_a_folder + " is not a folder"});
}

// `wrc fit --report` and `wrc plot --out` check their output before the fit and before gnuplot.
TEST_F(EarlyErrors, FitAndPlotCheckTheirOutputFirst) {
  const std::string no_folder = "the folder /nonexistent-wrc does not exist";
  expect_one_line_error_at_once("fit --no-validation --report /nonexistent-wrc/r.json",
                                {"wrc fit: --report /nonexistent-wrc/r.json: " + no_folder});
  expect_one_line_error_at_once("plot profiles --out /nonexistent-wrc/p.png",
                                {"wrc plot: --out /nonexistent-wrc/p.png: " + no_folder});
}

// `wrc run --wheel tests/data/bad_nan.txt` printed the services' logs (5-6 lines); like `wrc query`
// it now builds the geometry first and fails with the profile reader's one line.
TEST_F(EarlyErrors, RunRefusesABadProfileInOneLine) {
  const std::string bad = std::string(WRC_SOURCE_DIR) + "/tests/data/bad_nan.txt";
  expect_one_line_error_at_once(run_ + " --summary " + temp_path("s.json") + " --wheel " + bad,
                                {"wrc run: " + bad + ":4: NaN or infinite value"});
  EXPECT_FALSE(std::filesystem::exists(temp_path("s.json")));
}

// Parameter file errors name the file and the key: a number beyond a double (1e999: the JSON
// library's message named neither), a count too large (max_steps 1e30: was "not a whole number"),
// a key given twice (was taken silently); the too large count on the command line too.
TEST_F(EarlyErrors, RunParameterFileErrorsNameTheFileAndTheKey) {
  const std::string summary = " --summary " + temp_path("s.json");
  const std::string huge = write_file("huge.json", "{\"speed\": 1e999}");
  expect_one_line_error_at_once(run_ + summary + " --params " + huge,
                                {"wrc run: " + huge + ": speed = 1e999 is not a finite number (valid: (0, "});
  const std::string steps = write_file("steps.json", "{\"max_steps\": 1e30}");
  expect_one_line_error_at_once(run_ + summary + " --params " + steps,
                                {"wrc run: " + steps + ": max_steps = 1e+30 is outside [1, 1e+12] [-]"});
  const std::string twice = write_file("twice.json", "{\"speed\": 10,\n \"mass\": 1500,\n \"speed\": 10}");
  expect_one_line_error_at_once(run_ + summary + " --params " + twice,
                                {"wrc run: " + twice + ": speed: duplicate key"});
  expect_one_line_error_at_once(run_ + summary + " --max-steps 1e30",
                                {"wrc run: --max-steps: 1e30 is outside [1, 1e+12] [-]"});
}

// 10 000 scheduled swaps were refused by the dynamics service as "does not match the swap lists";
// `wrc run --swap-at` now refuses more than the limit itself, naming it; the limit itself passes
// (the error is then the next one, the summary path).
TEST_F(EarlyErrors, RunRefusesMoreSwapsThanTheLimitNamingIt) {
  auto swaps = [](int count) {
    std::string text;
    for (int k = 1; k <= count; ++k) text += (k > 1 ? "," : "") + std::to_string(k) + ":interp";
    return text;
  };
  // 20000 s of run at 0.1 s per output sample: within the 200 000 samples a run may write.
  const std::string run = "run --model onepoint --t-end 20000 --output-period 0.1 --channel-prefix early";
  expect_one_line_error_at_once(run + " --summary " + temp_path("s.json") + " --swap-at " + swaps(10000),
                                {"wrc run: --swap-at: 10000 swaps, more than the limit of 1000"});
  expect_one_line_error_at_once(run + " --summary " + temp_path("s.json") + " --swap-at " + swaps(1001),
                                {"wrc run: --swap-at: 1001 swaps, more than the limit of 1000"});
  expect_one_line_error_at_once(run + " --summary /nonexistent-wrc/x.json --swap-at " + swaps(1000),
                                {"--summary /nonexistent-wrc/x.json"});
}

// `wrc query` had ranges of its own, wider than the library's rule the contact service applies
// (core/model_interface/query_validation.hpp): `--poisson 0.5` and `--grid 1x1` passed the command
// and failed at the service. It now checks its query by that rule before it starts anything, in
// one line naming the option and the library's range; the library's edges pass the check (the
// error is then the next one, the wheel profile file's, which comes before the bus).
TEST_F(EarlyErrors, QueryRefusesWhatTheServiceRefusesNamingTheRange) {
  const std::string query = "query --model onepoint --y 0.001 --channel-prefix early";
  expect_one_line_error_at_once(query + " --poisson 0.5", {"wrc query: --poisson: 0.5 is outside (0, 0.5) [-]"});
  expect_one_line_error_at_once(query + " --grid 1x1",
                                {"wrc query: --grid: '1x1' is not MxN with whole numbers in 2..400"});
  expect_one_line_error_at_once(query + " --shear-modulus 1e14", {"wrc query: --shear-modulus: 1e14 is outside (0, "});
  expect_one_line_error_at_once(query + " --speed 0", {"wrc query: --speed: 0 is not positive"});
  expect_one_line_error_at_once(query + " --speed 1000.5", {"wrc query: --speed: 1000.5 is outside (0, 1000] m/s"});
  const std::string bad = std::string(WRC_SOURCE_DIR) + "/tests/data/bad_nan.txt";
  expect_one_line_error_at_once(query + " --poisson 0.4999 --grid 2x400 --shear-modulus 1e13 --speed 1000 --wheel " + bad,
                                {"wrc query: " + bad + ":4: NaN or infinite value"});
}

}  // namespace
}  // namespace wrc::bus::test
