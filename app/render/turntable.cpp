#include "render/turntable.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "nome/error.hpp"
#include "render/camera.hpp"
#include "render/framebuffer.hpp"
#include "render/line_set.hpp"
#include "render/mesh_buffers.hpp"
#include "render/mesh_display_data.hpp"
#include "render/renderer.hpp"

namespace nome::render {

std::vector<Image> render_turntable(const Mesh& mesh, const SnapshotOptions& options, int frames) {
  if (frames < 1) throw InvalidInputError("render_turntable: at least one frame");
  const ViewAngle first = options.views.empty() ? ViewAngle{} : options.views.front();
  const std::vector<ViewAngle> views = views_around(first, frames);
  const double aspect = double(options.width) / double(options.height);
  // One framing for all: the centre of the box, and the farthest distance any azimuth's fit asks for.
  const std::vector<Vec3> framed = framed_points(mesh, options);
  glm::dvec3 low(0.0), high(0.0);
  if (!framed.empty()) low = high = framed.front();
  for (const Vec3& p : framed) low = glm::min(low, p), high = glm::max(high, p);
  const glm::dvec3 centre = options.target.value_or(0.5 * (low + high));
  double distance = 0.0;
  for (const ViewAngle& view : views) {
    Camera camera;
    camera.lens = options.lens;
    camera.set_view(view.azimuth, view.elevation);
    camera.fit(framed, aspect);
    distance = std::max(distance, camera.distance + glm::length(camera.target - centre));
  }
  if (options.distance) distance = *options.distance;

  const Renderer renderer;
  const MeshBuffers buffers(build_display_data(mesh));
  LineSet rims;
  rims.set(options.rims.points, options.rims.segments, options.rims.colors);
  const Framebuffer framebuffer(options.width, options.height, options.samples);
  framebuffer.bind();
  const glm::vec4 background = options.is_transparent ? glm::vec4(0.0f) : options.display.background;
  std::vector<Image> out;
  for (const ViewAngle& view : views) {
    Camera camera;
    camera.lens = options.lens;
    camera.set_view(view.azimuth, view.elevation);
    camera.target = centre;
    camera.distance = distance;
    const Renderer::Frame frame = Renderer::Frame::of(camera, {0, 0}, {options.width, options.height});
    renderer.begin(frame, background);
    renderer.draw_mesh(buffers, frame, options.display);
    renderer.draw_lines(rims, frame, glm::vec4(options.display.rim_color, 1.0f),
                        options.display.highlight_width);
    out.push_back(framebuffer.read(options.is_transparent));
  }
  return out;
}

Image contact_sheet(const std::vector<Image>& frames) {
  if (frames.empty()) throw InvalidInputError("contact_sheet: no frames");
  const int count = int(frames.size());
  const int columns = int(std::ceil(std::sqrt(double(count))));
  const int rows = (count + columns - 1) / columns;
  const int w = frames[0].width, h = frames[0].height;
  Image sheet(columns * w, rows * h);
  for (int i = 0; i < count; ++i)
    for (int y = 0; y < h; ++y)
      std::memcpy(sheet.pixel((i % columns) * w, (i / columns) * h + y), frames[std::size_t(i)].pixel(0, y),
                  std::size_t(w) * 4);
  // Tiles left empty at the end of the last row take the first frame's corner colour (the background).
  const std::uint8_t* corner = frames[0].pixel(0, 0);
  for (int i = count; i < rows * columns; ++i)
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        std::memcpy(sheet.pixel((i % columns) * w + x, (i / columns) * h + y), corner, 4);
  return sheet;
}

}  // namespace nome::render
