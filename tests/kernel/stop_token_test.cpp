#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>

#include "nome/stop_token.hpp"

// The portable jthread and stop tokens stand in for the standard ones where the standard library lacks
// them (the browser build): they are tested here, where the standard ones exist to compare with.
namespace {

using namespace std::chrono_literals;

TEST_CASE("A portable jthread hands its work a token and stops it when it goes away", "[kernel]") {
  std::atomic<bool> saw_stop = false;
  {
    nome::portable::jthread worker([&](nome::portable::stop_token stop) {
      while (!stop.stop_requested()) std::this_thread::sleep_for(1ms);
      saw_stop = true;
    });
    CHECK(worker.joinable());
  }
  CHECK(saw_stop);
}

TEST_CASE("A portable jthread runs work that takes no token and joins it", "[kernel]") {
  std::atomic<int> runs = 0;
  {
    nome::portable::jthread worker([&](int step) { runs += step; }, 3);
  }
  CHECK(runs == 3);
}

TEST_CASE("Assigning a portable jthread stops and joins the thread it held", "[kernel]") {
  std::atomic<bool> first_stopped = false, second_ran = false;
  nome::portable::jthread worker([&](nome::portable::stop_token stop) {
    while (!stop.stop_requested()) std::this_thread::sleep_for(1ms);
    first_stopped = true;
  });
  worker = nome::portable::jthread([&] { second_ran = true; });
  CHECK(first_stopped);
  worker.join();
  CHECK(second_ran);
  CHECK_FALSE(worker.joinable());
}

TEST_CASE("A portable stop source answers as the standard one does", "[kernel]") {
  nome::portable::stop_source source;
  std::stop_source standard;
  const nome::portable::stop_token token = source.get_token();
  CHECK(token.stop_possible() == standard.get_token().stop_possible());
  CHECK(token.stop_requested() == standard.stop_requested());
  CHECK(source.request_stop() == standard.request_stop());
  CHECK(source.request_stop() == standard.request_stop());
  CHECK(token.stop_requested() == standard.get_token().stop_requested());
  CHECK_FALSE(nome::portable::stop_token().stop_possible());
}

}  // namespace
