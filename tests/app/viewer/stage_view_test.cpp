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

TEST_CASE("a request says what changed in the session's input: nothing, positions or topology", "[app]") {
  viewer::Session session = viewer::Session::open(NOME_SOURCE_DIR "/assets/funnel_cube.nome");
  std::vector<double> distances;
  viewer::StageView view([&](const viewer::SceneInput&, const PipelineSettings& settings, nome::stop_token) {
    distances.push_back(settings.offset_distance);
    return std::optional<viewer::StageResult>();
  });
  auto requested = [&] {
    const viewer::InputChange change = view.request(session);
    view.take(10s);
    CHECK(change.face_attributes == (change.geometry == Change::topology));
    return change.geometry;
  };
  CHECK(requested() == Change::topology);  // the first
  CHECK(requested() == Change::none);
  view.settings().offset_distance = 0.25;  // the stage changes, the input does not
  CHECK(requested() == Change::none);
  CHECK(distances.back() == 0.25);
  session.set_parameter("fp_h", 0.3);  // moves vertices
  CHECK(requested() == Change::positions);
  session.set_parameter("fp_n", 5);  // another number of faces
  CHECK(requested() == Change::topology);
  session.set_parameter("fp_h", 0.4);
  session.set_parameter("fp_h", 0.5);
  CHECK(requested() == Change::positions);
  view.invalidate();
  CHECK(requested() == Change::topology);
  CHECK(distances.size() == 6);
  session.set_instance_color("cf_fun1", Color(1.0f, 0.0f, 0.0f));  // a colour: the same topology
  const viewer::InputChange colored = view.request(session);
  CHECK(colored.geometry == Change::positions);
  CHECK(colored.face_attributes);
  view.take(10s);
}
