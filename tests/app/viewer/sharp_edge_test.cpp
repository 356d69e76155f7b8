#include <catch2/catch.hpp>

#include <fstream>
#include <map>
#include <string>
#include <vector>

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

namespace {

using EdgeName = std::pair<std::string, std::string>;
using SharpWeights = std::map<EdgeName, float>;

EdgeName ordered(EdgeName e) {
  if (e.second < e.first) std::swap(e.first, e.second);
  return e;
}

// Three edges of the cube that clicks in edge mode pick, each with its pixel.
std::vector<std::pair<glm::dvec2, EdgeName>> clickable_edges(const Mesh& mesh) {
  const ScreenProjection projection = nome::test::viewer_projection(mesh, 30.0, 25.0);
  std::vector<std::pair<glm::dvec2, EdgeName>> found;
  for (Index e = 0; e < mesh.num_edges() && found.size() < 3; ++e) {
    const auto [u, w] = mesh.edge(e).vertices;
    if (const auto at = nome::test::edge_click(mesh, projection, e))
      found.push_back({*at, ordered({mesh.vertex_names()[u], mesh.vertex_names()[w]})});
  }
  REQUIRE(found.size() == 3);
  return found;
}

// The sharp edges a saved scene holds, by their vertex names.
SharpWeights saved_sharp(const std::string& path) {
  SharpWeights weights;
  const SceneDocument saved = SceneDocument::from_scene(read_scene(path));
  for (const NamedSharpEdge& e : saved.edits().sharp_edges()) weights[ordered({e.a, e.b})] = e.weight;
  return weights;
}

// Whether the texts occur in the log in this order.
bool logged_in_order(const std::string& log, const std::vector<std::string>& texts) {
  std::size_t at = 0;
  for (const std::string& text : texts) {
    at = log.find(text, at);
    if (at == std::string::npos) {
      UNSCOPED_INFO("not found in order: " << text);
      return false;
    }
    at += text.size();
  }
  return true;
}

}  // namespace

// K on several edges: every selected edge takes the Edit section's sharpness, unless every one has it
// already, when all become smooth; the message counts the edges that changed. Undo gives each edge its own
// weight from before, redo the one after. Each step is read back from the scene the script saves.
TEST_CASE("K on edges of mixed sharpness gives them all the sharpness unless all have it; undo each its own",
          "[app]") {
  const std::string dir = nome::test::private_scratch_dir("sharp_mixed");
  std::ofstream(dir + "/cube.nome") << edge_mode_cube_text;
  const auto edges = clickable_edges(glue_faces(read_scene(dir + "/cube.nome").combined_soup()).mesh);
  const EdgeName e1 = edges[0].second, e2 = edges[1].second, e3 = edges[2].second;
  auto clicks = [&](std::initializer_list<int> which) {
    std::string lines;
    for (int i : which) lines += click_line(edges[size_t(i)].first);
    return lines;
  };
  int saves = 0;
  auto save = [&] { return "save " + dir + "/s" + std::to_string(++saves) + ".nome\n"; };
  std::string script = "view 30 25\nmode edge\n";
  script += clicks({0}) + "key K\n" + save();                                 // s1: e1 alone, from smooth
  script += clicks({0, 1, 2}) + "key K\n" + save();                           // s2: one of three sharp
  script += clicks({0, 1}) + "key K\n" + save();                              // s3: both sharp: smooth
  script += "setting sharpness 2.5\n" + clicks({2, 0}) + "key K\n" + save();  // s4: sharp and smooth
  script += clicks({0, 1, 2}) + "key K\n" + save();                           // s5: two of three at 2.5
  script += "setting sharpness infinite\n" + clicks({0, 2}) + "key K\n" + save();  // s6: all 2.5
  script += "setting sharpness 2.5\n" + clicks({0, 1}) + "key K\n" + save();       // s7: infinite and 2.5
  script += clicks({0, 1}) + "key K\n" + save();                                   // s8: both at 2.5: smooth
  for (int undo = 0; undo < 3; ++undo) script += "key Ctrl+Z\n" + save();          // s9..s11
  script += "action redo\n" + save() + "quit\n";                                   // s12
  viewer::ViewerOptions options;
  options.file = dir + "/cube.nome";
  options.script = nome::test::write_script(dir, script);
  nome::test::TestViewer viewer(options);
  CHECK(viewer.run() == 0);
  const std::string log = viewer.messages();
  INFO(log);
  CHECK(logged_in_order(
      log, {"sharp: 1 edge marked sharp", "sharp: 2 edges marked sharp", "sharp: 2 edges marked smooth",
            "sharp: 2 edges given sharpness 2.5", "sharp: 1 edge given sharpness 2.5",
            "sharp: 2 edges marked sharp", "sharp: 1 edge given sharpness 2.5",
            "sharp: 2 edges marked smooth", "undone", "undone", "undone", "redone"}));
  const float infinite = infinite_sharpness;
  const SharpWeights s1{{e1, infinite}};
  const SharpWeights s2{{e1, infinite}, {e2, infinite}, {e3, infinite}};
  const SharpWeights s3{{e3, infinite}};
  const SharpWeights s4{{e1, 2.5f}, {e3, 2.5f}};
  const SharpWeights s5{{e1, 2.5f}, {e2, 2.5f}, {e3, 2.5f}};
  const SharpWeights s6{{e1, infinite}, {e2, 2.5f}, {e3, infinite}};
  const SharpWeights s7{{e1, 2.5f}, {e2, 2.5f}, {e3, infinite}};
  const SharpWeights s8{{e3, infinite}};
  const std::vector<SharpWeights> expected = {s1, s2, s3, s4, s5, s6, s7, s8, s7, s6, s5, s6};
  REQUIRE(saves == int(expected.size()));
  for (int i = 0; i < saves; ++i) {
    INFO("s" << i + 1);
    CHECK(saved_sharp(dir + "/s" + std::to_string(i + 1) + ".nome") == expected[size_t(i)]);
  }
  // The shown mesh after the redo: each edge with its weight, the others smooth.
  const Mesh& shown = *viewer.window().shown()->mesh;
  SharpWeights drawn;
  for (Index e = 0; e < shown.num_edges(); ++e)
    if (shown.edge_sharpness(e) > 0) {
      const auto [u, w] = shown.edge(e).vertices;
      drawn[ordered({shown.vertex_names()[u], shown.vertex_names()[w]})] = shown.edge_sharpness(e);
    }
  CHECK(drawn == s6);
}
