#include "render/render_support.hpp"

#include "render/offscreen_context.hpp"

namespace nome::test {

SideCounts count_sides(const render::Image& image) {
  SideCounts counts;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      if (p[0] > 245 && p[1] > 245 && p[2] > 245)
        ++counts.background;
      else if (p[0] > p[2] + 30)
        ++counts.front;
      else if (p[2] > p[0] + 30)
        ++counts.back;
    }
  }
  return counts;
}

render::Image render_small(const Mesh& mesh, render::SnapshotOptions options, int width, int height) {
  const render::OffscreenContext context;
  options.width = width;
  options.height = height;
  return render::render_snapshot(mesh, options);
}

}  // namespace nome::test
