#include <catch2/catch.hpp>

#include <atomic>
#include <stdexcept>

#include "viewer/session/background_job.hpp"

using nome::viewer::BackgroundJob;
using namespace std::chrono_literals;

TEST_CASE("a newer request supersedes the work in flight, whose result is dropped", "[app][threads]") {
  BackgroundJob<int> job;
  std::atomic<bool> first_saw_stop{false};
  job.submit([&](nome::stop_token stop) {
    while (!stop.stop_requested()) std::this_thread::sleep_for(1ms);
    first_saw_stop = true;
    return 1;
  });
  CHECK(job.is_busy());
  CHECK_FALSE(job.take(5ms));
  job.submit([](nome::stop_token) { return 2; });
  const auto result = job.take(5000ms);
  REQUIRE(result);
  CHECK(*result == 2);
  CHECK_FALSE(job.is_busy());
  CHECK_FALSE(job.take(1ms));  // handed over once
  job.cancel();
  CHECK(first_saw_stop);
}

TEST_CASE("a job's exception reaches the thread that takes its result", "[app][threads]") {
  BackgroundJob<int> job;
  job.submit([](nome::stop_token) -> int { throw std::runtime_error("a.nome:3:4: expected ')'"); });
  CHECK_THROWS_WITH(job.take(5000ms), "a.nome:3:4: expected ')'");
  CHECK_FALSE(job.is_busy());
}
