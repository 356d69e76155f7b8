#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <regex>

#include "app/viewer_support.hpp"
#include "nome/io/ply.hpp"
#include "nome/io/read_scene.hpp"
#include "nome/mesh/color_attribute.hpp"
#include "nome/mesh/glue_faces.hpp"
#include "nome/mesh/input_faces.hpp"
#include "nome/ops/pipeline.hpp"
#include "support/mesh_measures.hpp"
#include "support/placed_scene.hpp"
#include "viewer/tools/text_pane_tool.hpp"
#include "viewer/window.hpp"

using namespace nome;

// The scene text pane in scripted sessions (in this process, null renderer): what a user types, applies,
// clicks and saves.
namespace {

using nome::test::placed_scene;

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

void write(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

std::string read(const std::string& path) {
  return read_text_file(path);
}

// The text pane's part of each `state` line.
std::vector<std::string> text_states(const std::string& log) {
  static const std::regex part("\\| (text: [^\\n]*)");
  std::vector<std::string> out;
  for (auto it = std::sregex_iterator(log.begin(), log.end(), part); it != std::sregex_iterator(); ++it)
    out.push_back((*it)[1].str());
  return out;
}

}  // namespace

TEST_CASE("an edit in the text pane that breaks the file keeps the geometry and marks its line:col",
          "[app]") {
  const std::string dir = test::private_scratch_dir("viewer_text_broken");
  write(dir + "/s.nome", placed_scene);
  // Line 7's third vertex becomes an unknown name at column 16.
  write(dir + "/broken.nome", replaced(placed_scene, "(a c d) endface", "(a c q) endface"));
  const std::string script =
      test::write_script(dir, "state\nkey Ctrl+T\ntext-set " + dir +
                                  "/broken.nome\naction apply-text\nstate\nlog-click 3\nstate\nquit\n");
  const auto r = test::run_window(dir + "/s.nome --script " + script);
  INFO(r.err);
  // The refused apply fails its script line; everything after it still ran.
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("s.nome:7:16: "));
  const auto states = test::logged_states(r.err);
  REQUIRE(states.size() == 3);
  CHECK(states[1].vertices == states[0].vertices);
  CHECK(states[1].edges == states[0].edges);
  CHECK(states[1].faces == states[0].faces);
  const auto texts = text_states(r.err);
  REQUIRE(texts.size() == 3);
  CHECK_THAT(texts[0], Catch::StartsWith("text: hidden, 12 lines, cursor 1:1, error none"));
  CHECK_THAT(texts[1], Catch::StartsWith("text: shown, 12 lines, cursor 1:1, error 7:16"));
  CHECK_THAT(texts[1], Catch::EndsWith("modified"));
  // The click on the error in the log put the cursor on it.
  CHECK_THAT(texts[2], Catch::Contains("cursor 7:16, error 7:16"));
  // Nothing was written: the file is as it was.
  CHECK(read(dir + "/s.nome") == placed_scene);
}

TEST_CASE("a face or vertex selected in the view maps to the line of its statement", "[app]") {
  const std::string dir = test::private_scratch_dir("viewer_text_statement");
  write(dir + "/s.nome", placed_scene);
  const Mesh mesh = glue_faces(read_scene(dir + "/s.nome").combined_soup()).mesh;
  const auto projection = test::viewer_projection(mesh, 30.0, 25.0);
  // A pixel on the triangle of i2 (faces up and down coincide there: a click picks either) and one on a
  // funnel face.
  std::optional<glm::dvec2> up, funnel;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const std::string& name = mesh.face_names()[f];
    if (name.rfind("i1_", 0) == 0 && !funnel) funnel = test::face_click(mesh, projection, f);
    if (name != "i2_up") continue;
    Vec3 centre(0.0);
    for (Index v : mesh.face_vertices(f)) centre += mesh.position(v) / 3.0;
    const glm::dvec2 at = glm::floor(*test::pixel_of(projection, centre));
    std::vector<std::string> seen;
    for (const glm::dvec2 s : {at, at + glm::dvec2(1.0), at + glm::dvec2(0.5)})
      for (Index g : test::faces_seen_at(mesh, projection, s)) seen.push_back(mesh.face_names()[g]);
    if (std::all_of(seen.begin(), seen.end(), [](const std::string& n) { return n.rfind("i2_", 0) == 0; }))
      up = at;
  }
  REQUIRE(up);
  REQUIRE(funnel);
  // A vertex of the mesh's faces: its first face's statement.
  std::optional<glm::dvec2> point;
  for (Index v = 0; v < mesh.num_vertices() && !point; ++v)
    if (mesh.vertex_names()[v].rfind("i2_", 0) == 0) point = test::vertex_click(mesh, projection, v);
  REQUIRE(point);
  const std::string script = test::write_script(
      dir, "view 30 25\nmode face\n" + test::click_line(*up) + "state\naction clear-selection\n" +
               test::click_line(*funnel) + "state\naction clear-selection\nmode vertex\n" +
               test::click_line(*point) + "state\nquit\n");
  const auto r = test::run_window(dir + "/s.nome --script " + script);
  INFO(r.err);
  REQUIRE(r.status == 0);
  const bool is_up = r.err.find("face i2_up selected") != std::string::npos;
  CHECK((is_up || r.err.find("face i2_down selected") != std::string::npos));
  const auto texts = text_states(r.err);
  REQUIRE(texts.size() == 3);
  CHECK_THAT(texts[0], Catch::Contains(is_up ? "statement line 7" : "statement line 8"));
  CHECK_THAT(texts[1], Catch::Contains("statement line 2"));
  CHECK_THAT(texts[2], Catch::Contains("statement line 7"));
}

TEST_CASE("a face picked on the smoothed solid maps to the line of the statement it came from", "[app]") {
  const std::string dir = test::private_scratch_dir("viewer_text_solid_statement");
  const std::string scene =
      "funnel fu (4 1 0.5 1) endfunnel\n"
      "point a (3 0 0) endpoint\n"
      "point b (5 0 0) endpoint\n"
      "point c (5 2 0) endpoint\n"
      "point d (3 2 0) endpoint\n"
      "mesh m\n"
      "  face q (a b c d) endface\n"
      "endmesh\n"
      "instance i1 fu endinstance\n"
      "instance i2 m endinstance\n";
  write(dir + "/s.nome", scene);
  // The solid the viewer shows after `subdiv 1` and `offset 0.1`: a face made from a funnel face and one
  // made from the quad, each where a click shows it.
  PolygonSoup soup = read_scene(dir + "/s.nome").combined_soup();
  REQUIRE(soup.num_faces() == 5);
  mark_input_faces(soup);
  Pipeline pipeline;
  pipeline.set_input({soup, {}, Joining::across_edges});
  PipelineSettings settings;
  settings.subdivision_levels = 1;
  settings.offset_distance = 0.1;
  settings.stage = Stage::offset;
  const Mesh solid = pipeline.run(settings);
  const auto projection = test::viewer_projection(solid, 20.0, 60.0);
  std::optional<glm::dvec2> on_funnel, on_quad;
  for (Index f = 0; f < solid.num_faces(); ++f) {
    const Index input = *input_face(solid, f);
    std::optional<glm::dvec2>& click = input == 4 ? on_quad : on_funnel;
    if (!click) click = test::face_click(solid, projection, f);
  }
  REQUIRE(on_funnel);
  REQUIRE(on_quad);
  const std::string script = test::write_script(
      dir, "subdiv 1\noffset 0.1\nview 20 60\nmode face\n" + test::click_line(*on_funnel) +
               "state\naction clear-selection\n" + test::click_line(*on_quad) +
               "state\naction clear-selection\nmode instance\n" + test::click_line(*on_funnel) +
               "color 1 0 0\nexport " + dir + "/solid.ply\nquit\n");
  const auto r = test::run_window(dir + "/s.nome --script " + script);
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto texts = text_states(r.err);
  REQUIRE(texts.size() == 2);
  CHECK_THAT(texts[0], Catch::Contains("statement line 1"));
  CHECK_THAT(texts[1], Catch::Contains("statement line 7"));
  CHECK_THAT(r.err, Catch::Contains("offset stage"));
  // Instance mode finds the instance from a face of the solid too; its colour reaches the solid's faces.
  CHECK_THAT(r.err, Catch::Contains("instance i1 selected"));
  const PolygonSoup exported = read_ply(dir + "/solid.ply");
  REQUIRE(exported.num_faces() == solid.num_faces());
  const Column<Color>* colors = exported.face_attributes.find<Color>(color_attribute);
  REQUIRE(colors);
  int red = 0;
  for (Index f = 0; f < exported.num_faces(); ++f) {
    const bool is_funnel = test::face_centre(exported, f).x < 2.5;
    CHECK(((*colors)[f] == Color(1.0f, 0.0f, 0.0f)) == is_funnel);
    red += is_funnel ? 1 : 0;
  }
  CHECK(red > 0);
}

TEST_CASE("applying a good edit changes the geometry, and saving writes the text without a reload", "[app]") {
  const std::string dir = test::private_scratch_dir("viewer_text_apply");
  write(dir + "/s.nome", placed_scene);
  const std::string good = placed_scene + "instance i3 m translate (0 0 2) endinstance\n";
  write(dir + "/good.nome", good);
  const std::string script = test::write_script(
      dir, "state\ntext-set " + dir + "/good.nome\naction apply-text\nstate\naction save-text\nstate\n");
  viewer::ViewerOptions options;
  options.file = dir + "/s.nome";
  options.script = script;
  test::TestViewer viewer(options);
  // Long enough for the script and for the file watcher to look twice after the save.
  for (int i = 0; i < 240; ++i) viewer.frame();
  const std::string log = viewer.messages();
  INFO(log);
  CHECK(viewer.window().exit_status() == 0);
  const auto states = test::logged_states(log);
  REQUIRE(states.size() == 3);
  CHECK(states[1].faces == states[0].faces + 2);
  CHECK(states[2].faces == states[1].faces);
  const auto texts = text_states(log);
  REQUIRE(texts.size() == 3);
  CHECK_THAT(texts[1], Catch::EndsWith("modified"));
  CHECK_THAT(texts[2], Catch::EndsWith("saved"));
  // The file holds the text byte for byte, and the write left no temporary file beside it.
  CHECK(read(dir + "/s.nome") == good);
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    CHECK(entry.path().extension() != ".tmp");
  // The watcher took the save for the pane's own: no reload over the user's state.
  CHECK_THAT(log, !Catch::Contains("reloaded"));
  CHECK(viewer.window().find_tool<viewer::TextPaneTool>()->pane().text() == good);
  CHECK_FALSE(viewer.window().find_tool<viewer::TextPaneTool>()->pane().is_modified());
}

TEST_CASE("a change on disk reaches a clean pane, and a modified pane keeps the user's text", "[app]") {
  const std::string dir = test::private_scratch_dir("viewer_text_disk");
  const std::string mine = placed_scene + "# mine\n", theirs = placed_scene + "# theirs\n";
  write(dir + "/mine.nome", mine);
  const auto touch = [&](test::TestViewer& viewer, const std::string& text) {
    write(dir + "/s.nome", text);
    // Another program's write, at a time the watcher has not seen.
    const auto path = std::filesystem::path(dir + "/s.nome");
    std::filesystem::last_write_time(path, std::filesystem::last_write_time(path) + std::chrono::seconds(2));
    for (int i = 0; i < 60; ++i) viewer.frame();
  };
  for (const bool is_modified : {false, true}) {
    write(dir + "/s.nome", placed_scene);
    viewer::ViewerOptions options;
    options.file = dir + "/s.nome";
    if (is_modified) options.script = test::write_script(dir, "text-set " + dir + "/mine.nome\n");
    test::TestViewer viewer(options);
    for (int i = 0; i < 10; ++i) viewer.frame();
    const viewer::TextPane& pane = viewer.window().find_tool<viewer::TextPaneTool>()->pane();
    REQUIRE(pane.text() == (is_modified ? mine : placed_scene));
    touch(viewer, theirs);
    INFO(viewer.messages());
    CHECK_THAT(viewer.messages(), Catch::Contains("reloaded s.nome"));
    CHECK(pane.text() == (is_modified ? mine : theirs));
    CHECK(pane.is_changed_on_disk() == is_modified);
    CHECK(pane.is_modified() == is_modified);
  }
}
