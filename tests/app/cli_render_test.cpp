#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "app/cli_support.hpp"
#include "render/image.hpp"
#include "render/render_support.hpp"

using namespace nome;

namespace {

std::string asset(const std::string& name) {
  return std::string(NOME_SOURCE_DIR) + "/assets/" + name;
}

// The default rim colour (teal, DisplaySettings::rim_color), shaded edges included.
bool is_rim_color(const std::uint8_t* p) {
  return p[0] < 60 && p[1] > 80 && p[1] < 150 && p[2] > 100 && p[2] < 180;
}

}  // namespace

TEST_CASE("nome render writes a PNG of the requested size and reports the backend", "[app]") {
  const std::string dir = test::scratch_dir("cli_render");
  const test::CommandResult r = test::run_nome("render " + asset("mobius_band.obj") + " -o " + dir +
                                               "/band.png --size 320x200 --verbose");
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK_THAT(r.err, Catch::StartsWith("nome: EGL"));
  CHECK(r.err.find("wrote " + dir + "/band.png") != std::string::npos);
  const render::Image image = render::read_png(dir + "/band.png");
  CHECK(image.width == 320);
  CHECK(image.height == 200);
  const test::SideCounts sides = test::count_sides(image);
  CHECK(sides.front > 1000);
  CHECK(sides.back > 1000);
}

TEST_CASE("nome render --backend osmesa", "[app]") {
  const std::string dir = test::scratch_dir("cli_render_osmesa");
  const test::CommandResult r = test::run_nome("render " + asset("torus.obj") + " -o " + dir +
                                               "/t.png --size 64x48 --backend osmesa --verbose");
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(r.err.find("OSMesa") != std::string::npos);
  CHECK(render::read_png(dir + "/t.png").width == 64);
}

TEST_CASE("nome render --views 4 makes a contact sheet of four framed tiles", "[app]") {
  const std::string dir = test::scratch_dir("cli_render_views");
  REQUIRE(test::run_nome("render " + asset("torus.obj") + " -o " + dir + "/s.png --size 200x160 --views 4")
              .status == 0);
  const render::Image sheet = render::read_png(dir + "/s.png");
  // Each tile's centre column holds surface, and the cross between the tiles is background.
  for (int tile = 0; tile < 4; ++tile) {
    const int x0 = (tile % 2) * 100, y0 = (tile / 2) * 80;
    int surface = 0;
    for (int y = y0; y < y0 + 80; ++y)
      surface += sheet.pixel(x0 + 50, y)[0] > sheet.pixel(x0 + 50, y)[2] + 30;
    CHECK(surface > 5);
  }
  for (int y = 0; y < 160; ++y) CHECK(sheet.pixel(100, y)[0] > 245);
}

TEST_CASE("nome render colours and background", "[app]") {
  const std::string dir = test::scratch_dir("cli_render_colors");
  REQUIRE(test::run_nome("render " + asset("cube.obj") + " -o " + dir +
                         "/c.png --size 64x48 --background '#102030' --color 0,1,0")
              .status == 0);
  const render::Image image = render::read_png(dir + "/c.png");
  CHECK(int(image.pixel(0, 0)[0]) == 0x10);
  CHECK(int(image.pixel(0, 0)[1]) == 0x20);
  CHECK(int(image.pixel(0, 0)[2]) == 0x30);
  const std::uint8_t* centre = image.pixel(32, 24);
  CHECK(centre[1] > centre[0] + 40);
}

TEST_CASE("nome render refuses bad requests and writes nothing", "[app]") {
  const std::string dir = test::scratch_dir("cli_render_bad");
  const std::string out = " -o " + dir + "/x.png";
  struct Bad {
    std::string arguments;
    int status;
    const char* message;
  };
  const Bad cases[] = {
      {"render " + asset("cube.obj"), 2, "needs -o OUT.png"},
      {"render " + asset("cube.obj") + " -o " + dir + "/x.jpg", 2, "must end in .png"},
      {"render " + asset("cube.obj") + out + " --size 10x", 2, "--size expects WIDTHxHEIGHT"},
      {"render " + asset("cube.obj") + out + " --size 4x4", 2, "between 16 and 8192"},
      {"render " + asset("cube.obj") + out + " --view 30", 2, "--view expects AZ,EL"},
      {"render " + asset("cube.obj") + out + " --view 0,100", 2, "elevation must be between"},
      {"render " + asset("cube.obj") + out + " --views 40", 2, "--views must be between 1 and 16"},
      {"render " + asset("cube.obj") + out + " --background mauve", 2, "--background expects a colour"},
      {"render " + asset("cube.obj") + out + " --backend vulkan", 2,
       "--backend: unknown backend 'vulkan' (expected egl, egl-device or osmesa)"},
      {"render " + asset("cube.obj") + out + " --stage sculpted", 2, "--stage expects scene, merged"},
      {"render " + asset("cube.obj") + out + " --stage offset --offset 0", 2, "--offset expects a positive"},
      {"render " + asset("cube.obj") + out + " --fit --distance 3", 2, "cannot be combined"},
      {"render " + asset("cube.obj") + out + " --distance -1", 2, "--distance must be positive"},
      {"render " + asset("cube.obj") + out + " --target 1,2", 2, "--target expects X,Y,Z"},
      {"render " + dir + "/missing.obj" + out, 1, "missing.obj"},
  };
  for (const Bad& bad : cases) {
    INFO(bad.arguments);
    const test::CommandResult r = test::run_nome_in_process(bad.arguments);
    CHECK(r.status == bad.status);
    CHECK(r.err.find(bad.message) != std::string::npos);
    CHECK(std::filesystem::is_empty(dir));
  }
  CHECK(test::run_nome("render " + asset("cube.obj") + out + " --stage scene").status == 0);
}

TEST_CASE("nome render --target and --distance replace the fitted framing", "[app]") {
  const std::string dir = test::scratch_dir("cli_render_camera");
  auto surface_pixels = [&](const std::string& options) {
    const test::CommandResult r =
        test::run_nome("render " + asset("torus.obj") + " -o " + dir + "/t.png --size 96x72 " + options);
    REQUIRE(r.status == 0);
    return test::count_sides(render::read_png(dir + "/t.png")).front;
  };
  const int fitted = surface_pixels("--fit");
  CHECK(fitted > 1000);
  CHECK(surface_pixels("") == fitted);
  CHECK(surface_pixels("--distance 40") < fitted / 4);
  CHECK(surface_pixels("--target 30,0,0") == 0);  // looking far beside the torus
}

TEST_CASE("nome render --stage scene shows the parts before --merge glues them", "[app]") {
  const std::string dir = test::scratch_dir("cli_render_stage");
  std::ofstream(dir + "/a.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
  std::ofstream(dir + "/b.obj") << "v 1 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\nf 1 2 3 4\n";
  // Border edges are green: the shared middle edge is a border only before the merge.
  auto border_pixels_in_middle = [&](const std::string& stage) {
    const test::CommandResult r =
        test::run_nome("render " + dir + "/a.obj " + dir + "/b.obj -o " + dir +
                       "/s.png --size 128x96 --view 0,0 --merge --borders --stage " + stage);
    INFO(r.err);
    REQUIRE(r.status == 0);
    const render::Image image = render::read_png(dir + "/s.png");
    int green = 0;
    for (int y = 20; y < 76; ++y)
      for (int x = 60; x < 68; ++x) green += image.pixel(x, y)[1] > image.pixel(x, y)[0] + 60;
    return green;
  };
  CHECK(border_pixels_in_middle("scene") > 50);
  CHECK(border_pixels_in_middle("merged") == 0);
}

TEST_CASE("nome render draws a scene's polylines, framed, as the viewer does", "[app]") {
  // A scene of one closed polyline and no faces: before, a blank picture.
  const std::string dir = test::scratch_dir("cli_render_polylines");
  std::ofstream(dir + "/square.nome") << "point a (0 0 0) endpoint point b (1 0 0) endpoint\n"
                                         "point c (1 1 0) endpoint point d (0 1 0) endpoint\n"
                                         "polyline sq (a b c d) isloop endpolyline\n"
                                         "instance s sq endinstance\n";
  const test::CommandResult r =
      test::run_nome("render " + dir + "/square.nome -o " + dir + "/sq.png --size 200x150 --view 0,0");
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK_THAT(r.err, Catch::Contains("0 faces, 4 polyline segments"));
  const render::Image image = render::read_png(dir + "/sq.png");
  // The rim colour (teal) in each quarter of the picture: the square's four sides, fitted to the view.
  int quarters[4] = {};
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      if (is_rim_color(image.pixel(x, y)))
        ++quarters[(x < image.width / 2 ? 0 : 1) + (y < image.height / 2 ? 0 : 2)];
    }
  for (int q : quarters) CHECK(q > 50);
  // A turntable's frames draw them too.
  const test::CommandResult turning = test::run_nome("render " + dir + "/square.nome -o " + dir +
                                                     "/turn.png --size 200x150 --turntable 4 --sheet");
  REQUIRE(turning.status == 0);
  const render::Image sheet = render::read_png(dir + "/turn.png");
  int teal = 0;
  for (int y = 0; y < sheet.height; ++y)
    for (int x = 0; x < sheet.width; ++x) teal += is_rim_color(sheet.pixel(x, y)) ? 1 : 0;
  CHECK(teal > 100);
}
