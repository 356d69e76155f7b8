// Sculpting by hand in the viewer: G and the handle drag the selection; the scene's text or sliders follow.
#include <catch2/catch.hpp>

#include <fstream>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "app/viewer_support.hpp"
#include "nome/io/read_scene.hpp"
#include "viewer/tools/move_tool.hpp"
#include "viewer/tools/text_pane_tool.hpp"
#include "viewer/window.hpp"

using namespace nome;
using nome::test::assets;
using nome::viewer::InputFrame;
using nome::viewer::KeyModifier;

namespace {

InputFrame at(glm::dvec2 cursor) {
  InputFrame input;
  input.cursor = cursor;
  return input;
}

void click(test::TestViewer& viewer, glm::dvec2 pixel, int button = 0) {
  InputFrame press = at(pixel);
  press.is_pressed[button] = press.is_down[button] = true;
  viewer.frame(press);
  viewer.frame(at(pixel));
}

void press_key(test::TestViewer& viewer, glm::dvec2 cursor, int key,
               KeyModifier modifiers = KeyModifier::none) {
  InputFrame input = at(cursor);
  input.keys.push_back({key, modifiers});
  viewer.frame(input);
}

glm::dvec2 select_vertex(test::TestViewer& viewer, const std::string& name);

// A copy of the hand-made Moebius band (saving must not touch the project's file), open in a viewer.
struct SculptedBand {
  std::string path;
  std::string text;
  test::TestViewer viewer;

  explicit SculptedBand(const std::string& folder)
      : path(test::private_scratch_dir(folder) + "/hand_made_mobius_band.nome"),
        text(read_text_file(assets + "hand_made_mobius_band.nome")),
        viewer(options(path, text)) {
    REQUIRE(viewer.window().shown());
  }
  static viewer::ViewerOptions options(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
    viewer::ViewerOptions options;
    options.file = path;
    return options;
  }
};

// Selects the vertex of that name by a click where the screen oracle sees it.
glm::dvec2 select_vertex(test::TestViewer& viewer, const std::string& name) {
  const Mesh& mesh = *viewer.window().shown()->mesh;
  const auto projection = test::viewer_projection(mesh, 30.0, 25.0);
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    if (mesh.vertex_names()[v] != name) continue;
    const auto pixel = test::vertex_click(mesh, projection, v);
    REQUIRE(pixel);
    click(viewer, *pixel);
    REQUIRE(viewer.window().selection().vertices() == std::vector<Index>{v});
    return *pixel;
  }
  FAIL("no vertex " << name);
  return {};
}

const std::string& scene_text(test::TestViewer& viewer) {
  return viewer.window().sessions().scene_text();
}

Vec3 position(test::TestViewer& viewer, const std::string& name) {
  const scene::Scene* scene = viewer.window().sessions().scene();
  return scene->position(*scene->find_placed_vertex(name));
}

std::string with(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

void run_script(test::TestViewer& viewer, const std::string& script) {
  viewer.window().run_script(script, "test");
  for (int i = 0; i < 600 && viewer.window().is_running_script(); ++i) viewer.frame();
  viewer.frame();
}

}  // namespace

TEST_CASE("G, Z and a typed distance move a point's three numbers and nothing else; undo and redo", "[app]") {
  SculptedBand band("move_typed");
  const SculptedBand& file = band;
  test::TestViewer& viewer = band.viewer;
  const glm::dvec2 pixel = select_vertex(viewer, "m_o2");
  const Vec3 before = position(viewer, "m_o2");

  press_key(viewer, pixel, GLFW_KEY_G);
  const auto* tool = viewer.window().find_tool<viewer::MoveTool>();
  REQUIRE(tool->is_dragging());
  press_key(viewer, pixel, GLFW_KEY_Z);
  for (const int key : {GLFW_KEY_0, GLFW_KEY_PERIOD, GLFW_KEY_5}) press_key(viewer, pixel, key);
  CHECK(tool->offset() == Vec3(0, 0, 0.5));
  // The status bar says how far, and what the drag changes.
  CHECK_THAT(viewer.messages(), Catch::Contains("drag: the numbers of point 'o2'"));
  press_key(viewer, pixel, GLFW_KEY_ENTER);
  REQUIRE_FALSE(tool->is_dragging());

  const std::string moved = with(file.text, "point o2 (0.000 1.783 0.283)", "point o2 (0.000 1.783 0.783)");
  CHECK(scene_text(viewer) == moved);
  CHECK(viewer.window().find_tool<viewer::TextPaneTool>()->pane().text() == moved);
  CHECK(glm::distance(position(viewer, "m_o2"), before + Vec3(0, 0, 0.5)) < 1e-12);
  // The band keeps its faces: the selection stays, and it is still one-sided.
  CHECK(viewer.window().selection().vertices().size() == 1);

  press_key(viewer, pixel, GLFW_KEY_Z, KeyModifier::control);
  CHECK(scene_text(viewer) == file.text);
  CHECK(position(viewer, "m_o2") == before);
  press_key(viewer, pixel, GLFW_KEY_Y, KeyModifier::control);
  CHECK(scene_text(viewer) == moved);

  SECTION("the text pane's Save writes the moved text as it is; the file reads back moved") {
    run_script(viewer, "action save-text\n");
    CHECK(read_text_file(file.path) == moved);
    const scene::Scene saved = read_scene(file.path);
    CHECK(glm::distance(saved.position(*saved.find_placed_vertex("m_o2")), before + Vec3(0, 0, 0.5)) < 1e-12);
  }
  SECTION("Esc and a right click cancel a drag: the text is back as it was") {
    press_key(viewer, pixel, GLFW_KEY_G);
    for (const int key : {GLFW_KEY_X, GLFW_KEY_2}) press_key(viewer, pixel, key);
    CHECK(scene_text(viewer) != moved);
    press_key(viewer, pixel, GLFW_KEY_ESCAPE);
    CHECK(scene_text(viewer) == moved);
    press_key(viewer, pixel, GLFW_KEY_G);
    press_key(viewer, pixel, GLFW_KEY_1);
    click(viewer, pixel, 1);
    CHECK_FALSE(tool->is_dragging());
    CHECK(scene_text(viewer) == moved);
    CHECK(viewer.window().selection().vertices().size() == 1);  // the right click only cancelled
  }
}

TEST_CASE("a press on the handle's arrow drags along that axis until the release; Ctrl snaps", "[app]") {
  SculptedBand band("move_handle");
  test::TestViewer& viewer = band.viewer;
  select_vertex(viewer, "m_i4");
  const Vec3 before = position(viewer, "m_i4");
  const auto projection = test::viewer_projection(*viewer.window().shown()->mesh, 30.0, 25.0);
  const glm::dvec2 centre = *test::pixel_of(projection, before);
  // The Y arrow points up the screen from the vertex; its middle is 40 pixels along it.
  const glm::dvec2 up = glm::normalize(*test::pixel_of(projection, before + Vec3(0, 0.01, 0)) - centre);
  const glm::dvec2 grip = centre + 40.0 * up;
  InputFrame press = at(grip);
  press.is_pressed[0] = press.is_down[0] = true;
  viewer.frame(press);
  const auto* tool = viewer.window().find_tool<viewer::MoveTool>();
  REQUIRE(tool->is_dragging());
  const glm::dvec2 to = grip + 60.0 * up + glm::dvec2(25.0, 0.0);
  InputFrame hold = at(to);
  hold.is_down[0] = true;
  hold.held = KeyModifier::control;
  viewer.frame(hold);
  const Vec3 offset = tool->offset();
  CHECK(offset.x == 0.0);
  CHECK(offset.z == 0.0);
  CHECK(offset.y > 0.1);
  // On the grid: a tenth of a model about 3.5 across.
  CHECK(std::abs(offset.y * 10 - std::round(offset.y * 10)) < 1e-9);
  InputFrame release = at(to);
  release.held = KeyModifier::control;
  viewer.frame(release);  // the release keeps it
  REQUIRE_FALSE(tool->is_dragging());
  CHECK(glm::distance(position(viewer, "m_i4"), before + offset) < 1e-9);
  CHECK(viewer.window().selection().vertices().size() == 1);
}

TEST_CASE("dragging a funnel's vertex moves its sliders as one undo step; the slider lock holds", "[app]") {
  viewer::ViewerOptions options;
  options.file = assets + "funnel_cube_consolidated.nome";
  test::TestViewer viewer(options);
  REQUIRE(viewer.window().shown());
  const scene::Scene& scene = *viewer.window().sessions().scene();
  const auto value = [&](const char* name) { return scene.parameters()[*scene.find_parameter(name)].value; };
  const std::string text = scene_text(viewer);

  run_script(viewer, "drag fun1_bc5 z -0.2\n");
  CHECK(value("fp_z") == Approx(-1.2));
  CHECK(scene_text(viewer) == text);  // sliders move, the text stays
  CHECK_THAT(viewer.messages(), Catch::Contains("drag: fp_z -1 to -1.2"));
  run_script(viewer, "action undo\n");
  CHECK(value("fp_z") == -1.0);

  SECTION("an instance drag adds a translate after its transforms; undo takes it out") {
    run_script(viewer, "drag tp1 1 0 0\n");
    CHECK(scene_text(viewer) == with(text, "instance tp1 m1 rotate (0 0 1) (90) endinstance",
                                     "instance tp1 m1 rotate (0 0 1) (90) translate (1 0 0) endinstance"));
    run_script(viewer, "action undo\n");
    CHECK(scene_text(viewer) == text);
  }
  SECTION("with the sliders locked while editing, a drag that would move them is refused") {
    // An accepted face of the report's corner: the document has edits, which the lock protects.
    const std::string dir = test::private_scratch_dir("move_locked");
    std::ofstream(dir + "/edited.nome")
        << read_text_file(assets + "funnel_cube.nome")
        << "consolidate\n  consolidateface\n"
           "    vertex fun3_hc3 endvertex vertex fun5_hc3 endvertex "
           "vertex fun2_hc5 endvertex\n  endconsolidateface\nendconsolidate\n";
    run_script(viewer, "drop " + dir +
                           "/edited.nome\nprompt discard\naction lock-parameters\n"
                           "drag fun1_bc5 z -0.2\n");
    CHECK_THAT(viewer.messages(), Catch::Contains("the sliders are locked while editing"));
    const scene::Scene& edited = *viewer.window().sessions().scene();
    CHECK(edited.parameters()[*edited.find_parameter("fp_z")].value == -0.8);
  }
  SECTION("a vertex nothing places but constant numbers is refused with its statement") {
    const std::string dir = test::private_scratch_dir("move_constant");
    std::ofstream(dir + "/constant.nome")
        << "funnel fun (8 0.5 0 0.3) endfunnel\ninstance f fun endinstance\n";
    run_script(viewer, "drop " + dir + "/constant.nome\nprompt discard\ndrag f_hc2 0 0 1\n");
    CHECK_THAT(viewer.messages(),
               Catch::Contains("vertex 'f_hc2' cannot move: funnel 'fun' (" + dir + "/constant.nome:1:8)"));
  }
}

TEST_CASE("the drag script command takes an offset or an axis and a distance", "[app]") {
  const auto commands = viewer::parse_script("drag selection 0.5 0 -1\ndrag fun1_hc3 z 0.25\n", "s.txt");
  REQUIRE(commands.size() == 2);
  CHECK(commands[0].words == std::vector<std::string>{"selection"});
  CHECK(commands[0].numbers == std::vector<double>{0.5, 0, -1});
  CHECK(commands[1].words == std::vector<std::string>{"fun1_hc3", "z"});
  CHECK_THROWS_WITH(viewer::parse_script("drag a w 1\n", "s.txt"),
                    Catch::Contains("s.txt:1:8: expected an axis x, y or z, found 'w'"));
  CHECK_THROWS_WITH(viewer::parse_script("drag a 1\n", "s.txt"),
                    Catch::Contains("expected 'drag SELECTION DX DY DZ'"));
}
