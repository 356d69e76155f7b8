#include <catch2/catch.hpp>

#include <fstream>
#include <set>
#include <sstream>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include "app/viewer_support.hpp"
#include "viewer/layout.hpp"
#include "viewer/window.hpp"

using namespace nome;
using viewer::ScreenRect;

namespace {

using nome::test::assets;

// The log's `NAME X Y W H` lines as rectangles (bank headers keyed `bank NAME`).
std::vector<std::pair<std::string, ScreenRect>> layout_lines(const std::string& log) {
  std::vector<std::pair<std::string, ScreenRect>> rects;
  std::istringstream in(log);
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line.substr(line.find(' ') + 1));  // after "nome:"
    std::string name;
    words >> name;
    if (name == "bank") {
      std::string bank;
      words >> bank;
      name += " " + bank;
    }
    ScreenRect r;
    if (words >> r.origin.x >> r.origin.y >> r.size.x >> r.size.y) rects.push_back({name, r});
  }
  return rects;
}

}  // namespace

TEST_CASE("the scene text pane stands beside the controls, and the viewport and log give way", "[app]") {
  const viewer::LayoutChrome chrome{20.0, 24.0, 30.0, 1.0};
  viewer::LayoutSettings settings;
  CHECK_FALSE(settings.is_pane_shown);
  CHECK(viewer::arrange(settings, {1600.0, 900.0}, chrome).pane.size.x == 0.0);
  settings.is_pane_shown = true;
  const viewer::ScreenLayout a = viewer::arrange(settings, {1600.0, 900.0}, chrome);
  CHECK(a.pane.origin == glm::dvec2(settings.left_width, 20.0));
  CHECK(a.pane.size.x == settings.pane_width);
  CHECK(a.pane.max().y == Approx(900.0 - 24.0));
  CHECK(a.viewport.origin.x == Approx(a.pane.max().x));
  CHECK(a.viewport.max().x == Approx(1600.0 - settings.right_width));
  CHECK(a.log.origin.x == Approx(a.viewport.origin.x));
  CHECK(a.log.size.x == Approx(a.viewport.size.x));
  // Tab hides the sidebars, not the pane: the pane and the model share the window.
  settings.is_left_shown = settings.is_right_shown = false;
  const viewer::ScreenLayout b = viewer::arrange(settings, {1280.0, 800.0}, chrome);
  CHECK(b.pane.origin.x == 0.0);
  CHECK(b.viewport.size.x == Approx(1280.0 - settings.pane_width));
}

TEST_CASE("the viewport is the rectangle between the sidebars, above the log", "[app]") {
  const viewer::LayoutChrome chrome{20.0, 24.0, 30.0, 1.0};
  viewer::LayoutSettings settings;
  const viewer::ScreenLayout a = viewer::arrange(settings, {1280.0, 800.0}, chrome);
  CHECK(a.viewport.origin == glm::dvec2(settings.left_width, 20.0));
  CHECK(a.viewport.max().x == Approx(1280.0 - settings.right_width));
  CHECK(a.viewport.max().y == Approx(a.log.origin.y));
  CHECK(a.log.max().y == Approx(800.0 - 24.0));
  CHECK(a.right.max().x == Approx(1280.0));
  // Tab hides both sidebars and a collapsed log keeps only its bar: the viewport takes the room.
  settings.is_left_shown = settings.is_right_shown = settings.is_log_open = false;
  const viewer::ScreenLayout b = viewer::arrange(settings, {1280.0, 800.0}, chrome);
  CHECK(b.viewport.size == glm::dvec2(1280.0, 800.0 - 20.0 - 24.0 - 30.0));
  // Twice the content scale, twice the sidebars; a narrow window leaves the viewport its minimum.
  settings = {};
  const viewer::ScreenLayout c = viewer::arrange(settings, {500.0, 400.0}, {20.0, 24.0, 30.0, 2.0});
  CHECK(c.viewport.size.x == Approx(viewer::min_viewport_pixels));
  CHECK(c.viewport.size.y >= viewer::min_viewport_pixels);
}

TEST_CASE("the layout file round-trips, and a missing or damaged line keeps its default", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("layout_file");
  viewer::LayoutSettings settings;
  settings.left_width = 281.5;
  settings.right_width = 402.0;
  settings.log_height = 90.0;
  settings.is_right_shown = false;
  settings.is_log_open = false;
  settings.is_dark = true;
  settings.window_size = {1024, 700};
  viewer::write_layout(dir + "/nome/layout", settings);
  CHECK(viewer::read_layout(dir + "/nome/layout") == settings);
  CHECK(viewer::read_layout(dir + "/missing") == viewer::LayoutSettings{});
  std::ofstream(dir + "/damaged") << "left_width -3\nwindow_width 5\nright_width 300\nnonsense\n";
  const viewer::LayoutSettings damaged = viewer::read_layout(dir + "/damaged");
  CHECK(damaged.left_width == viewer::LayoutSettings{}.left_width);
  CHECK(damaged.window_size.x == 1280);
  CHECK(damaged.right_width == 300.0);
}

TEST_CASE("a session remembers its layout, a scripted one starts from the defaults", "[app]") {
  // Stores of its own: the other tests' windows start from the default layout.
  const std::string dir = nome::test::private_scratch_dir("layout_remembered");
  const viewer::ViewerStores stores{dir + "/recent", dir + "/recovery", dir + "/layout"};
  std::filesystem::remove(stores.layout_file);
  viewer::ViewerOptions options;
  {
    nome::test::TestViewer viewer(options, stores);
    viewer.frame();
    viewer::InputFrame tab;
    tab.keys.push_back({GLFW_KEY_TAB, viewer::KeyModifier::none});
    viewer.frame(tab);
    CHECK_FALSE(viewer.window().layout_settings().is_left_shown);
  }
  CHECK_FALSE(viewer::read_layout(stores.layout_file).is_right_shown);
  {
    nome::test::TestViewer viewer(options, stores);
    CHECK_FALSE(viewer.window().layout_settings().is_left_shown);
  }
  options.script = nome::test::write_script(nome::test::private_scratch_dir("layout_scripted"), "quit\n");
  nome::test::TestViewer scripted(options, stores);
  CHECK(scripted.window().layout_settings() == viewer::LayoutSettings{});
}

TEST_CASE("framing fits the model into the viewport, not the window", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("layout_framing");
  viewer::ViewerOptions options;
  options.file = assets + "klein_bottle.nome";
  options.script = nome::test::write_script(dir, "view 30 25\nquit\n");
  nome::test::TestViewer viewer(options);
  REQUIRE(viewer.run() == 0);
  const viewer::Window& window = viewer.window();
  const ScreenRect viewport = window.layout().viewport;
  // The panels take room: the viewport is well inside the window.
  CHECK(viewport.origin.x > 100.0);
  CHECK(viewport.max().x < nome::test::viewer_width - 100.0);
  const ScreenProjection projection = window.camera().screen_projection(viewport.size, viewport.origin);
  ScreenRect box{glm::dvec2(1e9), glm::dvec2(0.0)};
  glm::dvec2 high(-1e9);
  for (const Vec3& p : window.shown()->mesh->positions()) {
    const auto pixel = project_to_pixel(projection, p);
    REQUIRE(pixel);
    box.origin = glm::min(box.origin, glm::dvec2(*pixel));
    high = glm::max(high, glm::dvec2(*pixel));
  }
  box.size = high - box.origin;
  CHECK(viewport.contains(box));
  // ... and fills it along one of its axes.
  CHECK(std::max(box.size.x / viewport.size.x, box.size.y / viewport.size.y) > 0.8);
}

TEST_CASE("the wheel zooms towards the point under the cursor", "[app]") {
  viewer::ViewController view;
  const std::vector<Vec3> points = {Vec3(-1.0), Vec3(1.0)};
  const ScreenRect viewport{{300.0, 20.0}, {600.0, 500.0}};
  view.frame(points, {}, viewport);
  const glm::dvec2 cursor(450.0, 200.0);
  const Ray ray = ray_through_pixel(view.projection(viewport), cursor);
  // The point under the cursor at the orbit centre's depth stays under it.
  const glm::dvec3 eye = view.camera().eye();
  const glm::dvec3 forward = glm::normalize(view.camera().target - eye);
  const double t = glm::dot(view.camera().target - ray.origin, forward) / glm::dot(ray.direction, forward);
  const Vec3 under = ray.origin + t * ray.direction;
  const double distance = view.camera().distance;
  view.zoom_at(0.5, cursor, viewport);
  CHECK(view.camera().distance == Approx(distance * 0.5));
  const auto pixel = project_to_pixel(view.projection(viewport), under);
  REQUIRE(pixel);
  CHECK(pixel->x == Approx(cursor.x).margin(1e-6));
  CHECK(pixel->y == Approx(cursor.y).margin(1e-6));
}

TEST_CASE("a larger content scale makes the font, and so the menu bar and sidebars, larger", "[app]") {
  auto measure = [](float scale) {
    viewer::ViewerOptions options;
    nome::test::TestViewer viewer(options);
    viewer.platform().set_content_scale(scale);
    for (int i = 0; i < 3; ++i) viewer.frame();
    const float font = ImGui::GetFontSize();
    return std::pair{font, viewer.window().layout().viewport.origin.y};
  };
  const auto [font, menu] = measure(1.0f);
  const auto [font2, menu2] = measure(2.0f);
  CHECK(font2 == Approx(2.0 * font));
  CHECK(menu2 == Approx(2.0 * menu));
}

TEST_CASE("the script's layout and scroll bring every bank's header into the parameter panel", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("layout_twelve_banks");
  const std::string scene = dir + "/twelve.nome";
  nome::test::write_twelve_banks(scene);
  std::string script = "layout\n";
  for (int i = 0; i < 12; ++i) script += "scroll parameters 150\nlayout\n";
  const auto r = nome::test::run_window(scene + " --size 1024x700 --script " +
                                        nome::test::write_script(dir, script + "quit\n"));
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto rects = layout_lines(r.err);
  std::optional<ScreenRect> panel, viewport;
  std::set<std::string> seen;
  for (const auto& [name, rect] : rects) {
    if (name == "parameters") panel = rect;
    if (name == "viewport") viewport = rect;
    if (name.starts_with("bank ") && panel && panel->contains(rect)) seen.insert(name);
  }
  REQUIRE(panel);
  REQUIRE(viewport);
  CHECK(panel->max().x == 1024.0);
  CHECK(viewport->max().x <= panel->origin.x);
  CHECK(seen.size() == 12);
}

TEST_CASE("a sidebar dragged by its corner keeps the new width, which the viewport gives up", "[app]") {
  viewer::ViewerOptions options;
  options.script = nome::test::write_script(nome::test::private_scratch_dir("layout_drag"), "");
  nome::test::TestViewer viewer(options);
  viewer.frame();
  const ScreenRect left = viewer.window().layout().left;
  const glm::dvec2 grip = left.max() - glm::dvec2(3.0);
  ImGuiIO& io = ImGui::GetIO();
  auto mouse = [&](glm::dvec2 at, bool is_down) {
    io.MousePos = ImVec2(float(at.x), float(at.y));
    io.MouseDown[0] = is_down;
    viewer.frame();
  };
  mouse(grip, false);
  mouse(grip, true);
  for (double dx = 10.0; dx <= 80.0; dx += 10.0) mouse(grip + glm::dvec2(dx, 0.0), true);
  mouse(grip + glm::dvec2(80.0, 0.0), false);
  viewer.frame();
  CHECK(viewer.window().layout_settings().left_width == Approx(left.size.x + 80.0).margin(2.0));
  CHECK(viewer.window().layout().viewport.origin.x == Approx(left.size.x + 80.0).margin(2.0));
  CHECK(viewer.window().layout().left.size.y == left.size.y);  // the height stays the layout's
}

TEST_CASE("the default layout gives the model most of the width; the log opens from its status line",
          "[app]") {
  auto viewport_of = [](const std::string& size, const std::string& script) {
    const std::string dir = nome::test::private_scratch_dir("layout_default_" + size);
    const auto r = nome::test::run_window(std::string(NOME_SOURCE_DIR) + "/assets/mobius_band.nome --size " +
                                          size + " --script " + nome::test::write_script(dir, script));
    INFO(r.err);
    REQUIRE(r.status == 0);
    std::vector<ScreenRect> viewports;
    for (const auto& [name, rect] : layout_lines(r.err))
      if (name == "viewport") viewports.push_back(rect);
    return viewports;
  };
  // 780 of 1280 pixels (61 %); 524 of 1024 (51 %), where the sidebars keep their width.
  const auto wide = viewport_of("1280x800", "layout\nkey L\nlayout\nquit\n");
  REQUIRE(wide.size() == 2);
  CHECK(wide[0].size.x >= 0.6 * 1280.0);
  CHECK(wide[0].size.x == Approx(780.0));
  // The log, a status line by default, opens with L (View > Log open) and takes room from the model.
  CHECK(wide[1].size.y < wide[0].size.y - 100.0);
  const auto narrow = viewport_of("1024x700", "layout\nquit\n");
  REQUIRE(narrow.size() == 1);
  CHECK(narrow[0].size.x == Approx(524.0));
}
