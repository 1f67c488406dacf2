// SPDX-License-Identifier: Apache-2.0
// Benchmarks of the exact contact geometry: one potential-point evaluation of one
// wheel, one rigid-wheelset solve (cold and warm start), and the table y = -10..10 mm in 0.01 mm
// steps at 11 yaw angles. Counters: scans and roll iterations per solve.

#include <benchmark/benchmark.h>

#include <cmath>

#include "core/geometry/rigid_wheelset.hpp"
#include "core/profile/profile_factory.hpp"

namespace {
using namespace wrc;

const WheelsetGeometry& geometry() {
  static const WheelsetGeometry g(make_profile("S1002", ProfileSide::kWheel), make_profile("UIC60", ProfileSide::kRail));
  return g;
}

// All potential common points of one wheel (the full scan plus root refinement).
void BM_PotentialPoints(benchmark::State& state) {
  const double y = static_cast<double>(state.range(0)) * 1e-3;
  WheelsetPose pose;
  pose.y = y;
  pose.z = 0.46;
  size_t n = 0;
  for (auto _ : state) {
    auto p = geometry().potential_points(WheelSide::kLeft, pose);
    n = p.size();
    benchmark::DoNotOptimize(p);
  }
  state.counters["points"] = static_cast<double>(n);
}
BENCHMARK(BM_PotentialPoints)->Arg(0)->Arg(5)->Arg(8)->Unit(benchmark::kMicrosecond);

// Rigid wheelset, cold start, cycling through y in [-10, 10] mm. Arg 1: all potential points
// reported (full scan of both wheels at the solution); arg 0: common points certified only.
RigidSolverOptions options_for(const benchmark::State& state) {
  RigidSolverOptions o;
  o.all_potential_points = state.range(0) != 0;
  return o;
}

void BM_RigidSolveCold(benchmark::State& state) {
  const RigidWheelsetSolver solver(geometry(), options_for(state));
  int k = 0;
  double scans = 0, iterations = 0, solves = 0;
  for (auto _ : state) {
    const double y = -0.010 + 0.0001 * (k++ % 201);
    RigidContact c = solver.solve(y, 0.0);
    scans += c.scans;
    iterations += c.roll_iterations;
    ++solves;
    benchmark::DoNotOptimize(c);
  }
  state.counters["scans/solve"] = scans / solves;
  state.counters["roll_iter/solve"] = iterations / solves;
}
BENCHMARK(BM_RigidSolveCold)->Arg(1)->Arg(0)->Unit(benchmark::kMicrosecond);

// Rigid wheelset, warm start from the neighbour 0.01 mm away.
void BM_RigidSolveWarm(benchmark::State& state) {
  const RigidWheelsetSolver solver(geometry(), options_for(state));
  RigidContact previous = solver.solve(-0.010, 0.0);
  int k = 1;
  double scans = 0, iterations = 0, solves = 0;
  for (auto _ : state) {
    const double y = -0.010 + 1e-5 * (k++ % 2001);
    RigidContact c = solver.solve(y, 0.0, previous);
    scans += c.scans;
    iterations += c.roll_iterations;
    ++solves;
    previous = std::move(c);
  }
  state.counters["scans/solve"] = scans / solves;
  state.counters["roll_iter/solve"] = iterations / solves;
}
BENCHMARK(BM_RigidSolveWarm)->Arg(1)->Arg(0)->Unit(benchmark::kMicrosecond);

// The same with a yaw angle of 5 mrad (the curve C leaves the axle's vertical plane).
void BM_RigidSolveWarmYawed(benchmark::State& state) {
  const RigidWheelsetSolver solver(geometry(), options_for(state));
  RigidContact previous = solver.solve(-0.010, 0.005);
  int k = 1;
  for (auto _ : state) {
    const double y = -0.010 + 1e-5 * (k++ % 2001);
    previous = solver.solve(y, 0.005, previous);
  }
}
BENCHMARK(BM_RigidSolveWarmYawed)->Arg(1)->Arg(0)->Unit(benchmark::kMicrosecond);

// The geometry table of docs/performance.md: y from -10 to 10 mm in 0.01 mm steps (2001 values) at 11 yaw angles
// from -10 to 10 mrad, warm-started along y.
void BM_Table2001x11(benchmark::State& state) {
  const RigidWheelsetSolver solver(geometry(), options_for(state));
  for (auto _ : state) {
    for (int j = 0; j <= 10; ++j) {
      const double yaw = -0.01 + 0.002 * j;
      RigidContact previous = solver.solve(-0.010, yaw);
      for (int i = 1; i <= 2000; ++i) previous = solver.solve(-0.010 + 1e-5 * i, yaw, previous);
      benchmark::DoNotOptimize(previous);
    }
  }
  state.counters["solves"] = 2001 * 11;
}
BENCHMARK(BM_Table2001x11)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
