// SPDX-License-Identifier: Apache-2.0
#include "bus/transport/allocation_budget.hpp"

#include <cstdlib>
#include <new>

namespace wrc::bus {

namespace {
thread_local AllocationBudget* t_budget = nullptr;  // innermost open budget of this thread
}

AllocationBudget::AllocationBudget(std::size_t bytes) : remaining_(bytes), outer_(t_budget) { t_budget = this; }

AllocationBudget::~AllocationBudget() { t_budget = outer_; }

void* budgeted_allocate(std::size_t size) {
  if (AllocationBudget* budget = t_budget; budget != nullptr) {
    if (size > budget->remaining_) {
      budget->exceeded_ = true;
      throw std::bad_alloc();
    }
    budget->remaining_ -= size;
  }
  if (size == 0) size = 1;
  for (;;) {
    if (void* p = std::malloc(size)) return p;
    std::new_handler handler = std::get_new_handler();
    if (handler == nullptr) throw std::bad_alloc();
    handler();
  }
}

}  // namespace wrc::bus

// The replaceable global allocation functions ([new.delete]): the plain and array forms go
// through the budget; the nothrow forms and the deallocation functions match them.
void* operator new(std::size_t size) { return wrc::bus::budgeted_allocate(size); }
void* operator new[](std::size_t size) { return wrc::bus::budgeted_allocate(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return wrc::bus::budgeted_allocate(size);
  } catch (...) {
    return nullptr;
  }
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return wrc::bus::budgeted_allocate(size);
  } catch (...) {
    return nullptr;
  }
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
