// SPDX-License-Identifier: Apache-2.0
// In-process benchmark of the contact models (services/core/models): evaluations per second of
// onepoint, interp, multipoint and spline (both wheels, FASTSIM 20x20, rigid and elastic), the time
// interp spends building its table and the spline model its fit (sampling and least squares), what
// one query of both wheels needs from the splines, and the split of one one-point evaluation into geometry (common point
// of both wheels), Hertz (shape + loading, both wheels) and FASTSIM (both patches).
// S1002 / UIC60, standard track; the configurations cycle through 25 lateral shifts in
// [-6, 6] mm at their rigid-contact roll and height (tread, two-minima and flange-root cases; no yaw).
// Run: bench_models [--benchmark_repetitions=5 --benchmark_report_aggregates_only=true]

#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

#include "core/contact/fastsim.hpp"
#include "core/contact/hertz.hpp"
#include "core/geometry/rigid_wheelset.hpp"
#include "core/model_interface/patch_builder.hpp"
#include "core/models/contact_model_factory.hpp"
#include "core/models/interpolated_model.hpp"
#include "core/profile/profile_factory.hpp"
#include "core/spline/spline_geometry_fit.hpp"

namespace {

std::shared_ptr<const wrc::WheelsetGeometry> geometry() {
  static const auto g = std::make_shared<const wrc::WheelsetGeometry>(
      wrc::make_profile("S1002", wrc::ProfileSide::kWheel), wrc::make_profile("UIC60", wrc::ProfileSide::kRail));
  return g;
}

// 25 queries at the rigid-contact pose (roll and height solved: both wheels touch); elastic ones
// lowered by 60 um so that both wheels overlap their rails.
std::vector<wrc::ContactQuery> queries(wrc::ContactFormulation formulation) {
  std::vector<wrc::ContactQuery> out;
  const wrc::RigidWheelsetSolver solver(*geometry());
  for (int i = 0; i < 25; ++i) {
    wrc::ContactQuery q;
    q.pose = solver.solve(-0.006 + 0.0005 * i, 0.0).pose;
    q.speed = 30.0;
    q.spin_rate = 30.0 / 0.46;
    q.yaw_dot = 0.01;
    q.normal_load = {80e3, 80e3};
    q.formulation = formulation;
    if (formulation == wrc::ContactFormulation::kElastic) q.pose.z -= 60e-6;
    out.push_back(q);
  }
  return out;
}

const char* const kModels[] = {"onepoint", "interp", "multipoint", "spline"};

// The default spline model of S1002/UIC60 (SplineFitOptions{}), fitted once.
const wrc::SplineFit& spline_fit() {
  static const wrc::SplineFit fit = wrc::fit_spline_geometry(*geometry(), wrc::SplineFitOptions{});
  return fit;
}

// range(0): model index (onepoint, interp, multipoint, spline); range(1): 0 rigid, 1 elastic.
void BM_Evaluate(benchmark::State& state) {
  const auto formulation = state.range(1) == 0 ? wrc::ContactFormulation::kRigid : wrc::ContactFormulation::kElastic;
  const char* name = kModels[state.range(0)];
  const wrc::ContactModelData data{std::string(name) == "spline" ? spline_fit().model : nullptr};
  const auto model = wrc::make_contact_model(name, geometry(), {}, data);
  const std::vector<wrc::ContactQuery> qs = queries(formulation);
  size_t i = 0, patches = 0;
  for (auto _ : state) {
    const wrc::ContactResult r = model->evaluate(qs[i]);
    patches += r.patches.size();
    benchmark::DoNotOptimize(r.force);
    i = (i + 1) % qs.size();
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["patches/eval"] = static_cast<double>(patches) / static_cast<double>(state.iterations());
  state.SetLabel(std::string(kModels[state.range(0)]) + (state.range(1) == 0 ? " rigid" : " elastic"));
}
BENCHMARK(BM_Evaluate)->ArgsProduct({{0, 1, 2, 3}, {0, 1}})->Unit(benchmark::kMicrosecond);

// Both wheels' spline evaluation at the 25 rigid poses: per wheel one basis evaluation and the
// contraction (SplineContactGeometry::evaluate). range(0): derivatives (0 values only, 2 with z's
// gradient and Hessian); range(1): fields evaluated; range(2): fields with derivatives (1 z, 2 z
// and the flange clearance). What one contact query of both wheels needs (SplineModel):
// Args(2, kSplineQueryFieldCount = 22, 1). Every fitted quantity: Args(2, 26, 2).
// The query kernel of TensorSplineSet (services/core/spline/tensor_spline.cpp) at Args(2, 26, 2),
// measured with callgrind per wheel: the values about 700 instructions, against about 780 for a
// fully separable contraction and more again when merged with the derivatives into one pass; the
// derivatives about 330 one function at a time from the transposed coefficients, against about 900
// contracted for functions 0..3 together from the rows.
void BM_SplineBothWheels(benchmark::State& state) {
  const wrc::SplineContactGeometry& model = *spline_fit().model;
  const std::vector<wrc::ContactQuery> qs = queries(wrc::ContactFormulation::kRigid);
  const auto derivatives = static_cast<wrc::SplineDerivatives>(state.range(0));
  const int fields = static_cast<int>(state.range(1));
  const int derivative_fields = static_cast<int>(state.range(2));
  wrc::SplineEvaluation left, right;
  size_t i = 0;
  for (auto _ : state) {
    model.evaluate(wrc::WheelSide::kLeft, qs[i].pose, derivatives, left, fields, derivative_fields);
    model.evaluate(wrc::WheelSide::kRight, qs[i].pose, derivatives, right, fields, derivative_fields);
    benchmark::DoNotOptimize(left.value.data());
    benchmark::DoNotOptimize(right.z_hessian.data());
    i = (i + 1) % qs.size();
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["fields"] = fields;
  state.counters["terms/wheel"] = 64;
  const bool query = fields == wrc::kSplineQueryFieldCount && derivative_fields == 1 &&
                     derivatives == wrc::SplineDerivatives::kHessian;
  state.SetLabel(query ? "what a query needs" : fields == wrc::kSplineFieldCount ? "every field" : "");
}
BENCHMARK(BM_SplineBothWheels)
    ->Args({0, wrc::kSplineFieldCount, 1})
    ->Args({2, wrc::kSplineQueryFieldCount, 1})
    ->Args({2, wrc::kSplineFieldCount, 2})
    ->Unit(benchmark::kNanosecond);

// The default spline model's precomputation: exact-geometry sampling of both wheels (two threads
// on this machine) and the weighted least-squares fits.
void BM_SplinePrecompute(benchmark::State& state) {
  double sampling = 0, fitting = 0;
  for (auto _ : state) {
    const wrc::SplineFit fit = wrc::fit_spline_geometry(*geometry(), wrc::SplineFitOptions{});
    sampling += fit.sampling_seconds;
    fitting += fit.fitting_seconds;
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["sampling_s"] = sampling / n;
  state.counters["fitting_s"] = fitting / n;
  state.counters["exact_scans"] = spline_fit().wheels[0].exact_evaluations + spline_fit().wheels[1].exact_evaluations;
}
BENCHMARK(BM_SplinePrecompute)->Unit(benchmark::kMillisecond)->Iterations(3);

// Interp's table: 121 x 3 x 3 nodes, both wheels (the default grid), built in the constructor
// (37 ms: docs/performance.md).
void BM_InterpPrecompute(benchmark::State& state) {
  for (auto _ : state) {
    wrc::InterpolatedModel model(geometry());
    benchmark::DoNotOptimize(model.precomputation_seconds());
  }
}
BENCHMARK(BM_InterpPrecompute)->Unit(benchmark::kMillisecond)->Iterations(5);

// Split of one one-point evaluation: the common point of both wheels (two potential-point scans).
void BM_SplitGeometry(benchmark::State& state) {
  const std::vector<wrc::ContactQuery> qs = queries(wrc::ContactFormulation::kRigid);
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(geometry()->common_point(wrc::WheelSide::kLeft, qs[i].pose));
    benchmark::DoNotOptimize(geometry()->common_point(wrc::WheelSide::kRight, qs[i].pose));
    i = (i + 1) % qs.size();
  }
}
BENCHMARK(BM_SplitGeometry)->Unit(benchmark::kMicrosecond);

// Hertz for both wheels: shape from the curvatures (elliptic-integral inversion) and loading.
void BM_SplitHertz(benchmark::State& state) {
  const wrc::ContactPoint p = *geometry()->common_point(wrc::WheelSide::kLeft, wrc::WheelsetPose{0.001, 0.46, 0, 0, 0});
  const double e_star = wrc::contact_modulus(8.2e10, 0.28);
  double load = 80e3;
  for (auto _ : state) {
    for (int w = 0; w < 2; ++w) {
      load += 1e-9;
      const wrc::PatchShape shape = wrc::contact_shape(p, 0.01);
      benchmark::DoNotOptimize(wrc::hertz_from_force(shape.shape, e_star, load));
    }
  }
}
BENCHMARK(BM_SplitHertz)->Unit(benchmark::kMicrosecond);

// FASTSIM 20x20 for both patches of a free-rolling tread contact.
void BM_SplitFastsim(benchmark::State& state) {
  const wrc::Fastsim solver(20, 20);
  wrc::CreepPatch patch{6.7e-3, 5.0e-3, 80e3, 8.2e10, 0.28, 0.3};
  wrc::Creepages c{1e-4, 2e-4, 0.05};
  for (auto _ : state) {
    for (int w = 0; w < 2; ++w) {
      c.longitudinal += 1e-15;
      benchmark::DoNotOptimize(solver.solve(patch, c));
    }
  }
}
BENCHMARK(BM_SplitFastsim)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
