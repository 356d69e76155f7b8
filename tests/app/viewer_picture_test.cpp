#include <catch2/catch.hpp>

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

const std::string assets = std::string(NOME_SOURCE_DIR) + "/assets/";

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
