// The turntable's contact sheet: the frames in rows, the last row's empty tiles in the background colour.
#include <catch2/catch.hpp>

#include <array>
#include <cstdint>
#include <vector>

#include "render/turntable.hpp"

using namespace nome::render;

namespace {

Image filled(int width, int height, std::array<std::uint8_t, 4> color) {
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int k = 0; k < 4; ++k) image.pixel(x, y)[k] = color[std::size_t(k)];
  return image;
}

}  // namespace

TEST_CASE("a contact sheet puts the frames in rows and fills the tiles left over with the background",
          "[render]") {
  const int w = 5, h = 3;
  const std::vector<std::array<std::uint8_t, 4>> colors{
      {10, 20, 30, 255}, {40, 50, 60, 255}, {70, 80, 90, 255}, {100, 110, 120, 255}, {130, 140, 150, 255}};
  for (const int count : {1, 2, 3, 5}) {
    INFO(count << " frames");
    std::vector<Image> frames;
    for (int i = 0; i < count; ++i) frames.push_back(filled(w, h, colors[std::size_t(i)]));
    // The first frame's corner is the background: the empty tiles take it.
    frames[0].pixel(0, 0)[0] = 255;
    const Image sheet = contact_sheet(frames);
    const int columns = count == 1 ? 1 : count <= 4 ? 2 : 3;
    const int rows = (count + columns - 1) / columns;
    REQUIRE(sheet.width == columns * w);
    REQUIRE(sheet.height == rows * h);
    REQUIRE(sheet.rgba.size() == std::size_t(sheet.width) * std::size_t(sheet.height) * 4);
    for (int tile = 0; tile < rows * columns; ++tile)
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          const std::uint8_t* p = sheet.pixel((tile % columns) * w + x, (tile / columns) * h + y);
          const std::uint8_t* expected =
              tile < count ? frames[std::size_t(tile)].pixel(x, y) : frames[0].pixel(0, 0);
          INFO("tile " << tile << " at " << x << ", " << y);
          CHECK(std::vector<std::uint8_t>(p, p + 4) == std::vector<std::uint8_t>(expected, expected + 4));
        }
  }
  CHECK_THROWS_WITH(contact_sheet({}), "contact_sheet: no frames");
}
