#include "nome/error.hpp"
#include "render/scene_renderer.hpp"

namespace nome::render {
namespace {

// Keeps nothing: the viewer's logic never reads back from its renderer but for a screenshot.
class NullSceneRenderer final : public SceneRenderer {
 public:
  void set_mesh(const MeshDisplayData&) override {}
  void set_face_colors(std::span<const std::array<std::uint8_t, 4>>) override {}
  void set_selected_faces(std::span<const Index>) override {}
  void set_markers(std::span<const CubeMarker>) override {}
  void set_lines(Overlay, std::span<const glm::vec3>, std::span<const std::uint32_t>,
                 std::span<const glm::vec4>) override {}
  void draw(const Camera&, glm::ivec2, const PixelRect&, const DisplaySettings&) override {}
  Image read_pixels(glm::ivec2) const override {
    throw Error("screenshot: the null renderer draws no picture");
  }
};

}  // namespace

std::unique_ptr<SceneRenderer> make_null_scene_renderer() {
  return std::make_unique<NullSceneRenderer>();
}

}  // namespace nome::render
