#include "render/image_diff.hpp"

#include <algorithm>
#include <cstdlib>

namespace nome::render {

ImageDifference compare_images(const Image& expected, const Image& actual, int tolerance) {
  ImageDifference result;
  result.same_size = expected.width == actual.width && expected.height == actual.height;
  if (!result.same_size) return result;
  result.picture = Image(expected.width, expected.height);
  for (int y = 0; y < expected.height; ++y) {
    for (int x = 0; x < expected.width; ++x) {
      const std::uint8_t* a = expected.pixel(x, y);
      const std::uint8_t* b = actual.pixel(x, y);
      int largest = 0;
      for (int k = 0; k < 4; ++k) largest = std::max(largest, std::abs(int(a[k]) - int(b[k])));
      result.largest_difference = std::max(result.largest_difference, largest);
      std::uint8_t* out = result.picture.pixel(x, y);
      if (largest > tolerance) {
        ++result.differing_pixels;
        out[0] = 255, out[1] = 0, out[2] = 0, out[3] = 255;
      } else {
        const auto grey = std::uint8_t(192 + (int(a[0]) + int(a[1]) + int(a[2])) / 12);
        out[0] = out[1] = out[2] = grey, out[3] = 255;
      }
    }
  }
  const double total = double(expected.width) * double(expected.height);
  result.differing_fraction = total > 0 ? double(result.differing_pixels) / total : 0.0;
  return result;
}

}  // namespace nome::render
