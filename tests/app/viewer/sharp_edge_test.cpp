#include <catch2/catch.hpp>

#include <fstream>

#include "app/viewer_support.hpp"
#include "nome/edit/scene_document.hpp"
#include "nome/io/read_scene.hpp"
#include "nome/mesh/glue_faces.hpp"
#include "nome/ops/pipeline.hpp"
#include "viewer/window.hpp"

using nome::test::click_line;

using namespace nome;

namespace {

const char* const edge_mode_cube_text =
    "point a (0 0 0) endpoint point b (1 0 0) endpoint point c (1 1 0) endpoint point d (0 1 0) endpoint\n"
    "point e (0 0 1) endpoint point f (1 0 1) endpoint point g (1 1 1) endpoint point h (0 1 1) endpoint\n"
    "mesh box\n"
    "  face bottom (a d c b) endface face top (e f g h) endface face front (a b f e) endface\n"
    "  face back (c d h g) endface face left (a e h d) endface face right (b c g f) endface\n"
    "endmesh\n"
    "instance k box endinstance\n";

// A window pixel where a click in edge mode picks an edge, and that edge's vertex names.
std::pair<glm::dvec2, std::pair<std::string, std::string>> clickable_edge(const Mesh& mesh) {
  const ScreenProjection projection = nome::test::viewer_projection(mesh, 30.0, 25.0);
  for (Index e = 0; e < mesh.num_edges(); ++e) {
    const auto [u, w] = mesh.edge(e).vertices;
    if (const auto at = nome::test::edge_click(mesh, projection, e))
      return {*at, {mesh.vertex_names()[u], mesh.vertex_names()[w]}};
  }
  FAIL("no edge of the cube can be clicked");
  return {};
}

Buffer<Vec3> edge_mode_subdivided(const SceneDocument& doc, int levels = 1) {
  Pipeline pipeline;
  pipeline.set_input(doc.pipeline_input());
  PipelineSettings s;
  s.stage = Stage::subdivided;
  s.subdivision_levels = levels;
  return pipeline.run(s).positions();
}

// Writes the edge-mode cube as dir/cube.nome and returns one of its edges that a click selects.
std::pair<glm::dvec2, std::pair<std::string, std::string>> write_edge_mode_cube(const std::string& dir) {
  std::ofstream(dir + "/cube.nome") << edge_mode_cube_text;
  return clickable_edge(glue_faces(read_scene(dir + "/cube.nome").combined_soup()).mesh);
}

}  // namespace

TEST_CASE(
    "an edge clicked in edge mode and marked sharp with K is drawn, saved, read back and creases "
    "the subdivision",
    "[app]") {
  const std::string dir = nome::test::private_scratch_dir("sharp_edge");
  const auto [pixel, names] = write_edge_mode_cube(dir);
  viewer::ViewerOptions options;
  options.file = dir + "/cube.nome";
  options.script = nome::test::write_script(
      dir, "view 30 25\nmode edge\n" + click_line(pixel) + "key K\nsave " + dir + "/sharp.nome\nquit\n");
  nome::test::TestViewer viewer(options);
  CHECK(viewer.run() == 0);
  const std::string log = viewer.messages();
  CHECK_THAT(log, Catch::Contains("edge (" + names.first + ", " + names.second + ") selected"));
  CHECK_THAT(log, Catch::Contains("sharp: 1 edge marked sharp"));
  // The shown mesh has the edge sharp (the overlay draws the shown mesh's sharp edges).
  const Mesh& shown = *viewer.window().shown()->mesh;
  Index sharp = 0;
  for (const Edge& e : shown.edges()) sharp += e.is_sharp ? 1 : 0;
  CHECK(sharp == 1);

  const SceneDocument back = SceneDocument::from_scene(read_scene(dir + "/sharp.nome"));
  auto edge = names;
  if (edge.second < edge.first) std::swap(edge.first, edge.second);
  CHECK(back.edits().sharp_edges() == std::vector<NamedSharpEdge>{{edge.first, edge.second}});
  const SceneDocument plain = SceneDocument::from_scene(read_scene(dir + "/cube.nome"));
  CHECK(edge_mode_subdivided(back) != edge_mode_subdivided(plain));
}

TEST_CASE(
    "K gives an edge the Edit section's sharpness, undo gives back the weight before, and the saved "
    "weight subdivides as the text's sharp",
    "[app]") {
  const std::string dir = nome::test::private_scratch_dir("sharp_weight");
  const auto [pixel, names] = write_edge_mode_cube(dir);
  viewer::ViewerOptions options;
  options.file = dir + "/cube.nome";
  options.script = nome::test::write_script(
      dir, "view 30 25\nmode edge\n" + click_line(pixel) + "setting sharpness 2.5\nkey K\nmode edge\n" +
               click_line(pixel) + "setting sharpness 1\nkey K\nkey Ctrl+Z\nsave " + dir +
               "/weighted.nome\nquit\n");
  nome::test::TestViewer viewer(options);
  CHECK(viewer.run() == 0);
  const std::string log = viewer.messages();
  CHECK_THAT(log, Catch::Contains("sharp: 1 edge given sharpness 2.5"));
  CHECK_THAT(log,
             Catch::Contains("edge (" + names.first + ", " + names.second + "), sharpness 2.5, selected"));
  CHECK_THAT(log, Catch::Contains("sharp: 1 edge given sharpness 1"));
  // After the undo the shown mesh has the edge at 2.5 again.
  const Mesh& shown = *viewer.window().shown()->mesh;
  std::vector<float> weights;
  for (Index e = 0; e < shown.num_edges(); ++e)
    if (shown.edge_sharpness(e) > 0) weights.push_back(shown.edge_sharpness(e));
  CHECK(weights == std::vector<float>{2.5f});

  // The same edge made sharp 2.5 in the text (the mesh's vertices are the instance's without `k_`).
  std::string text = edge_mode_cube_text;
  text.replace(text.find("endmesh"), 0,
               "  sharp 2.5 (" + names.first.substr(2) + " " + names.second.substr(2) + ") endsharp\n");
  const SceneDocument back = SceneDocument::from_scene(read_scene(dir + "/weighted.nome"));
  const SceneDocument in_text = SceneDocument::from_scene(scene::Scene::from_text(text, "t.nome"));
  CHECK(edge_mode_subdivided(back, 3) == edge_mode_subdivided(in_text, 3));
}
