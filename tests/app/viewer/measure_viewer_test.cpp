#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "app/viewer_support.hpp"
#include "viewer/tools/measure_tool.hpp"
#include "viewer/window.hpp"

using namespace nome;

namespace {

const char* const measured_box_text =
    "point a (0 0 0) endpoint point b (1 0 0) endpoint point c (1 1 0) endpoint point d (0 1 0) endpoint\n"
    "point e (0 0 1) endpoint point f (1 0 1) endpoint point g (1 1 1) endpoint point h (0 1 1) endpoint\n"
    "mesh box\n"
    "  face bottom (a d c b) endface face top (e f g h) endface face front (a b f e) endface\n"
    "  face back (c d h g) endface face left (a e h d) endface face right (b c g f) endface\n"
    "endmesh\n"
    "offset slab height 0.05 instance k box endinstance endoffset\n";

void measure_click(test::TestViewer& viewer, glm::dvec2 pixel) {
  viewer::InputFrame press;
  press.cursor = pixel;
  press.is_pressed[0] = press.is_down[0] = true;
  viewer.frame(press);
  viewer::InputFrame release;
  release.cursor = pixel;
  viewer.frame(release);
}

void measure_key(test::TestViewer& viewer, int key, viewer::KeyModifier modifiers) {
  viewer::InputFrame input;
  input.keys.push_back({key, modifiers});
  viewer.frame(input);
}

}  // namespace

TEST_CASE("measuring in the viewer: Shift+M gives the wall of the offset box, M a distance", "[app]") {
  const std::string dir = test::private_scratch_dir("viewer_measure");
  std::ofstream(dir + "/box.nome") << measured_box_text;
  viewer::ViewerOptions options;
  options.file = dir + "/box.nome";
  test::TestViewer viewer(options);
  const auto is_solid = [&] {
    const viewer::StageResult* shown = viewer.window().shown();
    return shown && nome::is_solid(shown->stage);
  };
  for (int i = 0; i < 600 && !is_solid(); ++i) viewer.frame();
  REQUIRE(is_solid());

  measure_key(viewer, GLFW_KEY_M, viewer::KeyModifier::shift);
  REQUIRE(viewer.window().find_tool<viewer::MeasureTool>()->mode() == viewer::MeasureMode::wall);
  measure_click(viewer, {640, 400});
  const auto& wall = viewer.window().find_tool<viewer::MeasureTool>()->last();
  REQUIRE(wall);
  CHECK(wall->is_wall);
  // The viewer subdivides the box before the offset (a rounded box): its wall is the slab, 2d, to a few
  // percent (the kernel's test holds a smooth solid to 1 %).
  CHECK(wall->length == Approx(2 * 0.05).epsilon(0.05));
  CHECK(wall->length == Approx(glm::distance(wall->from, wall->to)));
  CHECK(viewer.window().selection().is_empty());  // measuring does not select

  measure_key(viewer, GLFW_KEY_M, viewer::KeyModifier::none);
  REQUIRE(viewer.window().find_tool<viewer::MeasureTool>()->mode() == viewer::MeasureMode::distance);
  measure_click(viewer, {600, 380});
  CHECK(viewer.window().find_tool<viewer::MeasureTool>()->first_point());
  measure_click(viewer, {690, 420});
  const auto& distance = viewer.window().find_tool<viewer::MeasureTool>()->last();
  REQUIRE(distance);
  CHECK_FALSE(distance->is_wall);
  CHECK(distance->length == Approx(glm::distance(distance->from, distance->to)));
  CHECK(distance->length > 0.1);
  CHECK_THAT(viewer.messages(), Catch::Contains("distance ") && Catch::Contains(" mm"));
  measure_key(viewer, GLFW_KEY_M, viewer::KeyModifier::none);
  CHECK(viewer.window().find_tool<viewer::MeasureTool>()->mode() == viewer::MeasureMode::off);
}
