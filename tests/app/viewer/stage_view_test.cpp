#include <catch2/catch.hpp>

#include <future>
#include <mutex>
#include <vector>

#include "support/shapes.hpp"
#include "viewer/session/stage_view.hpp"

using namespace nome;
using namespace std::chrono_literals;

namespace {

// An evaluation that waits for the test to open its gate (at most 10 s, so that a frame that waited
// for it would see its result and fail the checks rather than hang), telling which distance it ran.
struct GatedEvaluation {
  std::mutex mutex;
  std::shared_future<void> gate;
  std::vector<double> distances;  // of the evaluations started

  void close(std::promise<void>& opener) {
    std::lock_guard lock(mutex);
    gate = opener.get_future().share();
  }
  std::optional<viewer::StageResult> operator()(const PipelineSettings& settings) {
    std::shared_future<void> wait_for;
    {
      std::lock_guard lock(mutex);
      distances.push_back(settings.offset_distance);
      wait_for = gate;
    }
    if (wait_for.valid()) wait_for.wait_for(10s);
    viewer::StageResult result;
    result.stage = settings.stage;
    result.mesh = std::make_shared<const Mesh>(build_mesh(test::cube()));
    result.seconds = settings.offset_distance;  // which request this is
    return result;
  }
  std::size_t started() {
    std::lock_guard lock(mutex);
    return distances.size();
  }
};

}  // namespace

TEST_CASE("a frame never waits for a stage in flight: the last one stays, the latest request runs next",
          "[app][threads]") {
  GatedEvaluation evaluation;
  viewer::StageView view([&](const viewer::SceneInput&, const PipelineSettings& settings, nome::stop_token) {
    return evaluation(settings);
  });
  const viewer::Session session = viewer::Session::open(NOME_SOURCE_DIR "/assets/cube.obj");
  view.settings().offset_distance = 0.1;
  view.request(session);
  const auto deadline = std::chrono::steady_clock::now() + 10s;
  auto first = view.take_for_frame();
  while (!first && std::chrono::steady_clock::now() < deadline) first = view.take_for_frame();
  REQUIRE(first);
  view.show(std::move(*first), 0.0);

  std::promise<void> opener;
  evaluation.close(opener);
  view.settings().offset_distance = 0.2;  // starts at once, then blocks
  view.request(session);
  view.settings().offset_distance = 0.3;  // waits for it, then is replaced by the next
  view.request(session);
  view.settings().offset_distance = 0.4;
  view.request(session);
  while (evaluation.started() < 2 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(1ms);
  for (int frame = 0; frame < 3; ++frame) CHECK_FALSE(view.take_for_frame());
  CHECK(view.is_busy());
  CHECK(view.shown()->seconds == 0.1);  // the last stage stays on screen
  CHECK(evaluation.started() == 2);     // one job at a time

  opener.set_value();
  std::vector<double> shown;
  while (view.is_busy() && std::chrono::steady_clock::now() < deadline + 10s)
    if (auto result = view.take_for_frame()) shown.push_back(result->seconds);
  CHECK(shown == std::vector<double>{0.2, 0.4});
  CHECK(evaluation.distances == std::vector<double>{0.1, 0.2, 0.4});
}
