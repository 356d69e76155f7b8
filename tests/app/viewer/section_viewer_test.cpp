#include <catch2/catch.hpp>

#include <fstream>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "app/viewer_support.hpp"
#include "viewer/tools/section_tool.hpp"
#include "viewer/window.hpp"

using namespace nome;

TEST_CASE("C cuts the view with a section plane through the middle, filled on a solid only", "[app]") {
  const std::string dir = test::private_scratch_dir("viewer_section");
  std::ofstream(dir + "/band.nome") << "mobiusstrip band (1 1 2 24) endmobiusstrip\n"
                                       "offset slab height 0.05 instance strip band endinstance endoffset\n";
  viewer::ViewerOptions options;
  options.file = dir + "/band.nome";
  test::TestViewer viewer(options);
  for (int i = 0; i < 600 && !(viewer.window().shown() && is_solid(viewer.window().shown()->stage)); ++i)
    viewer.frame();
  REQUIRE(is_solid(viewer.window().shown()->stage));
  CHECK(viewer.window().display().section_plane == glm::vec4(0.0f));
  viewer::InputFrame press;
  press.keys.push_back({GLFW_KEY_C, viewer::KeyModifier::none});
  viewer.frame(press);
  REQUIRE(viewer.window().find_tool<viewer::SectionTool>()->state().is_on);
  viewer.frame();
  const render::DisplaySettings& display = viewer.window().display();
  // Perpendicular to z through the middle of the solid (the band is symmetric about z = 0).
  CHECK(display.section_plane.z == 1.0f);
  CHECK(display.section_plane.w == Approx(0.0).margin(1e-6));
  CHECK(display.fills_section);
  viewer.frame(press);
  viewer.frame();
  CHECK(viewer.window().display().section_plane == glm::vec4(0.0f));
}
