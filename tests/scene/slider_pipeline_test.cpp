#include <catch2/catch.hpp>

#include "nome/edit/scene_document.hpp"
#include "nome/mesh/topology_report.hpp"
#include "nome/ops/pipeline.hpp"
#include "scene/scene_support.hpp"

using namespace nome;

namespace {

// The viewer's solid stage over the report's consolidated funnel cube: merged, subdivided, thickened.
PipelineSettings solid_settings() {
  PipelineSettings s;
  s.stage = Stage::subdivided_offset;
  s.should_merge = true;
  s.subdivision_levels = 2;
  s.offset_distance = 0.03;
  s.subdivision_after = 1;
  return s;
}

SceneDocument funnel_cube_document() {
  return SceneDocument::from_scene(
      test::load_scene_file(test::assets_dir() + "funnel_cube_consolidated.nome"));
}

// One slider tick as the viewer makes it: the document moves the slider, the pipeline takes its input.
const Mesh& tick(SceneDocument& doc, Pipeline& pipeline, const std::string& slider, double value) {
  doc.set_parameter(slider, value);
  pipeline.set_input(doc.pipeline_input());
  return pipeline.run(solid_settings());
}

}  // namespace

TEST_CASE("a slider tick that moves vertices builds no mesh, from the scene to the solid", "[scene]") {
  SceneDocument doc = funnel_cube_document();
  Pipeline pipeline;
  pipeline.set_input(doc.pipeline_input());
  pipeline.run(solid_settings());
  for (const double height : {0.35, 0.4, 0.3}) {
    const std::uint64_t before = build_mesh_count();
    const Mesh& solid = tick(doc, pipeline, "fp_h", height);
    CHECK(build_mesh_count() == before);
    for (const Stage stage :
         {Stage::scene, Stage::merged, Stage::subdivided, Stage::offset, Stage::subdivided_offset})
      CHECK(pipeline.work(stage) == StageWork::positions);
    // The fast path gives what a fresh pipeline gives, bit for bit.
    Pipeline fresh;
    fresh.set_input(doc.pipeline_input());
    CHECK(solid.positions() == fresh.run(solid_settings()).positions());
    CHECK(topology_report(solid).borders == 0);
  }
}

TEST_CASE("the document's topology version stays while a slider moves vertices, faces named by the user too",
          "[scene]") {
  SceneDocument doc = funnel_cube_document();  // its saved faces name the funnels' vertices
  const std::uint64_t first = doc.input_topology_version();
  const Index faces = doc.pipeline_input().soup.num_faces();
  const std::size_t evaluations = doc.scene()->placement_evaluations();
  doc.set_parameter("fp_h", 0.4);
  CHECK(doc.scene()->last_change_moved_vertices_only());
  // The six funnels are made again (a funnel has no positions of its own); the saved faces' copies of
  // their vertices only move.
  CHECK(doc.scene()->placement_evaluations() - evaluations == 6);
  CHECK(doc.input_topology_version() == first);
  CHECK(doc.pipeline_positions() == doc.pipeline_input().soup.positions);
  // The same positions as the scene read at that height.
  std::string text = test::read_text(test::assets_dir() + "funnel_cube_consolidated.nome");
  const std::string height = "set      h       0.3";
  REQUIRE(text.find(height) != std::string::npos);
  text.replace(text.find(height), height.size(), "set      h       0.4");
  const SceneDocument read_at_height =
      SceneDocument::from_scene(scene::Scene::from_text(text, "funnel_cube_consolidated.nome"));
  CHECK(read_at_height.pipeline_input().soup.positions == doc.pipeline_input().soup.positions);
  doc.set_parameter("fp_n", 7);
  CHECK_FALSE(doc.scene()->last_change_moved_vertices_only());
  CHECK(doc.input_topology_version() != first);
  CHECK(doc.pipeline_input().soup.num_faces() != faces);
}

TEST_CASE("a slider tick that changes the topology builds the scene mesh and the merged mesh once",
          "[scene]") {
  SceneDocument doc = funnel_cube_document();
  Pipeline pipeline;
  pipeline.set_input(doc.pipeline_input());
  const Index faces_at_8 = pipeline.run(solid_settings()).num_faces();
  const std::uint64_t before = build_mesh_count();
  const Index faces_at_7 = tick(doc, pipeline, "fp_n", 7).num_faces();
  CHECK(build_mesh_count() - before == 2);
  CHECK(pipeline.work(Stage::scene) == StageWork::rebuilt);
  CHECK(pipeline.work(Stage::subdivided_offset) == StageWork::rebuilt);
  CHECK(faces_at_7 != faces_at_8);
}

TEST_CASE("a slider that moves a sweep's path moves the document's vertices and builds no mesh", "[scene]") {
  const auto text = [](double lift) {
    return "bank b set lift " + std::to_string(lift) +
           " -1 1 0.1 endbank\n"
           "point s1 (0.5 0.5 0) endpoint\npoint s2 (-0.5 0.5 0) endpoint\npoint s3 (-0.5 -0.5 0) endpoint\n"
           "point s4 (0.5 -0.5 0) endpoint\npolyline sq (s1 s2 s3 s4) isloop endpolyline\n"
           "point k0 (3 0 {expr $b_lift}) endpoint\npoint k1 (0 3 0) endpoint\npoint k2 (-3 0 0) endpoint\n"
           "point k3 (0 -3 0) endpoint\nbspline pa order 3 (k0 k1 k2 k3 k0 k1) segs 30 endbspline\n"
           "sweep s crosssection sq endcrosssection path pa endpath endsweep\ninstance i s endinstance\n";
  };
  SceneDocument doc = SceneDocument::from_scene(scene::Scene::from_text(text(0), "t.nome"));
  Pipeline pipeline;
  pipeline.set_input(doc.pipeline_input());
  pipeline.run(solid_settings());
  const std::uint64_t before = build_mesh_count();
  const Mesh& solid = tick(doc, pipeline, "b_lift", 0.4);
  CHECK(doc.scene()->last_change_moved_vertices_only());
  CHECK(build_mesh_count() == before);
  CHECK(pipeline.work(Stage::scene) == StageWork::positions);
  const SceneDocument fresh_doc = SceneDocument::from_scene(scene::Scene::from_text(text(0.4), "t.nome"));
  Pipeline fresh;
  fresh.set_input(fresh_doc.pipeline_input());
  CHECK(solid.positions() == fresh.run(solid_settings()).positions());
}
