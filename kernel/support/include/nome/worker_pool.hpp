#pragma once

#include <atomic>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace nome {

// The first exception thrown by the tasks of a pass, on whichever thread, for the caller to rethrow.
class FirstError {
 public:
  void run(const std::function<void(unsigned)>& task, unsigned i) noexcept;
  // Rethrows the exception kept, if any, and forgets it.
  void rethrow();

 private:
  std::mutex mutex_;
  std::exception_ptr error_;
};

// Threads kept from one parallel pass to the next. Starting a thread costs tens of microseconds on these
// machines, and a refinement or a slider's tick runs dozens of passes of a few hundred microseconds each.
class WorkerPool {
 public:
  WorkerPool() = default;
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;
  ~WorkerPool();

  // The process's pool; its threads start with the first pass that needs them.
  static WorkerPool& shared();

  // Runs task(i) for every i in [0, count), task(0) on the calling thread, and returns once all have
  // run; then rethrows the first exception a task threw, on any thread. A pass asked for while another runs
  // (from another thread, or from inside a task) gets threads of its own for its length. Where threads
  // cannot start (can_start_threads), all tasks run on the calling thread, in order.
  void run(unsigned count, const std::function<void(unsigned)>& task);

 private:
  void serve(unsigned worker);

  std::mutex busy_;
  std::vector<std::thread> workers_;
  // Written before `pass_` moves on, read by the workers after they see it move.
  const std::function<void(unsigned)>* task_ = nullptr;
  unsigned count_ = 0;
  bool is_stopping_ = false;
  std::atomic<std::uint32_t> pass_{0};
  // Workers yet to finish the current pass: every worker answers every pass, those without a task at once,
  // so that none still reads `count_` when the next pass writes it.
  std::atomic<std::uint32_t> unfinished_{0};
  FirstError error_;  // of the current pass
};

}  // namespace nome
