#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <span>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "nome/mesh/types.hpp"
#include "render/camera.hpp"
#include "render/cube_set.hpp"
#include "render/display_settings.hpp"
#include "render/image.hpp"
#include "render/mesh_display_data.hpp"

namespace nome::render {

// Where in the framebuffer the scene goes: lower-left corner and size in framebuffer pixels (GL's
// convention); the rest of the framebuffer is cleared to the background for the panels around it.
struct PixelRect {
  glm::ivec2 origin{0, 0};
  glm::ivec2 size{1, 1};
};

// The line overlays the viewer keeps on the GPU beside the mesh.
enum class Overlay { rim, selection, sharp };

// What the viewer draws, behind an interface (polyscope's render engine): the GL backend draws into the
// current context (a GLFW window, or an EGL / OSMesa framebuffer); the null backend draws nothing, so
// the viewer's logic runs in tests without a display or a context.
class SceneRenderer {
 public:
  virtual ~SceneRenderer() = default;

  // Replaces the displayed mesh (face colours and selection start from the data's own). Data of the
  // topology on display (the same DisplayTopology) only updates its positions, normals and colours.
  virtual void set_mesh(const MeshDisplayData& data) = 0;
  // Per-face RGBA colours (alpha 0: the display's front colour): one per face of the mesh, or none.
  virtual void set_face_colors(std::span<const std::array<std::uint8_t, 4>> colors) = 0;
  virtual void set_selected_faces(std::span<const Index> faces) = 0;
  virtual void set_markers(std::span<const CubeMarker> markers) = 0;
  // `segments` holds two indices into `points` per segment; `colors`, empty or one per point, as
  // LineSet::set takes them.
  virtual void set_lines(Overlay overlay, std::span<const glm::vec3> points,
                         std::span<const std::uint32_t> segments, std::span<const glm::vec4> colors = {}) = 0;

  // Clears the framebuffer and draws the mesh, the markers and the overlays into the viewport.
  virtual void draw(const Camera& camera, glm::ivec2 framebuffer_size, const PixelRect& viewport,
                    const DisplaySettings& display) = 0;
  // The picture drawn so far (a screenshot); throws Error when the backend has none.
  virtual Image read_pixels(glm::ivec2 framebuffer_size) const = 0;
};

// Needs a current GL 3.3 core context with glad loaded for its whole life.
std::unique_ptr<SceneRenderer> make_gl_scene_renderer();
std::unique_ptr<SceneRenderer> make_null_scene_renderer();

}  // namespace nome::render
