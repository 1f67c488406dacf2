// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Load figures of a service as reported in its heartbeat, and the window they are measured on.

#include <cstdint>
#include <vector>

namespace wrc::bus {

/// What a service reports about its load (heartbeat_t fields of the same names).
struct ServiceLoad {
  std::int64_t requests_handled = 0;   ///< [-] requests answered since start
  std::int64_t requests_rejected = 0;  ///< [-] requests rejected since start
  int max_queue = 0;                   ///< [-] most requests waiting behind one, last period
  double busy_fraction = 0.0;          ///< [-] share of the last period spent in handlers
  double latency_mean = 0.0;           ///< [s] mean handling time, recent window
  double latency_p95 = 0.0;            ///< [s] 95th percentile handling time, recent window
  double latency_max = 0.0;            ///< [s] largest handling time, recent window
};

/// Handling times of the most recent requests (a ring of fixed capacity).
class LatencyWindow {
 public:
  /// capacity: number of recent samples kept (> 0).
  explicit LatencyWindow(std::size_t capacity = 1000);
  /// Adds one handling time [s].
  void add(double seconds);
  /// Fills latency_mean, latency_p95 and latency_max of load (zeros when empty).
  void summarise(ServiceLoad& load) const;
  /// Number of samples held.
  std::size_t size() const { return samples_.size(); }
  /// The samples held [s], in no particular order.
  const std::vector<double>& samples() const { return samples_; }

 private:
  std::size_t capacity_;
  std::size_t next_ = 0;
  std::vector<double> samples_;
};

/// Anything that contributes to a service's load (request servers).
class LoadSource {
 public:
  virtual ~LoadSource() = default;
  /// Adds this source's figures to load (counts add up, latencies are merged by maximum).
  virtual void add_load(ServiceLoad& load) const = 0;
  /// [s] time spent in handlers since the previous call (resets the accumulator).
  virtual double take_busy_time() = 0;
  /// false: stop answering requests (this process is a duplicate of an older instance,
  /// bus/instance_identity.hpp); true: answer again. Sources that answer nothing ignore it.
  virtual void set_serving(bool /*serving*/) {}
};

}  // namespace wrc::bus
