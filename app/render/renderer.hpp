#pragma once

#include <memory>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include "render/camera.hpp"
#include "render/cube_set.hpp"
#include "render/display_settings.hpp"
#include "render/line_set.hpp"
#include "render/mesh_buffers.hpp"
#include "render/shader_program.hpp"

namespace nome::render {

// Draws meshes and overlays with the shaders in shaders/ into whatever framebuffer is bound: the
// window's (viewer) or an offscreen one (`nome render`, tests). Needs a current GL 3.3 core or GLES 3.0
// (WebGL2) context. Each shader program compiles on its first use; a shader that does not compile throws
// Error from that draw call, with the compiler's log.
class Renderer {
 public:
  // One frame's (or one tile's) view: where in the framebuffer, and through which camera.
  struct Frame {
    glm::ivec2 origin{0, 0};  // lower-left corner in framebuffer pixels
    glm::ivec2 size{1, 1};
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    float pixel_scale = 1.0f;  // multiplies line widths (see DisplaySettings)

    static Frame of(const Camera& camera, glm::ivec2 origin, glm::ivec2 size);
  };

  explicit Renderer(GlslDialect dialect = built_dialect);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Sets the viewport and clears it (only it) to the background colour.
  void begin(const Frame& frame, const glm::vec4& background) const;
  // The surface with two-sided lighting, then the wireframe, border and Möbius-edge overlays asked for.
  void draw_mesh(const MeshBuffers& mesh, const Frame& frame, const DisplaySettings& settings) const;
  void draw_lines(const LineSet& lines, const Frame& frame, const glm::vec4& color, float width) const;
  void draw_cubes(const CubeSet& cubes, const Frame& frame) const;

 private:
  void draw_segments(const SegmentSource& segments, const Frame& frame, const glm::vec4& color,
                     float width) const;

  struct Programs;
  std::unique_ptr<Programs> programs_;
};

}  // namespace nome::render
