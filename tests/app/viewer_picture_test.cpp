#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <fstream>

#include "app/viewer_support.hpp"
#include "render/image.hpp"
#include "support/shared_examples.hpp"

using namespace nome;
using nome::test::count_pixels;
using nome::test::write_script;

// The window's pictures in this process: the GL backend on a headless context (EGL, else OSMesa)
// draws the scene as the real window does, without the panels.
namespace {

using nome::test::assets;

nome::test::CommandResult run_gl_window(const std::string& arguments) {
  return nome::test::run_window(arguments, nome::test::TestViewer::private_stores(),
                                nome::test::TestRenderer::gl);
}

}  // namespace

TEST_CASE("the Möbius band shows its back faces in their own colour", "[app][render]") {
  const std::string dir = nome::test::private_scratch_dir("viewer_mobius");
  const std::string script = write_script(dir, "view 20 35\nscreenshot " + dir + "/mobius.png\nquit\n");
  const auto r = run_gl_window(assets + "mobius_band.obj --script " + script);
  INFO(r.err);
  REQUIRE(r.status == 0);
  const render::Image shot = render::read_png(dir + "/mobius.png");
  int front = 0, back = 0;
  for (int y = 0; y < shot.height; ++y)
    for (int x = 0; x < shot.width; ++x) {
      const auto* p = shot.pixel(x, y);
      front += p[0] > p[2] + 40;  // gold
      back += p[2] > p[0] + 40;   // blue
    }
  CHECK(front > 2000);
  CHECK(back > 2000);
}

TEST_CASE("a scene's rim lines are drawn, though they have no faces", "[app][render]") {
  NOME_NEEDS_SHARED_EXAMPLES("original");
  const std::string dir = nome::test::private_scratch_dir("viewer_rim_lines");
  const std::string script = write_script(dir, "view 30 25\nscreenshot " + dir + "/rim.png\nquit\n");
  const auto r =
      run_gl_window(nome::test::shared_examples_dir("original") + "rimline.nom --script " + script);
  INFO(r.err);
  REQUIRE(r.status == 0);
  // The polyline's three segments in the rim colour (0.05, 0.45, 0.55).
  CHECK(count_pixels(render::read_png(dir + "/rim.png"), 13, 115, 140, 20) > 300);
}

TEST_CASE("the model is drawn in the viewport between the panels, framed to fill it", "[app][render]") {
  const std::string dir = nome::test::private_scratch_dir("viewer_viewport");
  const std::string script =
      write_script(dir, "view 30 25\nlayout\nscreenshot " + dir + "/klein.png\nquit\n");
  const auto r = run_gl_window(assets + "klein_bottle.nome --script " + script);
  INFO(r.err);
  REQUIRE(r.status == 0);
  int x0 = 0, y0 = 0, w = 0, h = 0;
  const auto at = r.err.find("viewport ");
  REQUIRE(at != std::string::npos);
  REQUIRE(std::sscanf(r.err.c_str() + at, "viewport %d %d %d %d", &x0, &y0, &w, &h) == 4);
  const render::Image shot = render::read_png(dir + "/klein.png");
  int inside = 0, outside = 0;
  glm::ivec2 low(shot.width, shot.height), high(0);
  for (int y = 0; y < shot.height; ++y)
    for (int x = 0; x < shot.width; ++x) {
      const auto* p = shot.pixel(x, y);
      if (std::abs(p[0] - p[2]) < 40) continue;  // neither gold nor blue: background
      const bool is_inside = x >= x0 && x < x0 + w && y >= y0 && y < y0 + h;
      (is_inside ? inside : outside) += 1;
      low = glm::min(low, glm::ivec2(x, y));
      high = glm::max(high, glm::ivec2(x, y));
    }
  CHECK(outside == 0);
  CHECK(inside > 20000);
  // Framed to the viewport: the picture spans most of its width or its height.
  CHECK(std::max(double(high.x - low.x) / w, double(high.y - low.y) / h) > 0.8);
}
