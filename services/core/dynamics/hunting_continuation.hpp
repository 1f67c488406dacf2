// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The hunting bifurcation diagram by simulation (docs/bifurcation.md): the centred branch (runs
/// from a small disturbance), the stable limit-cycle branch by ramp-down continuation (from a
/// large disturbance at the highest speed, each lower speed started from the previous run's final
/// state), and the nonlinear critical speed, the lowest speed at which a hunting cycle persists,
/// refined by bisection between the last persisting and the first collapsing speed.

#include <functional>
#include <memory>
#include <vector>

#include "core/dynamics/contact_evaluator.hpp"
#include "core/dynamics/hunting_run.hpp"
#include "core/dynamics/wheelset_parameters.hpp"

namespace wrc {

/// How the diagram is traced.
struct ContinuationSettings {
  HuntingSettings run;                ///< each run's length and judgement
  /// Start of the centred branch's runs: 0.05 mm, below the separatrix of S1002 on UIC60's tread
  /// cycle (0.10 to 0.17 mm, docs/bifurcation.md), so that it tests the centred state's stability.
  InitialState small_disturbance{5e-5, 0, 0, 0, 0};
  InitialState large_disturbance{5e-3, 0, 0, 0, 0};    ///< start of the ramp-down at the highest speed
  /// The bisection stops when the bracket of the nonlinear critical speed is this narrow [m/s], > 0.
  double speed_tolerance = 0.25;
  /// A cycle counts as persisting only with at least this amplitude of y [m], >= 0: 0 any cycle;
  /// above the tread cycles' amplitude, the ramp-down follows the flange cycle to its own fold.
  double persisting_amplitude = 0;
  /// @throws std::invalid_argument naming the first value out of range.
  void validate() const;
};

/// The lowest speed with a persisting hunting cycle.
struct NonlinearCriticalSpeed {
  bool found = false;      ///< false: the cycle persisted down to the lowest speed, or never existed
  double speed = 0;        ///< the lowest speed where the cycle persisted [m/s]
  double collapsed_at = 0; ///< the highest speed below it where it collapsed [m/s]
  HuntingRun cycle;        ///< the run at speed (its amplitude and frequency)
};

/// The diagram: every run, in the order made.
struct HuntingDiagram {
  std::vector<HuntingRun> centred;     ///< from small_disturbance at each speed, ascending
  std::vector<HuntingRun> ramp_down;   ///< the continuation, descending, up to the first collapse or failure
  std::vector<HuntingRun> refinement;  ///< the bisection's runs
  NonlinearCriticalSpeed critical;
};

/// Runs one hunting run at a speed from a state (a model swap-free run_hunting with a fresh
/// contact evaluator or a shared one).
using HuntingRunner = std::function<HuntingRun(double speed, const InitialState& start)>;

/// A runner of run_hunting with base, contact and nominal_radius [m].
HuntingRunner hunting_runner(RunSpec base, std::shared_ptr<ContactEvaluator> contact, double nominal_radius,
                             HuntingSettings settings);

/// Traces the diagram over speeds [m/s] (ascending, as stability_speeds gives them): the centred
/// branch at every speed, the ramp-down from the highest, the bisection. progress, when given, is
/// called after every run.
/// @throws std::invalid_argument for fewer than 2 speeds, speeds not ascending, invalid settings.
HuntingDiagram trace_hunting(const std::vector<double>& speeds, const HuntingRunner& run,
                             const ContinuationSettings& settings,
                             const std::function<void(const char* branch, const HuntingRun&)>& progress = {});

/// An estimate of the unstable cycle at one speed: the start amplitude that separates decay from
/// growth, and the run started there.
struct UnstableCycle {
  double speed = 0;            ///< [m/s]
  double decaying_start = 0;   ///< largest y0 found to decay [m]
  double growing_start = 0;    ///< smallest y0 found to grow [m]
  HuntingRun run;              ///< the run from decaying_start (its amplitude near the cycle's)
  int runs = 0;                ///< runs made [-]
};

/// Bisection on the start amplitude y0 (yaw and rates 0) at speed [m/s] between decays_from (a
/// y0 that decays) and grows_from (one that grows, > decays_from) [m], iterations times: a run
/// decays when its growth per cycle is below 1 (or it ended centred), grows otherwise (growth
/// >= 1, a failure on the way up counts as growth). run should be short (a few seconds: the
/// judgement is the last cycles' growth, not a settled state).
/// @throws std::invalid_argument for grows_from <= decays_from or iterations < 1.
UnstableCycle unstable_cycle(const HuntingRunner& run, double speed, double decays_from, double grows_from,
                             int iterations);

}  // namespace wrc
