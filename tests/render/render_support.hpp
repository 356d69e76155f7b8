#pragma once

#include "nome/mesh/mesh.hpp"
#include "render/image.hpp"
#include "render/snapshot.hpp"

namespace nome::test {

// Pixels of the two default surface colours: gold in front, blue behind (white background).
struct SideCounts {
  int front = 0;
  int back = 0;
  int background = 0;
};
SideCounts count_sides(const render::Image& image);
// Back-colour pixels with no background pixel within `margin` pixels: away from the outline, where the back
// faces near a polygon mesh's contour can cover a pixel that its front faces miss.
int count_back_pixels_inside(const render::Image& image, int margin = 2);

// A small snapshot (256x192 unless told) in a fresh offscreen context.
render::Image render_small(const Mesh& mesh, render::SnapshotOptions options = {}, int width = 256,
                           int height = 192);

}  // namespace nome::test
