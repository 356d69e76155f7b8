#include "nome/worker_pool.hpp"

#include <chrono>
#include <exception>
#include <utility>

#include "nome/thread_support.hpp"

namespace nome {

void FirstError::run(const std::function<void(unsigned)>& task, unsigned i) noexcept {
  try {
    task(i);
  } catch (...) {
    const std::lock_guard lock(mutex_);
    if (!error_) error_ = std::current_exception();
  }
}

void FirstError::rethrow() {
  std::exception_ptr error;
  {
    const std::lock_guard lock(mutex_);
    std::swap(error, error_);
  }
  if (error) std::rethrow_exception(error);
}

namespace {

// Tells the core that this thread spins (x86's pause); other targets (WebAssembly) have no such hint.
void spin_pause() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#endif
}

// Waits until `value` differs from `old` and returns the new value: first spinning for a few tens of
// microseconds (the next pass usually follows at once, and waking a sleeping thread costs as much as the
// spin), then asleep in the kernel.
std::uint32_t wait_for_change(const std::atomic<std::uint32_t>& value, std::uint32_t old) {
  const auto spin_until = std::chrono::steady_clock::now() + std::chrono::microseconds(30);
  for (int i = 0;; ++i) {
    const std::uint32_t now = value.load(std::memory_order_acquire);
    if (now != old) return now;
    if ((i & 63) == 63 && std::chrono::steady_clock::now() > spin_until) break;
    spin_pause();
  }
  for (;;) {
    value.wait(old, std::memory_order_acquire);
    const std::uint32_t now = value.load(std::memory_order_acquire);
    if (now != old) return now;
  }
}

void run_on_new_threads(unsigned count, const std::function<void(unsigned)>& task) {
  FirstError error;
  std::vector<std::thread> threads;
  threads.reserve(count - 1);
  for (unsigned i = 1; i < count; ++i) threads.emplace_back([&, i] { error.run(task, i); });
  error.run(task, 0);
  for (std::thread& thread : threads) thread.join();
  error.rethrow();
}

// Where no thread can start, the tasks run one after another in the caller: each still gets its part, so
// the results are those of the threads.
void run_in_caller(unsigned count, const std::function<void(unsigned)>& task) {
  FirstError error;
  for (unsigned i = 0; i < count; ++i) error.run(task, i);
  error.rethrow();
}

}  // namespace

WorkerPool& WorkerPool::shared() {
  static WorkerPool pool;
  return pool;
}

WorkerPool::~WorkerPool() {
  is_stopping_ = true;
  pass_.fetch_add(1, std::memory_order_release);
  pass_.notify_all();
  for (std::thread& worker : workers_) worker.join();
}

void WorkerPool::run(unsigned count, const std::function<void(unsigned)>& task) {
  if (count <= 1) {
    if (count == 1) task(0);
    return;
  }
  if (!can_start_threads()) return run_in_caller(count, task);
  const std::unique_lock lock(busy_, std::try_to_lock);
  if (!lock.owns_lock()) return run_on_new_threads(count, task);
  while (workers_.size() + 1 < count) {
    // A new worker waits for the pass after the current one.
    const std::uint32_t current = pass_.load(std::memory_order_relaxed);
    const unsigned index = unsigned(workers_.size());
    workers_.emplace_back([this, index, current] {
      std::uint32_t seen = current;
      for (;;) {
        seen = wait_for_change(pass_, seen);
        if (is_stopping_) return;
        serve(index);
      }
    });
  }
  task_ = &task;
  count_ = count;
  unfinished_.store(std::uint32_t(workers_.size()), std::memory_order_relaxed);
  pass_.fetch_add(1, std::memory_order_release);
  pass_.notify_all();
  // The workers hold the task until they are done: an exception in any task waits for them too.
  error_.run(task, 0);
  for (std::uint32_t left = unfinished_.load(std::memory_order_acquire); left != 0;)
    left = wait_for_change(unfinished_, left);
  error_.rethrow();
}

void WorkerPool::serve(unsigned worker) {
  if (worker + 1 < count_) error_.run(*task_, worker + 1);
  if (unfinished_.fetch_sub(1, std::memory_order_acq_rel) == 1) unfinished_.notify_one();
}

}  // namespace nome
