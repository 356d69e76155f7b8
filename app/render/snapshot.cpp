#include "render/snapshot.hpp"

#include <cmath>

#include "render/camera.hpp"
#include "render/framebuffer.hpp"
#include "render/line_set.hpp"
#include "render/mesh_buffers.hpp"
#include "render/renderer.hpp"

namespace nome::render {

std::vector<ViewAngle> views_around(ViewAngle first, int count) {
  std::vector<ViewAngle> views;
  for (int i = 0; i < count; ++i)
    views.push_back({std::fmod(first.azimuth + 360.0 * i / count, 360.0), first.elevation});
  return views;
}

std::vector<Vec3> framed_points(const Mesh& mesh, const SnapshotOptions& options) {
  std::vector<Vec3> points(mesh.positions().begin(), mesh.positions().end());
  points.insert(points.end(), options.rims.points.begin(), options.rims.points.end());
  return points;
}

Image render_snapshot(const Mesh& mesh, const SnapshotOptions& options) {
  const Renderer renderer;
  const MeshBuffers buffers(build_display_data(mesh));
  LineSet rims;
  rims.set(options.rims.points, options.rims.segments, options.rims.colors);
  const std::vector<Vec3> framed = framed_points(mesh, options);
  const Framebuffer framebuffer(options.width, options.height, options.samples);
  framebuffer.bind();

  glm::vec4 background = options.display.background;
  // Transparent: clear to zero so resolved edge pixels are premultiplied, which read() undoes.
  if (options.is_transparent) background = glm::vec4(0.0f);
  const int count = std::max<int>(1, int(options.views.size()));
  const int columns = int(std::ceil(std::sqrt(double(count))));
  const int rows = (count + columns - 1) / columns;
  const glm::ivec2 tile(options.width / columns, options.height / rows);
  renderer.begin(Renderer::Frame{{0, 0}, {options.width, options.height}}, background);
  for (int i = 0; i < int(options.views.size()); ++i) {
    Camera camera;
    camera.lens = options.lens;
    camera.set_view(options.views[i].azimuth, options.views[i].elevation);
    camera.fit(framed, double(tile.x) / double(tile.y));
    if (options.target) camera.target = *options.target;
    if (options.distance) camera.distance = *options.distance;
    // Tiles fill rows from the top; GL counts rows from the bottom.
    const glm::ivec2 origin((i % columns) * tile.x, options.height - (i / columns + 1) * tile.y);
    const Renderer::Frame frame = Renderer::Frame::of(camera, origin, tile);
    if (count > 1) renderer.begin(frame, background);
    renderer.draw_mesh(buffers, frame, options.display);
    renderer.draw_lines(rims, frame, glm::vec4(options.display.rim_color, 1.0f),
                        options.display.highlight_width);
  }
  return framebuffer.read(options.is_transparent);
}

}  // namespace nome::render
