#include "render/renderer.hpp"

#include <array>
#include <string>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "render/shader_program.hpp"

namespace nome::render {
namespace {

// The features of mesh.frag, one bit each in a variant's number.
constexpr std::array<const char*, 6> mesh_features = {"FLAT_NORMALS", "DIFFERENT_BACK_COLOR", "FACE_COLORS",
                                                      "SELECTION",    "FILLS_SECTION",        "SCENE_LIGHTS"};

unsigned mesh_variant(const MeshBuffers& mesh, const DisplaySettings& settings) {
  const bool flags[] = {settings.shading == Shading::flat,
                        settings.back_faces == BackFacePolicy::different,
                        settings.uses_face_colors && mesh.has_face_colors(),
                        mesh.has_selection(),
                        settings.fills_section && settings.section_plane != glm::vec4(0.0f),
                        settings.lights.is_used};
  unsigned variant = 0;
  for (std::size_t i = 0; i < mesh_features.size(); ++i) variant |= flags[i] ? 1u << i : 0u;
  return variant;
}

}  // namespace

// Each program is compiled on first use: a render without overlays never pays for the others, and the
// mesh program only for the sets of features drawn (mesh.frag says why).
struct Renderer::Programs {
  const ShaderProgram& mesh(unsigned variant) {
    std::unique_ptr<ShaderProgram>& program = mesh_.at(variant);
    if (!program) {
      std::string defines;
      for (std::size_t i = 0; i < mesh_features.size(); ++i)
        if (variant & (1u << i)) defines += std::string("#define ") + mesh_features[i] + "\n";
      program = std::make_unique<ShaderProgram>(
          "mesh",
          std::vector<ShaderStage>{{GL_VERTEX_SHADER, {"mesh.vert"}},
                                   {GL_FRAGMENT_SHADER, {"lighting.glsl", "mesh.frag"}}},
          defines);
    }
    return *program;
  }
  const ShaderProgram& lines() {
    if (!lines_)
      lines_ = std::make_unique<ShaderProgram>(
          "lines", std::vector<ShaderStage>{{GL_VERTEX_SHADER, {"lines.vert"}},
                                            {GL_GEOMETRY_SHADER, {"lines.geom"}},
                                            {GL_FRAGMENT_SHADER, {"lines.frag"}}});
    return *lines_;
  }
  const ShaderProgram& cubes() {
    if (!cubes_)
      cubes_ = std::make_unique<ShaderProgram>(
          "cubes", std::vector<ShaderStage>{{GL_VERTEX_SHADER, {"cubes.vert"}},
                                            {GL_FRAGMENT_SHADER, {"lighting.glsl", "cubes.frag"}}});
    return *cubes_;
  }

 private:
  std::array<std::unique_ptr<ShaderProgram>, 1u << mesh_features.size()> mesh_;
  std::unique_ptr<ShaderProgram> lines_, cubes_;
};

Renderer::Frame Renderer::Frame::of(const Camera& camera, glm::ivec2 origin, glm::ivec2 size) {
  Frame frame;
  frame.origin = origin;
  frame.size = glm::max(size, glm::ivec2(1));
  frame.view = camera.view_matrix();
  frame.projection = camera.projection_matrix(double(frame.size.x) / double(frame.size.y));
  // Line widths are tuned for a picture about 600 pixels high.
  frame.pixel_scale = std::max(1.0f, float(frame.size.y) / 600.0f);
  return frame;
}

Renderer::Renderer() : programs_(std::make_unique<Programs>()) {}

Renderer::~Renderer() = default;

void Renderer::begin(const Frame& frame, const glm::vec4& background) const {
  glViewport(frame.origin.x, frame.origin.y, frame.size.x, frame.size.y);
  glEnable(GL_SCISSOR_TEST);
  glScissor(frame.origin.x, frame.origin.y, frame.size.x, frame.size.y);
  glClearColor(background.r, background.g, background.b, background.a);
  glClearDepth(1.0);
  glDepthMask(GL_TRUE);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glEnable(GL_MULTISAMPLE);
  glDisable(GL_BLEND);
}

void Renderer::draw_mesh(const MeshBuffers& mesh, const Frame& frame, const DisplaySettings& settings) const {
  glViewport(frame.origin.x, frame.origin.y, frame.size.x, frame.size.y);
  if (settings.draws_faces && mesh.triangle_index_count() > 0) {
    const ShaderProgram& p = programs_->mesh(mesh_variant(mesh, settings));
    p.use();
    p.set("model_view", frame.view);
    p.set("projection", frame.projection);
    p.set("front_color", settings.front_color);
    p.set("back_color", settings.back_color);
    p.set("selection_color", settings.selection_color);
    p.set("opacity", 1.0f);
    p.set("section_plane", settings.section_plane);
    p.set("section_color", settings.section_color);
    if (settings.lights.is_used) {
      p.set("scene_ambient", settings.lights.ambient);
      p.set("scene_light_count", settings.lights.count);
      const glm::mat3 to_view(frame.view);
      for (int i = 0; i < settings.lights.count; ++i) {
        const std::string at = "[" + std::to_string(i) + "]";
        p.set(("scene_light_directions" + at).c_str(),
              glm::normalize(to_view * settings.lights.directions[std::size_t(i)]));
        p.set(("scene_light_colors" + at).c_str(), settings.lights.colors[std::size_t(i)]);
      }
    }
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_BUFFER, mesh.face_color_texture());
    p.set("face_colors", 0);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_BUFFER, mesh.face_flag_texture());
    p.set("face_flags", 1);
    glActiveTexture(GL_TEXTURE2);
    glBindTexture(GL_TEXTURE_BUFFER, mesh.face_normal_texture());
    p.set("face_normals", 2);
    glActiveTexture(GL_TEXTURE0);
    if (settings.back_faces == BackFacePolicy::cull) {
      glEnable(GL_CULL_FACE);
      glCullFace(GL_BACK);
      glFrontFace(GL_CCW);
    }
    // Faces step back a little so edges drawn exactly on them win the depth test.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
    glBindVertexArray(mesh.surface_vao());
    // Clipping costs llvmpipe a test of every vertex: only with a section.
    if (settings.section_plane != glm::vec4(0.0f)) glEnable(GL_CLIP_DISTANCE0);
    // Each triangle's first vertex carries its face id (render/mesh_display_data.hpp).
    glProvokingVertex(GL_FIRST_VERTEX_CONVENTION);
    glDrawElements(GL_TRIANGLES, mesh.triangle_index_count(), GL_UNSIGNED_INT, nullptr);
    glProvokingVertex(GL_LAST_VERTEX_CONVENTION);
    glDisable(GL_CLIP_DISTANCE0);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_CULL_FACE);
  }
  if (settings.draws_wireframe)
    draw_segments(mesh.edge_vao(), mesh.all_edges(), frame, settings.wire_color, settings.wire_width);
  if (settings.draws_borders)
    draw_segments(mesh.edge_vao(), mesh.border_edges(), frame, settings.border_color,
                  settings.highlight_width);
  if (settings.draws_mobius_edges)
    draw_segments(mesh.edge_vao(), mesh.mobius_edges(), frame, settings.mobius_color,
                  settings.highlight_width);
  glBindVertexArray(0);
}

void Renderer::draw_segments(GLuint vao, SegmentRange range, const Frame& frame, const glm::vec4& color,
                             float width) const {
  if (range.count == 0) return;
  glViewport(frame.origin.x, frame.origin.y, frame.size.x, frame.size.y);
  const ShaderProgram& p = programs_->lines();
  p.use();
  p.set("model_view", frame.view);
  p.set("projection", frame.projection);
  p.set("depth_bias", 2e-5f);
  p.set("viewport_size", glm::vec2(frame.size));
  p.set("width", width * frame.pixel_scale);
  p.set("color", color);
  const bool is_translucent = color.a < 1.0f;
  if (is_translucent) {
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  }
  glBindVertexArray(vao);
  // Sets without their own colours read this constant for the colour attribute: the uniform wins.
  glVertexAttrib4f(1, 0.0f, 0.0f, 0.0f, 0.0f);
  glDrawElements(GL_LINES, GLsizei(range.count * 2), GL_UNSIGNED_INT,
                 reinterpret_cast<void*>(std::size_t(range.first) * 2 * sizeof(std::uint32_t)));
  glBindVertexArray(0);
  if (is_translucent) glDisable(GL_BLEND);
}

void Renderer::draw_lines(const LineSet& lines, const Frame& frame, const glm::vec4& color,
                          float width) const {
  draw_segments(lines.vao(), {0, std::uint32_t(lines.index_count() / 2)}, frame, color, width);
}

void Renderer::draw_cubes(const CubeSet& cubes, const Frame& frame) const {
  if (cubes.count() == 0) return;
  glViewport(frame.origin.x, frame.origin.y, frame.size.x, frame.size.y);
  const ShaderProgram& p = programs_->cubes();
  p.use();
  p.set("model_view", frame.view);
  p.set("projection", frame.projection);
  glBindVertexArray(cubes.vao());
  glDrawArraysInstanced(GL_TRIANGLES, 0, 36, cubes.count());
  glBindVertexArray(0);
}

}  // namespace nome::render
