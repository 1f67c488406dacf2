// SPDX-License-Identifier: Apache-2.0
// Benchmarks of the contact-mechanics kernels (services/core/contact): FASTSIM per patch on 10x10,
// 20x20 and 40x40 grids in the linear and saturated regimes and with flange-contact spin, the Hertz
// solve per patch (shape inversion plus loading) and the Kalker-coefficient lookup. Time per call in ns.
// Run: bench_creep [--benchmark_repetitions=5 --benchmark_report_aggregates_only=true]

#include <benchmark/benchmark.h>

#include "core/contact/fastsim.hpp"
#include "core/contact/hertz.hpp"
#include "core/contact/kalker_coefficients.hpp"
#include "core/contact/linear_creep.hpp"

namespace {

wrc::CreepPatch example_patch() {
  wrc::CreepPatch p;
  p.a = 6.68e-3;
  p.b = 5.02e-3;
  p.normal_force = 80e3;
  return p;
}

// FASTSIM per patch, coefficients looked up inside (what a contact model calls per patch).
// range(0): grid size n (n x n); range(1): regime 0 linear (xi ~ 1e-5), 1 partial slip (xi ~ 1e-3),
// 2 saturated (xi ~ 1e-2), 3 flange spin (phi = 2 1/m).
void BM_Fastsim(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const wrc::Fastsim solver(n, n);
  wrc::CreepPatch patch = example_patch();
  const wrc::Creepages regimes[] = {{1e-5, 1e-5, 0.01}, {1e-3, 5e-4, 0.1}, {1e-2, 5e-3, 0.1}, {1e-3, 1e-3, 2.0}};
  wrc::Creepages c = regimes[state.range(1)];
  for (auto _ : state) {
    c.longitudinal += 1e-15;  // defeat hoisting of the loop-invariant call
    benchmark::DoNotOptimize(solver.solve(patch, c));
  }
  state.SetLabel(state.range(1) == 0 ? "linear" : state.range(1) == 1 ? "partial slip"
                                                 : state.range(1) == 2 ? "saturated" : "flange spin");
}
BENCHMARK(BM_Fastsim)->ArgsProduct({{10, 20, 40}, {0, 1, 2, 3}});

// Hertz per patch: solve the ellipse shape from (A, B) and load it with N.
void BM_HertzSolve(benchmark::State& state) {
  const double estar = wrc::contact_modulus(8.2e10, 0.28);
  double B = 0.5 / 0.30;
  for (auto _ : state) {
    B += 1e-12;
    benchmark::DoNotOptimize(wrc::hertz_from_force(0.5 / 0.46, B, estar, 80e3));
  }
}
BENCHMARK(BM_HertzSolve);

// Hertz with a known shape (elastic models re-load a cached shape): from a penetration.
void BM_HertzFromPenetration(benchmark::State& state) {
  const double estar = wrc::contact_modulus(8.2e10, 0.28);
  const auto shape = wrc::hertz_shape(0.5 / 0.46, 0.5 / 0.30);
  double delta = 90e-6;
  for (auto _ : state) {
    delta += 1e-18;
    benchmark::DoNotOptimize(wrc::hertz_from_penetration(shape, estar, delta));
  }
}
BENCHMARK(BM_HertzFromPenetration);

// Kalker coefficient lookup (table interpolation in a/b and 1/C Lagrange in nu).
void BM_KalkerCoefficients(benchmark::State& state) {
  double g = 1.33;
  for (auto _ : state) {
    g += 1e-12;
    benchmark::DoNotOptimize(wrc::kalker_coefficients(g, 0.28));
  }
}
BENCHMARK(BM_KalkerCoefficients);

// Linear theory per patch, coefficients included.
void BM_LinearCreep(benchmark::State& state) {
  const wrc::CreepPatch patch = example_patch();
  wrc::Creepages c{1e-4, 1e-4, 0.1};
  for (auto _ : state) {
    c.longitudinal += 1e-15;
    benchmark::DoNotOptimize(wrc::linear_creep_forces(patch, c));
  }
}
BENCHMARK(BM_LinearCreep);

}  // namespace

BENCHMARK_MAIN();
