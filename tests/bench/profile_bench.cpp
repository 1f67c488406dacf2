// SPDX-License-Identifier: Apache-2.0
// Cost of Profile::evaluate() (one virtual call) for the analytic and file profiles.
// Run: build-dir/tests/bench_profile. The lateral coordinates sweep the whole domain in a
// pseudo-random order so that branch prediction and the spline's binary search see varied input.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "core/profile/profile_factory.hpp"

namespace {

std::vector<double> sweep(const wrc::Profile& p) {
  std::vector<double> s(4096);
  unsigned state = 12345u;
  for (double& v : s) {
    state = state * 1664525u + 1013904223u;
    v = p.lower() + (p.upper() - p.lower()) * (state >> 8) / double(1u << 24);
  }
  return s;
}

void evaluate_loop(benchmark::State& state, const std::string& spec, wrc::ProfileSide side) {
  const wrc::ProfilePtr profile = wrc::make_profile(spec, side);
  const std::vector<double> s = sweep(*profile);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(profile->evaluate(s[i]));
    i = (i + 1) & (s.size() - 1);
  }
  state.SetLabel(profile->name());
}

void BM_S1002Analytic(benchmark::State& state) {
  evaluate_loop(state, "S1002", wrc::ProfileSide::kWheel);
}
void BM_Uic60Analytic(benchmark::State& state) {
  evaluate_loop(state, "UIC60", wrc::ProfileSide::kRail);
}
void BM_S1002FileSpline(benchmark::State& state) {
  evaluate_loop(state, std::string(WRC_PROFILES_DIR) + "/MBench_S1002_v3.prw",
                wrc::ProfileSide::kWheel);
}
void BM_Uic60FileSpline(benchmark::State& state) {
  evaluate_loop(state, std::string(WRC_PROFILES_DIR) + "/MBench_UIC60_v3.prr",
                wrc::ProfileSide::kRail);
}

BENCHMARK(BM_S1002Analytic);
BENCHMARK(BM_Uic60Analytic);
BENCHMARK(BM_S1002FileSpline);
BENCHMARK(BM_Uic60FileSpline);

}  // namespace

BENCHMARK_MAIN();
