#include <catch2/catch.hpp>

#include "nome/edit/scene_document.hpp"
#include "nome/mesh/glue_faces.hpp"
#include "nome/mesh/topology_report.hpp"
#include "nome/ops/merge.hpp"
#include "scene/scene_support.hpp"
#include "support/funnel_cube_scene.hpp"

using namespace nome;

namespace {

// The four polygons the report adds below one corner (its funnel_cube_consolidated.nome).
const std::vector<std::vector<std::string>> corner = {{"fun3_hc3", "fun2_hc5", "fun2_hc6", "fun3_hc2"},
                                                      {"fun3_hc3", "fun5_hc3", "fun2_hc5"},
                                                      {"fun3_hc4", "fun5_hc2", "fun5_hc3", "fun3_hc3"},
                                                      {"fun5_hc3", "fun5_hc4", "fun2_hc4", "fun2_hc5"}};

void close_corner(SceneDocument& doc) {
  for (const auto& face : corner) {
    std::vector<std::string> full;
    for (const std::string& name : face) full.push_back(doc.scene()->resolve_vertex_name(name));
    const EditOutcome added = doc.edits().add_polygon(full);
    INFO(added.message);
    REQUIRE(added.applied);
  }
  REQUIRE(doc.edits().accept_temporary().applied);
}

}  // namespace

TEST_CASE("funnel_cube_consolidated.nome: its top-level instances merge into one orientable surface",
          "[scene]") {
  const scene::Scene s = test::load_scene_file(test::assets_dir() + "funnel_cube_consolidated.nome");
  std::vector<Mesh> instances;
  for (const scene::SceneInstance& instance : s.instances())
    instances.push_back(build_mesh(instance.geometry.soup));
  REQUIRE(instances.size() == 9);  // the six funnels' group and the eight corner patches
  const MergeResult merged = merge_meshes(instances);
  CHECK(merged.skipped.empty());
  const TopologyReport r = topology_report(merged.mesh);
  CHECK(r.vertices == 96);
  CHECK(r.edges == 180);
  CHECK(r.faces == 80);
  CHECK(r.chi == -4);
  CHECK(r.orientable);
  CHECK(r.borders == 6);
  CHECK(r.components.size() == 1);
  // Each patch has 9 border edges; they and the funnels' 6 x 8 inner rim edges all pair up.
  CHECK(merged.glued_edges == (8 * 9 + 6 * 8) / 2);
}

TEST_CASE("the report's corner polygons, accepted and merged, join three funnels into one surface",
          "[scene]") {
  SceneDocument doc =
      SceneDocument::from_scene(scene::Scene::from_text(test::funnel_cube_scene, "cube.nome"));
  close_corner(doc);
  const MergeResult merged = merge_boundaries(glue_faces(doc.pipeline_input().soup).mesh);
  CHECK(merged.skipped.empty());
  const TopologyReport r = topology_report(merged.mesh);
  CHECK(r.components.size() == 4);  // the corner's three funnels as one, the other three apart
  CHECK(r.orientable);
  CHECK(r.mobius_edges == 0);
  CHECK(r.faces == 48 + 4);
}

TEST_CASE("the consolidated mesh is saved into the scene and read back", "[scene]") {
  SceneDocument doc =
      SceneDocument::from_scene(scene::Scene::from_text(test::funnel_cube_scene, "cube.nome"));
  close_corner(doc);
  REQUIRE(doc.edits().delete_faces({doc.edits().scene_geometry().face_names[0]}).applied);
  const std::string text = doc.saved_text();
  const SceneDocument reread = SceneDocument::from_scene(scene::Scene::from_text(text, "saved.nome"));
  CHECK(reread.edits().consolidated_faces().size() == 4);
  CHECK(reread.edits().deleted_faces() == doc.edits().deleted_faces());
  const TopologyReport before =
      topology_report(merge_boundaries(glue_faces(doc.pipeline_input().soup).mesh).mesh);
  const TopologyReport after =
      topology_report(merge_boundaries(glue_faces(reread.pipeline_input().soup).mesh).mesh);
  CHECK(after.vertices == before.vertices);
  CHECK(after.edges == before.edges);
  CHECK(after.faces == before.faces);
  CHECK(after.components.size() == before.components.size());
}

TEST_CASE("lowering a slider hides the edits on vanished vertices, raising it brings them back", "[scene]") {
  SceneDocument doc =
      SceneDocument::from_scene(scene::Scene::from_text(test::funnel_cube_scene, "cube.nome"));
  close_corner(doc);
  const auto n = doc.scene()->find_parameter("fp_n");
  REQUIRE(n);
  doc.set_parameter(*n, 5);  // hc5 and hc6 are gone
  const std::vector<UnresolvedEdit> gone = doc.edits().unresolved();
  CHECK(gone.size() == 3);  // the faces through fun2_hc5 or fun2_hc6
  std::vector<std::string> left_out;
  const scene::SceneEdits saved = doc.saved_edits(&left_out);
  CHECK(left_out.size() == 3);
  CHECK(saved.consolidated.size() == 1);

  doc.set_parameter(*n, 8);
  CHECK(doc.edits().unresolved().empty());
  CHECK(glue_faces(doc.edits().consolidated_soup()).mesh.num_faces() == 4);
}
