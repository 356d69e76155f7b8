#include <catch2/catch.hpp>

#include <cstdlib>
#include <vector>

#include "app/cli_support.hpp"
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
