#include "nome/thread_support.hpp"

#include <atomic>

namespace nome {
namespace {

std::atomic<bool> is_switched_off{false};

}  // namespace

bool can_start_threads() noexcept {
  return build_has_threads && !is_switched_off.load(std::memory_order_relaxed);
}

WithoutThreads::WithoutThreads() : could_before_(!is_switched_off.exchange(true)) {}

WithoutThreads::~WithoutThreads() {
  is_switched_off.store(!could_before_);
}

}  // namespace nome
