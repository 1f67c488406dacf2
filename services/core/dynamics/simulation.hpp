// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// What a service needs of a run, whichever equations it integrates: the lone wheelset's
/// (wheelset_simulation.hpp) or a vehicle's (core/vehicle_dynamics/vehicle_simulation.hpp). Started
/// once, then advanced one integrator step at a time until it is over.

#include <memory>
#include <string>
#include <vector>

#include "core/dynamics/contact_evaluator.hpp"
#include "core/dynamics/run_counters.hpp"

namespace wrc {

/// How a run ends.
enum class RunState { kRunning, kFinished, kFailed, kStopped };

/// A model swap that took effect.
struct SwapRecord {
  double t = 0;        ///< simulated time of the step boundary where it took effect [s]
  std::string from;    ///< model before
  std::string to;      ///< model after
};

class Simulation {
 public:
  virtual ~Simulation() = default;
  /// The state at t = 0 and the first output. @throws std::runtime_error when there is none.
  virtual void start() = 0;
  /// One integrator step with what it passes; false once the run is over (state() says how).
  virtual bool advance() = 0;
  /// Ends the run at the next step boundary with RunState::kStopped.
  virtual void request_stop() = 0;
  /// A live swap to next at the next step boundary (the model of every wheelset).
  virtual void request_swap(std::shared_ptr<ContactEvaluator> next) = 0;
  /// A swap to next at the first step boundary at or after time t [s].
  virtual void schedule_swap(double t, std::shared_ptr<ContactEvaluator> next) = 0;
  virtual RunState state() const = 0;
  /// Why the run failed or stopped (empty while it runs or when it finished).
  virtual const std::string& message() const = 0;
  virtual double time() const = 0;  ///< simulated time reached [s]
  virtual std::string model() const = 0;  ///< the contact model in use
  virtual RunCounters counters() const = 0;  ///< summed over the run
  virtual const std::vector<SwapRecord>& swaps() const = 0;  ///< swaps that took effect
};

}  // namespace wrc
