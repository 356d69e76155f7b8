#include <catch2/catch.hpp>

#include <algorithm>
#include <functional>

#include "nome/error.hpp"
#include "nome/mesh/topology_report.hpp"
#include "nome/ops/offset.hpp"
#include "nome/ops/pipeline.hpp"
#include "support/same_report.hpp"
#include "support/shapes.hpp"

using namespace nome;

namespace {

PipelineSettings full_options() {
  PipelineSettings o;
  o.subdivision_levels = 2;
  o.offset_distance = 0.04;
  o.subdivision_after = 1;
  return o;
}

Mesh moved(Mesh m, double amount) {
  for (Vec3& p : m.positions()) p += Vec3(amount * p.y, 0.0, amount * p.x * p.x);
  return m;
}

}  // namespace

TEST_CASE("the pipeline composes subdivision, offset and subdivision after", "[kernel]") {
  const Mesh band = build_mesh(test::mobius_band(12, 2));
  Pipeline pipeline;
  const Mesh& result = pipeline.run(band, full_options());
  const Mesh expected =
      offset(subdivide(band, {2, SubdivisionRule::classic}), {0.04, 1, SubdivisionRule::classic});
  CHECK(result.positions() == expected.positions());
  CHECK(result.corner_vertices() == expected.corner_vertices());
  const TopologyReport r = topology_report(result);
  CHECK((r.chi == 0 && r.orientable && r.borders == 0 && r.components.size() == 1));
  CHECK(pipeline.work(Stage::subdivided) == StageWork::rebuilt);
  CHECK(pipeline.work(Stage::offset) == StageWork::rebuilt);
  CHECK(pipeline.work(Stage::subdivided_offset) == StageWork::rebuilt);
}

TEST_CASE("the pipeline redoes only what an input or option change invalidates", "[kernel]") {
  const Mesh band = build_mesh(test::mobius_band(12, 2));
  Pipeline pipeline;
  PipelineSettings o = full_options();
  pipeline.run(band, o);

  pipeline.run(band, o);
  CHECK(pipeline.work(Stage::subdivided) == StageWork::cached);
  CHECK(pipeline.work(Stage::offset) == StageWork::cached);
  CHECK(pipeline.work(Stage::subdivided_offset) == StageWork::cached);

  // A slider moved vertices: every stage re-runs its position pass only, and gets what a fresh
  // pipeline gets, bit for bit.
  const Mesh dragged = moved(band, 0.2);
  const Buffer<Vec3> fast = pipeline.run(dragged, o).positions();
  CHECK(pipeline.work(Stage::subdivided) == StageWork::positions);
  CHECK(pipeline.work(Stage::offset) == StageWork::positions);
  CHECK(pipeline.work(Stage::subdivided_offset) == StageWork::positions);
  CHECK(fast == Pipeline().run(dragged, o).positions());

  o.offset_distance = 0.08;  // a thicker slab: the subdivision before the offset is kept
  const Buffer<Vec3> thicker = pipeline.run(dragged, o).positions();
  CHECK(pipeline.work(Stage::subdivided) == StageWork::cached);
  CHECK(pipeline.work(Stage::offset) == StageWork::positions);
  CHECK(pipeline.work(Stage::subdivided_offset) == StageWork::positions);
  CHECK(thicker == Pipeline().run(dragged, o).positions());

  o.rule = SubdivisionRule::report;
  pipeline.run(dragged, o);
  CHECK(pipeline.work(Stage::subdivided) == StageWork::positions);
  CHECK(pipeline.run(dragged, o).positions() == Pipeline().run(dragged, o).positions());

  o.subdivision_levels = 1;
  pipeline.run(dragged, o);
  CHECK(pipeline.work(Stage::subdivided) == StageWork::rebuilt);
  CHECK(pipeline.work(Stage::offset) == StageWork::rebuilt);

  const Mesh other = build_mesh(test::mobius_band(10, 2));
  const Mesh& result = pipeline.run(other, o);
  CHECK(pipeline.work(Stage::subdivided) == StageWork::rebuilt);
  CHECK(result.positions() == Pipeline().run(other, o).positions());

  o.offset_distance = 0;
  o.subdivision_after = 0;
  CHECK(pipeline.run(other, o).num_faces() == other.num_corners());
  CHECK(pipeline.work(Stage::offset) == StageWork::skipped);
}

TEST_CASE("moving the input's vertices flows positions only and equals a whole new input", "[kernel]") {
  const PolygonSoup band = test::mobius_band(12, 2);
  Pipeline pipeline;
  PipelineSettings o = full_options();
  CHECK_THROWS_AS(pipeline.move_input_vertices(band.positions), InvalidInputError);  // no input yet
  pipeline.set_input(PipelineInput{band, {}, {}});
  pipeline.run(o);
  PolygonSoup dragged = band;
  for (Vec3& p : dragged.positions) p += Vec3(0.2 * p.y, 0.0, 0.1 * p.x * p.x);
  pipeline.move_input_vertices(dragged.positions);
  const Buffer<Vec3> fast = pipeline.run(o).positions();
  CHECK(pipeline.work(Stage::scene) == StageWork::positions);
  CHECK(pipeline.work(Stage::subdivided) == StageWork::positions);
  Pipeline fresh;
  fresh.set_input(PipelineInput{dragged, {}, {}});
  CHECK(fast == fresh.run(o).positions());
  Buffer<Vec3> short_by_one = dragged.positions;
  short_by_one.pop_back();
  CHECK_THROWS_AS(pipeline.move_input_vertices(short_by_one), InvalidInputError);
}

TEST_CASE("the pipeline refuses a result over the memory budget unless forced", "[kernel]") {
  const Mesh cube = build_mesh(test::cube());
  PipelineSettings o;
  o.subdivision_levels = 12;
  const PipelineEstimate e = estimate_pipeline(cube, o);
  CHECK(e.faces == 24.0 * (1 << 22));
  CHECK_THROWS_AS(Pipeline().run(cube, o), BudgetError);
  CHECK_THROWS_WITH(Pipeline().run(cube, o), Catch::Contains("100663296 faces") && Catch::Contains("GB"));
  o.subdivision_levels = 2;
  o.memory_budget = 1000;
  CHECK_THROWS_AS(Pipeline().run(cube, o), BudgetError);
  o.force = true;
  CHECK(Pipeline().run(cube, o).num_faces() == 96);
  // Offset and subdivision after are counted too: 2 * 96 faces, then 4 * 4 each.
  o.offset_distance = 0.1;
  o.subdivision_after = 1;
  CHECK(estimate_pipeline(cube, o).faces == 2 * 96 * 4);
  CHECK(Pipeline().run(cube, o).num_faces() == 2 * 96 * 4);
}

TEST_CASE("the pipeline checks its options and passes on the offset's warnings", "[kernel]") {
  const Mesh cube = build_mesh(test::cube());
  PipelineSettings o;
  o.offset_distance = -1;
  CHECK_THROWS_AS(Pipeline().run(cube, o), InvalidInputError);
  o.offset_distance = 0;
  o.subdivision_after = 1;
  CHECK_THROWS_WITH(Pipeline().run(cube, o), Catch::Contains("needs an offset"));
  o.subdivision_after = 0;
  o.subdivision_levels = -1;
  CHECK_THROWS_AS(Pipeline().run(cube, o), InvalidInputError);

  PolygonSoup s = test::grid(2, 1);
  s.positions[4] = s.positions[1];
  s.positions[5] = s.positions[2];
  Pipeline pipeline;
  PipelineSettings thick;
  thick.offset_distance = 0.1;
  pipeline.run(build_mesh(s), thick);
  REQUIRE(pipeline.warnings().size() == 1);
  CHECK_THAT(pipeline.warnings()[0],
             Catch::StartsWith("offset: 1 degenerate faces") && Catch::Contains("f1"));
}

TEST_CASE("the pipeline's result is the stage asked for, also after a later stage ran", "[kernel]") {
  PipelineInput input;
  input.soup = test::mobius_band(12, 2);
  Pipeline pipeline;
  pipeline.set_input(input);
  PipelineSettings s = full_options();
  const Index solid_faces = pipeline.run(s).num_faces();
  s.stage = Stage::merged;
  s.should_merge = true;
  const Index merged_faces = pipeline.run(s).num_faces();
  CHECK(merged_faces == 24);
  CHECK(solid_faces > merged_faces);
  CHECK(pipeline.take_result().num_faces() == merged_faces);
}

TEST_CASE("a part that may touch at vertices is split there with a warning, other faults stay refused",
          "[kernel]") {
  // Two triangles meeting only at vertex 0 (a bowtie), named so that the warning can say which.
  PolygonSoup bowtie;
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(-1, 0, 0), Vec3(-1, -1, 0)})
    bowtie.add_vertex(p);
  bowtie.add_face({0, 1, 2});
  bowtie.add_face({0, 3, 4});
  bowtie.vertex_names = {"apex", "a", "b", "c", "d"};
  PipelineSettings scene_stage;
  scene_stage.stage = Stage::scene;

  CHECK_THROWS_WITH(
      Pipeline().set_input(PipelineInput{bowtie, {{"bowtie.obj", 2, false}}, Joining::manifold}),
      Catch::Contains("bowtie.obj") && Catch::Contains("vertex apex") && Catch::Contains("one fan"));

  Pipeline splitting;
  splitting.set_input(PipelineInput{bowtie, {{"bowtie.nome", 2, true}}, Joining::manifold});
  const Mesh& split = splitting.run(scene_stage);
  CHECK(split.num_vertices() == 6);
  CHECK(topology_report(split).components.size() == 2);
  REQUIRE(splitting.warnings().size() == 1);
  CHECK_THAT(splitting.warnings()[0], Catch::Contains("1 vertices") && Catch::Contains("(apex)"));

  // A slider that moves the shared vertex moves both copies and keeps the warning.
  PolygonSoup moved = bowtie;
  moved.positions[0] = Vec3(0, 0, 2);
  splitting.set_input(PipelineInput{moved, {{"bowtie.nome", 2, true}}, Joining::manifold});
  const Mesh& after = splitting.run(scene_stage);
  CHECK(splitting.work(Stage::scene) == StageWork::positions);
  CHECK(std::count(after.positions().begin(), after.positions().end(), Vec3(0, 0, 2)) == 2);
  CHECK(splitting.warnings().size() == 1);

  // An edge of three faces is refused all the same.
  PolygonSoup fin = bowtie;
  fin.add_face({0, 1, 3});
  fin.add_face({1, 0, 4});
  CHECK_THROWS_WITH(Pipeline().set_input(PipelineInput{fin, {{"fin.nome", 4, true}}, Joining::manifold}),
                    Catch::Contains("fin.nome") && Catch::Contains("has a third face"));
}

TEST_CASE("every sequence of settings gives what a new pipeline gives for the last one", "[kernel]") {
  // The offset's input is the subdivision's result or the scene itself: a change of levels between runs
  // changes the topology under the offset (turning subdivision off once kept the old solid's topology).
  const Mesh band = build_mesh(test::mobius_band(12, 2));
  const int levels_sequence[][2] = {{1, 0}, {0, 0}, {2, 1}, {0, 1}, {1, 1}, {1, 0}, {0, 0}};
  Pipeline live;
  for (const auto& [before, after] : levels_sequence) {
    INFO("levels before " << before << ", after " << after);
    PipelineSettings s = full_options();
    s.subdivision_levels = before;
    s.subdivision_after = after;
    const Mesh& result = live.run(band, s);
    Pipeline fresh;
    const Mesh& expected = fresh.run(band, s);
    CHECK(result.positions() == expected.positions());
    CHECK(result.corner_vertices() == expected.corner_vertices());
  }
}

TEST_CASE("the scene stage tells a new input's faces from the last one's, however it joined them",
          "[kernel]") {
  for (const Joining joining : {Joining::manifold, Joining::across_edges}) {
    CAPTURE(int(joining));
    PipelineSettings scene_only;
    scene_only.stage = Stage::scene;
    Pipeline pipeline;
    pipeline.set_input(PipelineInput{test::cube(), {}, joining});
    pipeline.run(scene_only);
    CHECK(pipeline.work(Stage::scene) == StageWork::rebuilt);

    PolygonSoup moved = test::cube();
    moved.positions[0] += Vec3(0.0, 0.0, 0.25);
    pipeline.set_input(PipelineInput{moved, {}, joining});
    const Mesh& after_move = pipeline.run(scene_only);
    CHECK(pipeline.work(Stage::scene) == StageWork::positions);
    CHECK(std::find(after_move.positions().begin(), after_move.positions().end(), moved.positions[0]) !=
          after_move.positions().end());

    // The same positions with one face turned the other way round: new faces, a new mesh.
    PolygonSoup turned = moved;
    std::reverse(turned.face_vertices.begin(), turned.face_vertices.begin() + turned.face_offsets[1]);
    pipeline.set_input(PipelineInput{turned, {}, joining});
    pipeline.run(scene_only);
    CHECK(pipeline.work(Stage::scene) == StageWork::rebuilt);
    pipeline.set_input(PipelineInput{turned, {}, joining});
    pipeline.run(scene_only);
    CHECK(pipeline.work(Stage::scene) == StageWork::positions);
  }
}

TEST_CASE("moving input vertices needs an input, not a mesh given as the result", "[kernel]") {
  Pipeline pipeline;
  PipelineSettings scene_only;
  scene_only.stage = Stage::scene;
  pipeline.set_input(PipelineInput{test::cube(), {}, {}});
  pipeline.move_input_vertices(test::cube().positions);
  pipeline.run(build_mesh(test::tetrahedron()), scene_only);
  CHECK_THROWS_AS(pipeline.move_input_vertices(test::cube().positions), InvalidInputError);
}

TEST_CASE("a later stage's result positions change places with the caller's, then are made again",
          "[kernel]") {
  const Mesh band = build_mesh(test::mobius_band(12, 2));
  for (const Stage stage : {Stage::subdivided, Stage::offset, Stage::subdivided_offset}) {
    INFO("stage " << int(stage));
    PipelineSettings s = full_options();
    s.stage = stage;
    Pipeline live;
    const Buffer<Vec3> made = live.run(band, s).positions();
    Buffer<Vec3> kept(made.size(), Vec3(7.0));
    REQUIRE(live.exchange_result_positions(kept));
    CHECK(kept == made);
    // Nothing changed, yet every stage makes its positions again (the result held the caller's array).
    const Mesh& again = live.run(band, s);
    CHECK(again.positions() == made);
    CHECK(live.work(Stage::subdivided) == StageWork::positions);
    // The stage after one whose result changed places reads that result's positions made again.
    if (stage == Stage::subdivided) {
      Buffer<Vec3> other(made.size(), Vec3(7.0));
      REQUIRE(live.exchange_result_positions(other));
      s.stage = Stage::subdivided_offset;
      Pipeline fresh;
      CHECK(live.run(band, s).positions() == fresh.run(band, s).positions());
    }
    Buffer<Vec3> wrong_size(made.size() + 1, Vec3(7.0));
    CHECK_FALSE(live.exchange_result_positions(wrong_size));
    CHECK(wrong_size == Buffer<Vec3>(made.size() + 1, Vec3(7.0)));
  }
  // The scene's and merge's meshes stay the pipeline's.
  for (const Stage stage : {Stage::scene, Stage::merged}) {
    PipelineSettings s = full_options();
    s.stage = stage;
    Pipeline live;
    Buffer<Vec3> kept(live.run(band, s).num_vertices(), Vec3(7.0));
    CHECK_FALSE(live.exchange_result_positions(kept));
    CHECK(kept == Buffer<Vec3>(band.num_vertices(), Vec3(7.0)));
  }
}

TEST_CASE("a later stage's result is lent out, copied back when taken up again, else made again",
          "[kernel]") {
  const Mesh band = build_mesh(test::mobius_band(12, 2));
  const Mesh band_moved = moved(band, 0.1);
  const Mesh other = build_mesh(test::mobius_band(14, 2));
  for (const Stage stage : {Stage::subdivided, Stage::offset, Stage::subdivided_offset}) {
    INFO("stage " << int(stage));
    PipelineSettings s = full_options();
    s.stage = stage;
    Pipeline fresh;
    const Mesh expected_moved = fresh.run(band_moved, s);
    for (const bool copies_back : {true, false}) {
      INFO("copies back " << copies_back);
      Pipeline live;
      const Buffer<Vec3> made = live.run(band, s).positions();
      Mesh lent;
      int copies = 0;
      std::function<Mesh()> copy_back;
      if (copies_back) copy_back = [&] { return ++copies, Mesh(lent); };
      REQUIRE(live.lend_result(lent, copy_back));
      CHECK(lent.positions() == made);
      CHECK(validate(lent).empty());
      // The report comes from the stages' inputs, which stay the pipeline's.
      test::check_same_report(live.result_report(), topology_report(lent));
      // Moved vertices flow into the copy; without one the stage makes its result again.
      const Mesh& again = live.run(band_moved, s);
      CHECK(again.positions() == expected_moved.positions());
      CHECK(again.corner_vertices() == expected_moved.corner_vertices());
      CHECK(live.work(stage) == (copies_back ? StageWork::positions : StageWork::rebuilt));
      CHECK(copies == (copies_back ? 1 : 0));
      CHECK(lent.positions() == made);  // the lent mesh is the caller's
      // A new topology makes the stage anew: the copy is never asked for.
      REQUIRE(live.lend_result(lent, copy_back));
      const int before = copies;
      Pipeline fresh_other;
      CHECK(live.run(other, s).positions() == fresh_other.run(other, s).positions());
      CHECK(copies == before);
    }
  }
  // The scene's and merge's meshes stay the pipeline's.
  for (const Stage stage : {Stage::scene, Stage::merged}) {
    PipelineSettings s = full_options();
    s.stage = stage;
    Pipeline live;
    live.run(band, s);
    Mesh lent;
    CHECK_FALSE(live.lend_result(lent, [] { return Mesh(); }));
    CHECK(lent.num_faces() == 0);
    CHECK(live.run(band, s).num_faces() == band.num_faces());
  }
}

TEST_CASE("the result's report, derived from a stage's input, is the one counted on the result", "[kernel]") {
  Mesh holed = build_mesh(test::torus(6, 4));
  holed.set_hole(3, true);
  std::vector<Mesh> meshes = {build_mesh(test::mobius_band(12, 2)), build_mesh(test::klein_bottle(8, 6)),
                              build_mesh(test::disjoint_union(test::tetrahedron(), test::mobius_band(7, 1)))};
  meshes.push_back(std::move(holed));
  for (const Mesh& mesh : meshes)
    for (const Stage stage : {Stage::scene, Stage::subdivided, Stage::offset, Stage::subdivided_offset})
      for (const BoundaryMode boundary : {BoundaryMode::edge_only, BoundaryMode::none}) {
        CAPTURE(mesh.num_faces(), int(stage), int(boundary));
        PipelineSettings s = full_options();
        s.stage = stage;
        s.boundary = boundary;
        Pipeline live;
        const Mesh& result = live.run(mesh, s);
        test::check_same_report(live.result_report(), topology_report(result));
      }
}

TEST_CASE("results lent out at several stages are taken back when their stage is shown again", "[kernel]") {
  const Mesh torus = build_mesh(test::torus(8, 6));
  PipelineSettings s = full_options();
  Pipeline live;
  // The caller lends every result it shows, as a viewer does: the offset's, then the subdivision's while
  // the offset is left out, then the offset's again (its own lent result, cached).
  std::vector<Mesh> shown;
  shown.reserve(8);
  int copies = 0;
  const auto show = [&](Stage stage) {
    s.stage = stage;
    const Mesh& result = live.run(torus, s);
    Pipeline fresh;
    const Mesh& expected = fresh.run(torus, s);
    CHECK(result.positions() == expected.positions());
    CHECK(result.corner_vertices() == expected.corner_vertices());
    shown.emplace_back();
    Mesh& lent = shown.back();
    if (live.lend_result(lent, [&lent, &copies] { return ++copies, Mesh(lent); }))
      CHECK(lent.num_faces() == expected.num_faces());
  };
  show(Stage::offset);
  show(Stage::subdivided);
  show(Stage::offset);
  CHECK(live.work(Stage::offset) == StageWork::cached);
  CHECK(copies == 2);  // the subdivision's, then the offset's: neither made again
  show(Stage::subdivided_offset);
  show(Stage::subdivided);
  show(Stage::subdivided_offset);
  CHECK(live.work(Stage::subdivided_offset) == StageWork::cached);
  // Another level count makes them anew: no copy is asked for.
  const int before = copies;
  s.subdivision_levels = 1;
  show(Stage::offset);
  CHECK(live.work(Stage::offset) == StageWork::rebuilt);
  CHECK(copies == before);
}
