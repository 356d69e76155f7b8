#include <atomic>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <catch2/catch.hpp>

#include "nome/worker_pool.hpp"

using nome::WorkerPool;

namespace {

// Runs a pass of `count` tasks on `pool` and returns how often each task ran and on which thread.
struct Pass {
  std::vector<std::atomic<int>> runs;
  std::vector<std::thread::id> threads;
  explicit Pass(unsigned count) : runs(count), threads(count) {}
  void run(WorkerPool& pool) {
    pool.run(unsigned(runs.size()), [&](unsigned i) {
      threads[i] = std::this_thread::get_id();
      ++runs[i];
    });
  }
  bool each_ran_once() const {
    for (const auto& r : runs)
      if (r.load() != 1) return false;
    return true;
  }
};

}  // namespace

TEST_CASE("A worker pool runs each task of a pass once, the first on the caller", "[kernel]") {
  WorkerPool pool;
  for (const unsigned count : {1u, 2u, 3u, 2u, 5u}) {
    Pass pass(count);
    pass.run(pool);
    INFO("count " << count);
    CHECK(pass.each_ran_once());
    CHECK(pass.threads[0] == std::this_thread::get_id());
    for (unsigned i = 1; i < count; ++i) CHECK(pass.threads[i] != std::this_thread::get_id());
  }
  Pass none(0);
  none.run(pool);
}

TEST_CASE("A worker pool keeps its threads from pass to pass", "[kernel]") {
  // Each thread counts the passes it served: a kept thread has served the earlier ones too (a thread id
  // alone could not tell, as a new thread may take a finished one's id).
  thread_local int served = 0;
  WorkerPool pool;
  std::vector<int> seen(3);
  for (int& s : seen)
    pool.run(2, [&](unsigned i) {
      if (i == 1) s = ++served;
    });
  CHECK(seen == std::vector<int>{1, 2, 3});
}

TEST_CASE("A pass nested in a task, or asked for from another thread, still runs in full", "[kernel]") {
  WorkerPool pool;
  std::atomic<int> inner_runs{0};
  pool.run(2, [&](unsigned) {
    Pass inner(3);
    inner.run(pool);
    if (inner.each_ran_once()) ++inner_runs;
  });
  CHECK(inner_runs == 2);

  std::atomic<int> good{0};
  auto passes = [&] {
    for (int i = 0; i < 200; ++i) {
      Pass pass(2);
      pass.run(pool);
      if (pass.each_ran_once()) ++good;
    }
  };
  std::thread other(passes);
  passes();
  other.join();
  CHECK(good == 400);
}

TEST_CASE("An exception in any task reaches the caller after the other tasks ran, also on a busy pool",
          "[kernel]") {
  for (const unsigned thrower : {0u, 2u}) {
    INFO("task " << thrower << " throws");
    WorkerPool pool;
    std::atomic<int> others{0};
    const std::string what = "task " + std::to_string(thrower);
    const auto throwing = [&](unsigned i) {
      if (i == thrower) throw std::runtime_error(what);
      ++others;
    };
    CHECK_THROWS_WITH(pool.run(3, throwing), what);
    CHECK(others == 2);
    // From inside a task the pool is busy: the nested pass runs on threads of its own.
    CHECK_THROWS_WITH(pool.run(2,
                               [&](unsigned i) {
                                 if (i == 0) pool.run(3, throwing);
                               }),
                      what);
    Pass after(3);
    after.run(pool);
    CHECK(after.each_ran_once());
  }
}
