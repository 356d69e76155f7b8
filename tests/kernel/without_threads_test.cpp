#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "nome/atomic_file.hpp"
#include "nome/edit/scene_document.hpp"
#include "nome/file_blocks.hpp"
#include "nome/io/obj.hpp"
#include "nome/ops/pipeline.hpp"
#include "nome/query/triangle_bvh.hpp"
#include "nome/thread_support.hpp"
#include "nome/worker_pool.hpp"
#include "scene/scene_support.hpp"
#include "support/same_mesh.hpp"
#include "support/scratch_files.hpp"
#include "support/shapes.hpp"

using namespace nome;

namespace {

// The threads of this process now (Linux): a writer or helper thread that runs shows here.
std::size_t live_threads() {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& task : std::filesystem::directory_iterator("/proc/self/task")) ++n;
  return n;
}

// Every face with vertices of its own: only the merge joins them.
PolygonSoup unwelded(const PolygonSoup& soup) {
  PolygonSoup out;
  for (Index f = 0; f < soup.num_faces(); ++f) {
    for (Index c = soup.face_offsets[f]; c < soup.face_offsets[f + 1]; ++c) {
      out.face_vertices.push_back(Index(out.positions.size()));
      out.positions.push_back(soup.positions[soup.face_vertices[c]]);
    }
    out.face_offsets.push_back(Index(out.face_vertices.size()));
  }
  return out;
}

// Merged, three levels of Catmull-Clark, thickened, on more threads than the machine has cores.
PipelineSettings solid_settings() {
  PipelineSettings s;
  s.stage = Stage::offset;
  s.should_merge = true;
  s.subdivision_levels = 3;
  s.offset_distance = 0.02;
  s.threads = 4;
  return s;
}

Mesh solid(const PipelineInput& input) {
  Pipeline pipeline;
  pipeline.set_input(input);
  return pipeline.run(solid_settings());
}

void check_same_solid_without_threads(const PipelineInput& input) {
  const Mesh threaded = solid(input);
  // Large enough that the passes split: a pool that dropped or repeated a part would show.
  REQUIRE(threaded.num_faces() > 2 * (Index{1} << 15));
  const WithoutThreads without_threads;
  test::check_same_mesh(solid(input), threaded);
}

}  // namespace

TEST_CASE("without threads, a worker pool runs every task on the caller, in order", "[kernel]") {
  WorkerPool pool;
  const WithoutThreads without_threads;
  CHECK_FALSE(can_start_threads());
  std::vector<unsigned> order;
  std::vector<std::thread::id> threads;
  const std::size_t before = live_threads();
  pool.run(5, [&](unsigned i) {
    order.push_back(i);
    threads.push_back(std::this_thread::get_id());
  });
  CHECK(live_threads() == before);
  CHECK(order == std::vector<unsigned>{0, 1, 2, 3, 4});
  for (const std::thread::id id : threads) CHECK(id == std::this_thread::get_id());
}

TEST_CASE("without threads, a worker pool runs all tasks and then rethrows the first error", "[kernel]") {
  WorkerPool pool;
  const WithoutThreads without_threads;
  int ran = 0;
  CHECK_THROWS_WITH(pool.run(3,
                             [&](unsigned i) {
                               ++ran;
                               if (i > 0) throw std::runtime_error("task " + std::to_string(i));
                             }),
                    "task 1");
  CHECK(ran == 3);
}

TEST_CASE("the switch for tests restores what it found", "[kernel]") {
  CHECK(can_start_threads() == build_has_threads);
  {
    const WithoutThreads outer;
    {
      const WithoutThreads inner;
      CHECK_FALSE(can_start_threads());
    }
    CHECK_FALSE(can_start_threads());
  }
  CHECK(can_start_threads() == build_has_threads);
}

TEST_CASE("without threads, merge, three levels and the offset give the threads' solid bit for bit",
          "[kernel]") {
  SECTION("a torus") {
    check_same_solid_without_threads({unwelded(test::torus(64, 24)), {}, {}});
  }
  SECTION("a Möbius band") {
    check_same_solid_without_threads({unwelded(test::mobius_band(128, 12)), {}, {}});
  }
  SECTION("the report's funnel cube") {
    const SceneDocument doc =
        SceneDocument::from_scene(test::load_scene_file(test::assets_dir() + "funnel_cube.nome"));
    PipelineInput input = doc.pipeline_input();
    PipelineSettings settings = solid_settings();
    settings.subdivision_levels = 5;  // its 48 quads: enough faces to split the passes
    Pipeline threaded_pipeline;
    threaded_pipeline.set_input(input);
    const Mesh threaded = threaded_pipeline.run(settings);
    REQUIRE(threaded.num_faces() > 2 * (Index{1} << 15));
    const WithoutThreads without_threads;
    Pipeline pipeline;
    pipeline.set_input(input);
    test::check_same_mesh(pipeline.run(settings), threaded);
  }
}

TEST_CASE("without threads, a BVH's two halves are built in turn and answer as the threads' do", "[kernel]") {
  const Mesh mesh = solid({unwelded(test::torus(64, 24)), {}, {}});
  BvhOptions options;
  options.parallel_build_threshold = 1;
  const TriangleBvh threaded(mesh, options);
  const std::size_t before = live_threads();
  const WithoutThreads without_threads;
  const TriangleBvh inline_built(mesh, options);
  CHECK(live_threads() == before);
  CHECK(inline_built.num_nodes() == threaded.num_nodes());
  for (int i = 0; i < 64; ++i) {
    const double angle = 0.1 * i;
    const Ray ray{Vec3(3.0 * std::cos(angle), 3.0 * std::sin(angle), 0.05 * (i % 7)),
                  Vec3(-std::cos(angle), -std::sin(angle), 0.0)};
    const auto a = threaded.cast_all(ray), b = inline_built.cast_all(ray);
    REQUIRE(a.size() == b.size());
    for (std::size_t h = 0; h < a.size(); ++h) {
      CHECK(a[h].face == b[h].face);
      CHECK(a[h].depth == b[h].depth);
    }
  }
}

TEST_CASE("without threads, a file's blocks are written by the caller, the same bytes", "[kernel]") {
  // Enough bytes for several blocks, none a multiple of a disk block.
  std::string text;
  for (int i = 0; text.size() < 3 * FileBlocks::block_bytes + 12345; ++i) text += std::to_string(i) + '\n';
  auto write = [&](const std::string& name) {
    const auto path = test::scratch_path("nome_without_threads", name);
    std::size_t extra_threads = 0;
    const std::size_t before = live_threads();
    write_file_in_blocks(path, [&](FileBlocks& blocks) {
      for (std::size_t at = 0; at < text.size(); at += 1000) {
        const std::size_t n = std::min<std::size_t>(1000, text.size() - at);
        char* room = blocks.room(n);
        text.copy(room, n, at);
        blocks.commit(room + n);
      }
      extra_threads = live_threads() - before;
    });
    return std::pair{test::file_bytes(path), extra_threads};
  };
  const auto [threaded, writers] = write("threaded.txt");
  CHECK(threaded == text);
  CHECK(writers == (build_has_threads ? 1 : 0));
  const WithoutThreads without_threads;
  const auto [caller_written, no_writers] = write("caller.txt");
  CHECK(no_writers == 0);
  CHECK(caller_written == text);
}

TEST_CASE("without threads, an OBJ export of a solid writes the threads' bytes", "[kernel]") {
  const Mesh mesh = solid({unwelded(test::torus(64, 24)), {}, {}});
  const auto threaded = test::scratch_path("nome_without_threads", "threaded.obj");
  write_obj(threaded, mesh);
  const WithoutThreads without_threads;
  const auto caller_written = test::scratch_path("nome_without_threads", "caller.obj");
  write_obj(caller_written, mesh);
  const std::string bytes = test::file_bytes(threaded);
  REQUIRE(bytes.size() > 2 * FileBlocks::block_bytes);
  CHECK(test::file_bytes(caller_written) == bytes);
}
