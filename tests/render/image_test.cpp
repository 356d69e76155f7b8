#include <catch2/catch.hpp>

#include <fstream>

#include "app/cli_support.hpp"
#include "nome/error.hpp"
#include "render/image.hpp"
#include "render/image_diff.hpp"

using namespace nome;

TEST_CASE("PNG round trip keeps every byte, alpha included", "[render]") {
  render::Image image(5, 3);
  for (std::size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = std::uint8_t(i * 37);
  const std::string path = test::scratch_dir("png") + "/a.png";
  render::write_png(path, image);
  const render::Image back = render::read_png(path);
  CHECK(back.width == 5);
  CHECK(back.height == 3);
  CHECK(back.rgba == image.rgba);
}

TEST_CASE("a PNG that cannot be written leaves nothing behind", "[render]") {
  const std::string dir = test::scratch_dir("png_fail");
  CHECK_THROWS_AS(render::write_png(dir + "/missing/a.png", render::Image(2, 2)), IoError);
  CHECK(std::filesystem::is_empty(dir));
  std::ofstream(dir + "/not.png") << "text";
  CHECK_THROWS_AS(render::read_png(dir + "/not.png"), IoError);
}

TEST_CASE("image comparison counts pixels beyond the tolerance", "[render]") {
  render::Image a(4, 4), b(4, 4);
  b.pixel(1, 2)[0] = 10;  // within a tolerance of 12
  b.pixel(3, 3)[2] = 200;
  const render::ImageDifference d = render::compare_images(a, b, 12);
  CHECK(d.same_size);
  CHECK(d.differing_pixels == 1);
  CHECK(d.largest_difference == 200);
  CHECK(d.differing_fraction == Approx(1.0 / 16));
  CHECK(d.picture.pixel(3, 3)[0] == 255);
  CHECK(d.picture.pixel(3, 3)[1] == 0);
  CHECK_FALSE(render::compare_images(a, render::Image(4, 5), 12).same_size);
}
