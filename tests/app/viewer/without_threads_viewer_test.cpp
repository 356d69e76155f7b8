#include <catch2/catch.hpp>

#include <stdexcept>
#include <thread>

#include "nome/thread_support.hpp"
#include "support/same_mesh.hpp"
#include "support/shapes.hpp"
#include "viewer/session/background_job.hpp"
#include "viewer/session/stage_pipeline.hpp"

using namespace nome;
using nome::viewer::BackgroundJob;
using namespace std::chrono_literals;

TEST_CASE("without threads, a job runs when its result is taken, on the taking thread", "[app]") {
  const WithoutThreads without_threads;
  BackgroundJob<std::thread::id> job;
  int runs = 0;
  job.submit([&](nome::stop_token) {
    ++runs;
    return std::this_thread::get_id();
  });
  CHECK(job.is_busy());
  CHECK(runs == 0);
  const auto result = job.take();
  REQUIRE(result);
  CHECK(*result == std::this_thread::get_id());
  CHECK(runs == 1);
  CHECK_FALSE(job.is_busy());
  CHECK_FALSE(job.take());  // handed over once
}

TEST_CASE("without threads, a superseded request never runs, and a cancelled one neither", "[app]") {
  const WithoutThreads without_threads;
  BackgroundJob<int> job;
  bool first_ran = false;
  job.submit([&](nome::stop_token) {
    first_ran = true;
    return 1;
  });
  job.submit([](nome::stop_token) { return 2; });
  const auto result = job.take(5000ms);
  REQUIRE(result);
  CHECK(*result == 2);
  CHECK_FALSE(first_ran);
  job.submit([&](nome::stop_token) {
    first_ran = true;
    return 3;
  });
  job.cancel();
  CHECK_FALSE(job.is_busy());
  CHECK_FALSE(job.take());
  CHECK_FALSE(first_ran);
}

TEST_CASE("without threads, a job's exception reaches the caller of take", "[app]") {
  const WithoutThreads without_threads;
  BackgroundJob<int> job;
  job.submit([](nome::stop_token) -> int { throw std::runtime_error("a.nome:3:4: expected ')'"); });
  CHECK_THROWS_WITH(job.take(), "a.nome:3:4: expected ')'");
  CHECK_FALSE(job.is_busy());
}

TEST_CASE("without threads, the viewer's stages and display arrays are the threads' bit for bit", "[app]") {
  // Large enough for the helper threads of the display arrays (from 2^16 vertices).
  const PipelineInput input{test::torus(64, 24), {}, {}};
  PipelineSettings settings = viewer::initial_settings();
  settings.stage = Stage::subdivided_offset;
  settings.subdivision_levels = 3;
  settings.threads = 4;
  // Twice each: a new topology, then the same one again (kept display topology, the mesh copied back).
  auto run_twice = [&] {
    viewer::StagePipeline pipeline;
    std::vector<viewer::StageResult> results;
    for (const double distance : {0.05, 0.04}) {
      settings.offset_distance = distance;
      auto result = pipeline.run(input, settings, nome::stop_token{});
      REQUIRE(result);
      results.push_back(std::move(*result));
    }
    return results;
  };
  const auto threaded = run_twice();
  REQUIRE(threaded[0].mesh->num_vertices() >= (1u << 16));
  const WithoutThreads without_threads;
  const auto inline_run = run_twice();
  for (std::size_t i = 0; i < threaded.size(); ++i) {
    test::check_same_mesh(*inline_run[i].mesh, *threaded[i].mesh);
    const render::DisplayPositions &a = *inline_run[i].display.positions, &b = *threaded[i].display.positions;
    CHECK(a.vertices == b.vertices);
    CHECK(a.vertex_normals == b.vertex_normals);
    CHECK(a.face_normals == b.face_normals);
    CHECK(a.extra_vertices == b.extra_vertices);
    CHECK(a.extra_normals == b.extra_normals);
    CHECK(a.bounds.min == b.bounds.min);
    CHECK(a.bounds.max == b.bounds.max);
    CHECK(inline_run[i].display.topology->triangles == threaded[i].display.topology->triangles);
  }
}
