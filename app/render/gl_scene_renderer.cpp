#include <algorithm>

#include "render/cube_set.hpp"
#include "render/line_set.hpp"
#include "render/mesh_buffers.hpp"
#include "render/renderer.hpp"
#include "render/scene_renderer.hpp"

namespace nome::render {
namespace {

class GlSceneRenderer final : public SceneRenderer {
 public:
  void set_mesh(const MeshDisplayData& data) override {
    // The same topology (a slider that moved vertices): positions, normals and colours in place.
    if (buffers_ && &buffers_->topology() == data.topology.get()) {
      buffers_->update_positions(*data.positions);
      buffers_->set_face_colors(data.face_colors);
    } else {
      buffers_ = std::make_unique<MeshBuffers>(data);
    }
  }
  void set_face_colors(std::span<const std::array<std::uint8_t, 4>> colors) override {
    if (buffers_) buffers_->set_face_colors(colors);
  }
  void set_selected_faces(std::span<const Index> faces) override {
    if (buffers_) buffers_->set_selected_faces(faces);
  }
  void set_markers(std::span<const CubeMarker> markers) override { cubes_.set(markers); }
  void set_lines(Overlay overlay, std::span<const glm::vec3> points, std::span<const std::uint32_t> segments,
                 std::span<const glm::vec4> colors) override {
    (overlay == Overlay::rim     ? rim_lines_
     : overlay == Overlay::sharp ? sharp_lines_
                                 : selection_lines_)
        .set(points, segments, colors);
  }

  void draw(const Camera& camera, glm::ivec2 framebuffer_size, const PixelRect& viewport,
            const DisplaySettings& display) override {
    // One clear of the whole framebuffer covers the viewport too: a multisampled clear costs llvmpipe
    // a pass over four samples per pixel.
    renderer_.begin(Renderer::Frame::of(camera, {0, 0}, glm::max(framebuffer_size, {1, 1})),
                    display.background);
    const Renderer::Frame frame =
        Renderer::Frame::of(camera, viewport.origin, glm::max(viewport.size, {1, 1}));
    if (!buffers_) return;
    renderer_.draw_mesh(*buffers_, frame, display);
    renderer_.draw_cubes(cubes_, frame);
    renderer_.draw_lines(rim_lines_, frame, glm::vec4(display.rim_color, 1.0f), display.highlight_width);
    renderer_.draw_lines(sharp_lines_, frame, glm::vec4(display.sharp_color, 1.0f), display.highlight_width);
    renderer_.draw_lines(selection_lines_, frame, glm::vec4(display.selection_color, 1.0f),
                         display.highlight_width * 1.5f);
  }

  Image read_pixels(glm::ivec2 size) const override {
    Image image(size.x, size.y);
    std::vector<std::uint8_t> rows(image.rgba.size());
    // A window's picture is in its back buffer until the swap; a framebuffer object's in its colour.
    GLint bound = 0;
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &bound);
    glReadBuffer(bound == 0 ? GL_BACK : GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, size.x, size.y, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
    // GL reads bottom row first; PNG stores the top row first.
    const std::size_t stride = std::size_t(size.x) * 4;
    for (int y = 0; y < size.y; ++y)
      std::copy_n(rows.data() + std::size_t(size.y - 1 - y) * stride, stride, image.rgba.data() + y * stride);
    for (std::size_t i = 3; i < image.rgba.size(); i += 4) image.rgba[i] = 255;
    return image;
  }

 private:
  Renderer renderer_;
  std::unique_ptr<MeshBuffers> buffers_;
  CubeSet cubes_;
  LineSet rim_lines_, selection_lines_, sharp_lines_;
};

}  // namespace

std::unique_ptr<SceneRenderer> make_gl_scene_renderer() {
  return std::make_unique<GlSceneRenderer>();
}

}  // namespace nome::render
