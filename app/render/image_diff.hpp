#pragma once

#include <cstddef>

#include "render/image.hpp"

namespace nome::render {

struct ImageDifference {
  bool same_size = false;
  std::size_t differing_pixels = 0;  // pixels with a channel off by more than the tolerance
  int largest_difference = 0;        // the largest channel difference anywhere (0..255)
  double differing_fraction = 1.0;
  Image picture;  // the expected image faded, with differing pixels in red (empty if sizes differ)
};

// Compares two renders channel by channel (RGBA). Software rasterizers are deterministic on one
// machine, but Mesa updates move antialiased edges a little: callers accept a small fraction.
ImageDifference compare_images(const Image& expected, const Image& actual, int tolerance);

}  // namespace nome::render
