// SPDX-License-Identifier: Apache-2.0
/// @file
/// Benchmarks of the tensor B-spline kernels (services/core/spline): the per-wheel spline query (the
/// 3-D cubic basis over y, roll and yaw evaluated once, 20 functions' values contracted, one
/// function's derivatives) with Hessian or gradient, the bare basis evaluation, and the weighted
/// least-squares fit of 20 functions with 828 coefficients to 16000 samples.
/// Run: bench_spline [--benchmark_min_time=0.2]

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "core/spline/tensor_spline.hpp"

namespace {

constexpr int kFunctions = 20;

// Cubic in y [m], roll [rad] and yaw [rad] with `ny` x `nr` x `nw` uniform intervals.
wrc::TensorBasis wheel_basis(int ny, int nr, int nw) {
  return wrc::TensorBasis({wrc::BSplineBasis::uniform(3, -0.012, 0.012, ny),
                           wrc::BSplineBasis::uniform(3, -0.02, 0.02, nr),
                           wrc::BSplineBasis::uniform(3, -0.03, 0.03, nw)});
}

// kFunctions functions with random coefficients on the 10 x 2 x 2-interval basis (325 coefficients).
wrc::TensorSplineSet query_set() {
  const wrc::TensorBasis basis = wheel_basis(10, 2, 2);
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Eigen::MatrixXd c(basis.size(), kFunctions);
  for (Eigen::Index i = 0; i < c.size(); ++i) c.data()[i] = unit(rng);
  return wrc::TensorSplineSet(basis, c);
}

// The per-wheel query: evaluate the basis with `derivatives`, every function's value, and the value,
// gradient and (kHessian) Hessian of function 0. The point walks along y through the intervals.
// TensorSplineSet::derivatives' dot products by Eigen's packet reduction measured 2.5 times as fast
// here as a plain loop (one latency-bound scalar chain per output) and twice as fast as all outputs
// accumulated together.
void spline_query(benchmark::State& state, wrc::SplineDerivatives derivatives) {
  const wrc::TensorSplineSet set = query_set();
  wrc::TensorBasisPoint point;
  double x[3] = {-0.0119, 0.003, -0.007};
  double values[kFunctions], value, gradient[3], hessian[6];
  const bool hessian_wanted = derivatives == wrc::SplineDerivatives::kHessian;
  for (auto _ : state) {
    x[0] += 1.37e-5;
    if (x[0] > 0.0119) x[0] -= 0.0238;
    set.basis().evaluate(x, derivatives, point);
    set.values(point, values);
    set.derivatives(point, 0, value, gradient, hessian_wanted ? hessian : nullptr);
    benchmark::DoNotOptimize(values);
    benchmark::DoNotOptimize(value);
    benchmark::DoNotOptimize(gradient);
    benchmark::DoNotOptimize(hessian);
  }
}

void BM_SplineQueryHessian(benchmark::State& state) { spline_query(state, wrc::SplineDerivatives::kHessian); }
BENCHMARK(BM_SplineQueryHessian);

void BM_SplineQueryGradient(benchmark::State& state) { spline_query(state, wrc::SplineDerivatives::kGradient); }
BENCHMARK(BM_SplineQueryGradient);

// The basis evaluation alone (64 terms), range(0) = derivative order 0, 1, 2.
void BM_SplineBasisEvaluate(benchmark::State& state) {
  const wrc::TensorBasis basis = wheel_basis(10, 2, 2);
  const auto derivatives = static_cast<wrc::SplineDerivatives>(state.range(0));
  wrc::TensorBasisPoint point;
  double x[3] = {-0.0119, 0.003, -0.007};
  for (auto _ : state) {
    x[0] += 1.37e-5;
    if (x[0] > 0.0119) x[0] -= 0.0238;
    basis.evaluate(x, derivatives, point);
    benchmark::DoNotOptimize(point.value.data());
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_SplineBasisEvaluate)->Arg(0)->Arg(1)->Arg(2);

// The fit: 20 x 3 x 3 cubic intervals (23 x 6 x 6 = 828 coefficients), 16000 samples on a jittered
// 40 x 20 x 20 grid with weights in [0.01, 1], kFunctions smooth right-hand sides. Time per fit [ms].
void BM_SplineFit(benchmark::State& state) {
  const wrc::TensorBasis basis = wheel_basis(20, 3, 3);
  const int grid[3] = {40, 20, 20};
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  wrc::WeightedSamples samples;
  samples.dimension = 3;
  samples.values.resize(grid[0] * grid[1] * grid[2], kFunctions);
  int n = 0;
  for (int i = 0; i < grid[0]; ++i)
    for (int j = 0; j < grid[1]; ++j)
      for (int k = 0; k < grid[2]; ++k, ++n) {
        const int cell[3] = {i, j, k};
        double x[3];
        for (int v = 0; v < 3; ++v) {
          const auto& b = basis.basis(v);
          x[v] = b.lower() + (b.upper() - b.lower()) * (cell[v] + unit(rng)) / grid[v];
        }
        samples.points.insert(samples.points.end(), x, x + 3);
        samples.weights.push_back(0.01 + 0.99 * unit(rng));
        for (int f = 0; f < kFunctions; ++f)
          samples.values(n, f) = std::sin((f + 1) * 50 * x[0] + 10 * x[1]) * std::exp(5 * x[2]);
      }
  wrc::FitStatistics stats;
  for (auto _ : state) {
    benchmark::DoNotOptimize(wrc::fit_tensor_spline(basis, samples, &stats));
  }
  state.counters["coefficients"] = stats.coefficients;
  state.counters["samples"] = stats.samples;
  state.counters["nonzeros"] = static_cast<double>(stats.nonzeros);
}
BENCHMARK(BM_SplineFit)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
