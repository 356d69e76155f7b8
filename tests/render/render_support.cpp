#include "render/render_support.hpp"

#include <algorithm>

#include "render/offscreen_context.hpp"

namespace nome::test {

namespace {

bool is_background(const std::uint8_t* p) {
  return p[0] > 245 && p[1] > 245 && p[2] > 245;
}
bool is_back(const std::uint8_t* p) {
  return !is_background(p) && p[2] > p[0] + 30;
}

}  // namespace

SideCounts count_sides(const render::Image& image) {
  SideCounts counts;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      if (is_background(p))
        ++counts.background;
      else if (p[0] > p[2] + 30)
        ++counts.front;
      else if (is_back(p))
        ++counts.back;
    }
  }
  return counts;
}

int count_back_pixels_inside(const render::Image& image, int margin) {
  int count = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      if (!is_back(image.pixel(x, y))) continue;
      bool near_background = false;
      for (int dy = -margin; dy <= margin && !near_background; ++dy)
        for (int dx = -margin; dx <= margin && !near_background; ++dx) {
          const int u = std::clamp(x + dx, 0, image.width - 1), v = std::clamp(y + dy, 0, image.height - 1);
          near_background = is_background(image.pixel(u, v));
        }
      count += near_background ? 0 : 1;
    }
  return count;
}

render::Image render_small(const Mesh& mesh, render::SnapshotOptions options, int width, int height) {
  const render::OffscreenContext context;
  options.width = width;
  options.height = height;
  return render::render_snapshot(mesh, options);
}

}  // namespace nome::test
