// SPDX-License-Identifier: Apache-2.0
#include "core/models/fastsim_cache.hpp"

namespace wrc {

FastsimCache::FastsimCache() {
  auto solver = std::make_unique<Fastsim>(kDefaultFastsimGrid, kDefaultFastsimGrid);
  default_ = solver.get();
  solvers_.emplace(std::make_pair(kDefaultFastsimGrid, kDefaultFastsimGrid), std::move(solver));
}

const Fastsim& FastsimCache::get(int elements_per_strip, int strips) const {
  // The default grid never changes after construction: no lock needed.
  if (elements_per_strip == kDefaultFastsimGrid && strips == kDefaultFastsimGrid) return *default_;
  std::lock_guard<std::mutex> lock(mutex_);
  auto& slot = solvers_[std::make_pair(elements_per_strip, strips)];
  if (!slot) slot = std::make_unique<Fastsim>(elements_per_strip, strips);
  return *slot;
}

}  // namespace wrc
