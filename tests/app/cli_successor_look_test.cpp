#include <catch2/catch.hpp>

#include <array>
#include <cstdlib>
#include <fstream>
#include <string>

#include "app/cli_support.hpp"
#include "render/image.hpp"
#include "render/image_diff.hpp"
#include "support/shared_examples.hpp"

using namespace nome;

namespace {

// Two quads facing +z side by side (x in -2..0 and 0..2), the left one green, the right one with no colour
// of its own; under a white ambient light alone every face shows exactly its colour.
const std::string two_quads = R"(
frontcolor (0.8 0 0) endfrontcolor
surface G color (0 0.9 0) endsurface
point a (-2 -1 0) endpoint
point b (0 -1 0) endpoint
point c (2 -1 0) endpoint
point d (2 1 0) endpoint
point e (0 1 0) endpoint
point f (-2 1 0) endpoint
mesh m
  face left (a b e f) surface G endface
  face right (b c d e) endface
endmesh
instance im m endinstance
)";

const std::string white_ambient = R"(
light amb
  type NOME_AMBIENT
  color (1 1 1)
endlight
instance lamp amb endinstance
)";

struct Rendered {
  test::CommandResult run;
  render::Image image;
};

// Renders the scene text from the front (looking down -z) at 400x300.
Rendered render_text(const std::string& name, const std::string& text, const std::string& options = "") {
  const std::string dir = test::scratch_dir("successor_look_" + name);
  const std::string scene = dir + "/" + name + ".nom", out = dir + "/" + name + ".png";
  std::ofstream(scene) << text;
  Rendered r;
  r.run = test::run_nome("render " + scene + " --view 0,0 --size 400x300 " + options + " -o " + out);
  INFO(r.run.err);
  REQUIRE(r.run.status == 0);
  r.image = render::read_png(out);
  return r;
}

std::array<int, 3> rgb_at(const render::Image& image, double fx, double fy) {
  const std::uint8_t* p = image.pixel(int(fx * image.width), int(fy * image.height));
  return {p[0], p[1], p[2]};
}

bool is_near(const std::array<int, 3>& got, const std::array<int, 3>& want, int tolerance = 3) {
  for (int k = 0; k < 3; ++k)
    if (std::abs(got[k] - want[k]) > tolerance) return false;
  return true;
}

// How many pixels are within a few levels of the colour.
int count_color(const render::Image& image, const std::array<int, 3>& want, int tolerance = 12) {
  int n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      n += is_near({p[0], p[1], p[2]}, want, tolerance) ? 1 : 0;
    }
  return n;
}

}  // namespace

TEST_CASE("frontcolor colours the faces without a colour of their own beside coloured ones",
          "[app][render]") {
  const Rendered r = render_text("frontcolor", two_quads + white_ambient);
  INFO("left " << rgb_at(r.image, 0.3, 0.5)[0] << "," << rgb_at(r.image, 0.3, 0.5)[1] << ","
               << rgb_at(r.image, 0.3, 0.5)[2] << " right " << rgb_at(r.image, 0.7, 0.5)[0] << ","
               << rgb_at(r.image, 0.7, 0.5)[1] << "," << rgb_at(r.image, 0.7, 0.5)[2]);
  CHECK(is_near(rgb_at(r.image, 0.3, 0.5), {0, 230, 0}));  // its surface: 0.9 green
  CHECK(is_near(rgb_at(r.image, 0.7, 0.5), {204, 0, 0}));  // the file's front colour: 0.8 red
  // The user's own front colour takes the file's place, and the painted face keeps its surface.
  const Rendered own = render_text("frontcolor_option", two_quads + white_ambient, "--color 0,0,1");
  CHECK(is_near(rgb_at(own.image, 0.3, 0.5), {0, 230, 0}));
  CHECK(is_near(rgb_at(own.image, 0.7, 0.5), {0, 0, 255}));
}

TEST_CASE("--palette jipcad gives JIPCAD's front colour; the file's frontcolor still wins", "[app][render]") {
  const std::string plain = R"(
point a (-2 -1 0) endpoint
point b (2 -1 0) endpoint
point c (2 1 0) endpoint
point d (-2 1 0) endpoint
mesh m face q (a b c d) endface endmesh
instance im m endinstance
)";
  const Rendered jipcad = render_text("palette", plain + white_ambient, "--palette jipcad");
  CHECK(is_near(rgb_at(jipcad.image, 0.5, 0.5), {250, 166, 25}));
  const Rendered nome = render_text("palette_nome", plain + white_ambient, "--palette nome");
  CHECK(is_near(rgb_at(nome.image, 0.5, 0.5), {204, 158, 64}));  // Nome's gold, 0.80 0.62 0.25
  const Rendered file = render_text("palette_file", two_quads + white_ambient, "--palette jipcad");
  CHECK(is_near(rgb_at(file.image, 0.7, 0.5), {204, 0, 0}));
  const test::CommandResult bad =
      test::run_nome("render " + test::assets + "cube.obj --palette blender -o x.png");
  CHECK(bad.status != 0);
  CHECK(bad.err.find("--palette expects nome or jipcad, found 'blender'") != std::string::npos);
}

TEST_CASE("a scene's lights light it: all at zero a black model, a directional light by its direction",
          "[app][render]") {
  const std::string dark = two_quads + R"(
light amb type NOME_AMBIENT color (0 0 0) endlight
light sun type NOME_DIRECTIONAL color (0 0 0) endlight
instance lamp amb endinstance
instance sunn sun endinstance
)";
  const Rendered black = render_text("lights_zero", dark);
  CHECK(is_near(rgb_at(black.image, 0.3, 0.5), {0, 0, 0}));
  CHECK(is_near(rgb_at(black.image, 0.7, 0.5), {0, 0, 0}));
  CHECK(is_near(rgb_at(black.image, 0.02, 0.02), {255, 255, 255}));  // the background stays
  // The viewer's own lights on request.
  const Rendered lit = render_text("lights_viewer", dark, "--viewer-lights");
  CHECK(rgb_at(lit.image, 0.7, 0.5)[0] > 60);

  // A directional light travels along +y turned by its instance: turned -90 degrees about x it travels
  // along -z, onto the faces' front, which then shows light colour times face colour; turned +90 degrees
  // it travels along +z and lights only their backs.
  const std::string sun = two_quads + R"(
light sun type NOME_DIRECTIONAL color (0.5 1 1) endlight
instance sunn sun rotate (1 0 0) (ANGLE) endinstance
)";
  auto with_angle = [&](const std::string& angle) {
    std::string text = sun;
    text.replace(text.find("ANGLE"), 5, angle);
    return text;
  };
  const Rendered facing = render_text("lights_facing", with_angle("-90"));
  CHECK(is_near(rgb_at(facing.image, 0.3, 0.5), {0, 230, 0}));
  CHECK(is_near(rgb_at(facing.image, 0.7, 0.5), {102, 0, 0}));  // 0.5 of the red channel's 0.8
  const Rendered behind = render_text("lights_behind", with_angle("90"));
  CHECK(is_near(rgb_at(behind.image, 0.3, 0.5), {0, 0, 0}));
  CHECK(is_near(rgb_at(behind.image, 0.7, 0.5), {0, 0, 0}));
}

TEST_CASE("curves take their instance's surface colour; a curve without one keeps the rim colour",
          "[app][render]") {
  const std::string curves = R"(
surface B color (0 0 1) endsurface
point a (-2 0 0) endpoint
point b (2 0 0) endpoint
point c (-2 1 0) endpoint
point d (2 1 0) endpoint
polyline painted (a b) endpolyline
polyline plain (c d) endpolyline
instance ip painted surface B endinstance
instance iq plain endinstance
circle ring (0.5 12) endcircle
instance ir ring translate (0 -1 0) surface B endinstance
)";
  const Rendered r = render_text("curve_colors", curves, "--dialect jipcad");
  const int blue = count_color(r.image, {0, 0, 255});
  const int teal = count_color(r.image, {13, 115, 140});  // DisplaySettings::rim_color
  INFO("blue " << blue << ", teal " << teal);
  CHECK(blue > 600);  // the painted line and the circle, 4 and 3.1 units long, 3 pixels wide
  CHECK(teal > 300);
  CHECK(blue > 1.3 * teal);
}

TEST_CASE("unsubdivided results are drawn faceted, subdivision surfaces smooth, unless the user says",
          "[app][render]") {
  const std::string dir = test::scratch_dir("successor_look_shading");
  auto render = [&](const std::string& name, const std::string& options) {
    const test::CommandResult r = test::run_nome("render " + test::assets + "cube.obj --size 256x192 " +
                                                 options + " -o " + dir + "/" + name + ".png");
    INFO(r.err);
    REQUIRE(r.status == 0);
    return render::read_png(dir + "/" + name + ".png");
  };
  auto same = [](const render::Image& a, const render::Image& b) {
    const render::ImageDifference d = render::compare_images(a, b, 0);
    return d.same_size && d.differing_fraction == 0.0;
  };
  const render::Image automatic = render("automatic", "");
  CHECK(same(automatic, render("flat", "--flat")));
  CHECK_FALSE(same(automatic, render("smooth", "--smooth")));
  const render::Image subdivided = render("subdivided", "--subdiv 2");
  CHECK(same(subdivided, render("subdivided_smooth", "--subdiv 2 --smooth")));
  CHECK_FALSE(same(subdivided, render("subdivided_flat", "--subdiv 2 --flat")));
  const test::CommandResult both =
      test::run_nome("render " + test::assets + "cube.obj --flat --smooth -o x.png");
  CHECK(both.status != 0);
  CHECK(both.err.find("--flat and --smooth exclude each other") != std::string::npos);
}

TEST_CASE(
    "JIPCAD's render examples: light_test's lights at zero draw a black model, backface's plain faces red",
    "[app][render]") {
  NOME_NEEDS_SHARED_EXAMPLES("jipcad");
  const std::string dir = test::scratch_dir("successor_look_examples");
  const std::string examples = test::shared_examples_dir("jipcad");
  const test::CommandResult light = test::run_nome(
      "render " + examples + "/render__light_test.nom --size 320x240 -o " + dir + "/light.png");
  INFO(light.err);
  REQUIRE(light.status == 0);
  const render::Image dark = render::read_png(dir + "/light.png");
  CHECK(count_color(dark, {0, 0, 0}, 4) > 5000);
  CHECK(count_color(dark, {255, 255, 255}, 4) + count_color(dark, {0, 0, 0}, 4) > 0.97 * 320 * 240);
  // The cube's four plain faces in the file's front colour (0.8 0 0), whatever the light: red dominates.
  const test::CommandResult back =
      test::run_nome("render " + examples + "/render__backface.nom --size 320x240 -o " + dir + "/back.png");
  INFO(back.err);
  REQUIRE(back.status == 0);
  const render::Image cube = render::read_png(dir + "/back.png");
  int red = 0, grey = 0;
  for (int y = 0; y < cube.height; ++y)
    for (int x = 0; x < cube.width; ++x) {
      const std::uint8_t* p = cube.pixel(x, y);
      red += p[0] > 60 && p[1] < p[0] / 4 && p[2] < p[0] / 4 ? 1 : 0;
      grey += p[0] < 250 && std::abs(p[0] - p[1]) < 8 && std::abs(p[1] - p[2]) < 8 ? 1 : 0;
    }
  INFO("red " << red << ", grey " << grey);
  CHECK(red > 10000);
  CHECK(grey < 200);
}
