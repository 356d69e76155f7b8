#include <catch2/catch.hpp>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli_support.hpp"
#include "app/screen_oracle.hpp"
#include "render/camera.hpp"
#include "render/image.hpp"

using namespace nome;

namespace {

// The runs of the section's colour (DisplaySettings::section_color, drawn flat) along row y: [first, last].
std::vector<std::pair<int, int>> section_runs(const render::Image& image, int y) {
  std::vector<std::pair<int, int>> runs;
  bool is_in = false;
  for (int x = 0; x < image.width; ++x) {
    const std::uint8_t* p = image.pixel(x, y);
    const bool is_cut = std::abs(p[0] - 219) < 12 && std::abs(p[1] - 41) < 12 && std::abs(p[2] - 51) < 12;
    if (is_cut && !is_in) runs.push_back({x, x});
    if (is_cut) runs.back().second = x;
    is_in = is_cut;
  }
  return runs;
}

}  // namespace

TEST_CASE("nome render --section cuts the offset torus and fills its wall: bands of the slab's thickness",
          "[app]") {
  const std::string dir = test::private_scratch_dir("cli_section");
  const std::string torus = std::string(NOME_SOURCE_DIR) + "/assets/torus.obj";
  const double d = 0.05;
  const auto r = test::run_nome_in_process(
      "render " + torus + " --offset 0.05 --section z=0 --view 0,0 --size 800x800 -o " + dir + "/cut.png");
  INFO(r.err);
  REQUIRE(r.status == 0);
  const render::Image cut = render::read_png(dir + "/cut.png");
  const auto runs = section_runs(cut, 400);
  // The plane through the tube's middle crosses the slab four times along the row through the centre.
  REQUIRE(runs.size() == 4);
  // The outermost cut pixels are 2 (1.35 + d) apart (the torus reaches 1.35 from its axis).
  const double pixels_per_unit = (runs.back().second - runs.front().first + 1) / (2.0 * (1.35 + d));
  for (const auto& [first, last] : runs) {
    INFO(first << ".." << last);
    CHECK(std::abs((last - first + 1) - 2.0 * d * pixels_per_unit) <= 2.0);
  }

  const auto surface = test::run_nome_in_process(
      "render " + torus + " --section z=0 --view 0,0 --size 200x200 -o " + dir + "/surface.png");
  REQUIRE(surface.status == 0);
  CHECK(section_runs(render::read_png(dir + "/surface.png"), 100).empty());  // a surface has no inside
  CHECK(test::run_nome_in_process("render " + torus + " --section w -o " + dir + "/x.png").status == 2);
}

namespace {

// Two flat squares off the origin: one in z = 0 (x 0..2, y 1..3) seen from +z, one in y = 0 (x 0..2,
// z -3..-1) seen from above, each filling the picture; a cut is where the picture shows background.
constexpr int section_size = 400;

struct SectionScene {
  std::string obj;  // the file's text
  double azimuth;   // the view that sees the square face on
  double elevation;
  std::vector<nome::Vec3> corners;
};

const SectionScene square_in_z{"v 0 1 0\nv 2 1 0\nv 2 3 0\nv 0 3 0\nf 1 2 3 4\n",
                               0.0,
                               0.0,
                               {{0, 1, 0}, {2, 1, 0}, {2, 3, 0}, {0, 3, 0}}};
const SectionScene square_in_y{"v 0 0 -3\nv 0 0 -1\nv 2 0 -1\nv 2 0 -3\nf 1 2 3 4\n",
                               0.0,
                               90.0,
                               {{0, 0, -3}, {0, 0, -1}, {2, 0, -1}, {2, 0, -3}}};

// Renders the square cut by --section SECTION and tells for each point whether the picture shows the
// surface at the pixel the camera's own matrices put it (true) or the white background (false).
std::vector<bool> shown_after_section(const std::string& dir, const SectionScene& scene,
                                      const std::string& section, const std::vector<nome::Vec3>& points) {
  std::ofstream(dir + "/square.obj") << scene.obj;
  std::ostringstream view;
  view << scene.azimuth << "," << scene.elevation;
  const auto r = test::run_nome_in_process({"render", dir + "/square.obj", "--section", section, "--view",
                                            view.str(), "--size", "400x400", "-o", dir + "/cut.png"});
  INFO(r.err);
  REQUIRE(r.status == 0);
  const render::Image image = render::read_png(dir + "/cut.png");
  render::Camera camera;
  camera.set_view(scene.azimuth, scene.elevation);
  camera.fit(scene.corners, 1.0);
  const ScreenProjection projection = camera.screen_projection({section_size, section_size});
  std::vector<bool> shown;
  for (const nome::Vec3& p : points) {
    const auto at = test::pixel_of(projection, p);
    REQUIRE(at);
    const std::uint8_t* rgb = image.pixel(int(at->x), int(at->y));
    shown.push_back(!(rgb[0] > 245 && rgb[1] > 245 && rgb[2] > 245));
  }
  return shown;
}

}  // namespace

// The plane axis = AT cuts away where the coordinate exceeds AT, for AT anywhere (the middle when not
// given), along each axis: points a quarter unit or more either side of it are kept or cut.
TEST_CASE("nome render --section cuts at the plane it names along x, y and z, off the origin", "[app]") {
  const std::string dir = test::private_scratch_dir("cli_section_planes");
  using Points = std::vector<nome::Vec3>;
  using Shown = std::vector<bool>;
  SECTION("x = 0.5 and x = 1.4 on the square in z = 0") {
    const Points points = {{0.25, 2, 0}, {0.75, 2, 0}, {1.15, 1.5, 0}, {1.65, 2.5, 0}};
    CHECK(shown_after_section(dir, square_in_z, "x=0.5", points) == Shown{true, false, false, false});
    CHECK(shown_after_section(dir, square_in_z, "x=1.4", points) == Shown{true, true, true, false});
  }
  SECTION("y = 2.6 and y = 1.3 on the square in z = 0") {
    const Points points = {{1, 1.1, 0}, {0.5, 1.55, 0}, {1.5, 2.35, 0}, {1, 2.85, 0}};
    CHECK(shown_after_section(dir, square_in_z, "y=2.6", points) == Shown{true, true, true, false});
    CHECK(shown_after_section(dir, square_in_z, "y=1.3", points) == Shown{true, false, false, false});
  }
  SECTION("z = -1.6 and z = -2.4 on the square in y = 0") {
    const Points points = {{1, 0, -2.8}, {1, 0, -2.1}, {0.5, 0, -1.85}, {1.5, 0, -1.3}};
    CHECK(shown_after_section(dir, square_in_y, "z=-1.6", points) == Shown{true, true, true, false});
    CHECK(shown_after_section(dir, square_in_y, "z=-2.4", points) == Shown{true, false, false, false});
  }
  SECTION("without AT, the middle of the mesh's extent: x = 1, y = 2, z = -2") {
    const Points in_z = {{0.7, 1.2, 0}, {1.3, 1.2, 0}, {0.2, 1.7, 0}, {0.2, 2.3, 0}};
    CHECK(shown_after_section(dir, square_in_z, "x", in_z) == Shown{true, false, true, true});
    CHECK(shown_after_section(dir, square_in_z, "y", in_z) == Shown{true, true, true, false});
    const Points in_y = {{1, 0, -2.3}, {1, 0, -1.7}};
    CHECK(shown_after_section(dir, square_in_y, "z", in_y) == Shown{true, false});
  }
}
