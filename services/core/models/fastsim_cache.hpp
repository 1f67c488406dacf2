// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// One FASTSIM solver per grid size, built on first use and kept for the model's lifetime.

#include <map>
#include <memory>
#include <mutex>
#include <utility>

#include "core/contact/fastsim.hpp"

namespace wrc {

/// Thread-safe cache of Fastsim instances keyed by (elements per strip, strips). The solver of the
/// query default (kDefaultFastsimGrid in both directions) is built in the constructor. References stay valid for the cache's lifetime.
class FastsimCache {
 public:
  FastsimCache();
  FastsimCache(const FastsimCache&) = delete;
  FastsimCache& operator=(const FastsimCache&) = delete;

  /// The solver for m_x elements per strip and m_y strips [-] (validated by Fastsim).
  const Fastsim& get(int elements_per_strip, int strips) const;

 private:
  const Fastsim* default_;
  mutable std::mutex mutex_;
  mutable std::map<std::pair<int, int>, std::unique_ptr<Fastsim>> solvers_;
};

}  // namespace wrc
