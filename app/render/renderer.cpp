#include "render/renderer.hpp"

#include <array>
#include <string>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "render/shader_program.hpp"
#include "render/table_texture.hpp"

namespace nome::render {
namespace {

// The features of mesh.frag, one bit each in a variant's number.
constexpr std::array<const char*, 7> mesh_features = {
    "FLAT_NORMALS", "DIFFERENT_BACK_COLOR", "FACE_COLORS", "SELECTION",
    "SECTION",      "FILLS_SECTION",        "SCENE_LIGHTS"};

// Defines the programs that read table textures need (shaders/tables.glsl).
const std::string table_defines = "#define TABLE_WIDTH_BITS " + std::to_string(table_width_bits) + "\n";

unsigned mesh_variant(const MeshBuffers& mesh, const DisplaySettings& settings) {
  const bool flags[] = {settings.shading == Shading::flat,
                        settings.back_faces == BackFacePolicy::different,
                        settings.uses_face_colors && mesh.has_face_colors(),
                        mesh.has_selection(),
                        settings.section_plane != glm::vec4(0.0f),
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
  explicit Programs(GlslDialect dialect) : dialect_(dialect) {}

  const ShaderProgram& mesh(unsigned variant) {
    std::unique_ptr<ShaderProgram>& program = mesh_.at(variant);
    if (!program) {
      std::string defines = table_defines;
      for (std::size_t i = 0; i < mesh_features.size(); ++i)
        if (variant & (1u << i)) defines += std::string("#define ") + mesh_features[i] + "\n";
      program = std::make_unique<ShaderProgram>(
          "mesh",
          std::vector<ShaderStage>{{GL_VERTEX_SHADER, {"mesh.vert"}},
                                   {GL_FRAGMENT_SHADER, {"tables.glsl", "lighting.glsl", "mesh.frag"}}},
          defines, dialect_);
    }
    return *program;
  }
  const ShaderProgram& lines() {
    if (!lines_)
      lines_ = std::make_unique<ShaderProgram>(
          "lines",
          std::vector<ShaderStage>{{GL_VERTEX_SHADER, {"tables.glsl", "lines.vert"}},
                                   {GL_FRAGMENT_SHADER, {"lines.frag"}}},
          table_defines, dialect_);
    return *lines_;
  }
  const ShaderProgram& cubes() {
    if (!cubes_)
      cubes_ = std::make_unique<ShaderProgram>(
          "cubes",
          std::vector<ShaderStage>{{GL_VERTEX_SHADER, {"cubes.vert"}},
                                   {GL_FRAGMENT_SHADER, {"lighting.glsl", "cubes.frag"}}},
          std::string(), dialect_);
    return *cubes_;
  }

 private:
  GlslDialect dialect_;
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

Renderer::Renderer(GlslDialect dialect) : programs_(std::make_unique<Programs>(dialect)) {}

Renderer::~Renderer() = default;

void Renderer::begin(const Frame& frame, const glm::vec4& background) const {
  glViewport(frame.origin.x, frame.origin.y, frame.size.x, frame.size.y);
  glEnable(GL_SCISSOR_TEST);
  glScissor(frame.origin.x, frame.origin.y, frame.size.x, frame.size.y);
  glClearColor(background.r, background.g, background.b, background.a);
  glDepthMask(GL_TRUE);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
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
    glBindTexture(GL_TEXTURE_2D, mesh.face_color_texture());
    p.set("face_colors", 0);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, mesh.face_flag_texture());
    p.set("face_flags", 1);
    glActiveTexture(GL_TEXTURE2);
    glBindTexture(GL_TEXTURE_2D, mesh.face_normal_texture());
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
    glDrawElements(GL_TRIANGLES, mesh.triangle_index_count(), GL_UNSIGNED_INT, nullptr);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_CULL_FACE);
  }
  if (settings.draws_wireframe)
    draw_segments(mesh.edges(mesh.all_edges()), frame, settings.wire_color, settings.wire_width);
  if (settings.draws_borders)
    draw_segments(mesh.edges(mesh.border_edges()), frame, settings.border_color, settings.highlight_width);
  if (settings.draws_mobius_edges)
    draw_segments(mesh.edges(mesh.mobius_edges()), frame, settings.mobius_color, settings.highlight_width);
  glBindVertexArray(0);
}

void Renderer::draw_segments(const SegmentSource& segments, const Frame& frame, const glm::vec4& color,
                             float width) const {
  if (segments.range.count == 0) return;
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
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, segments.points);
  p.set("points", 0);
  glBindVertexArray(segments.vao);
  // GLES has no base instance: the ends attribute starts at the range's first segment.
  glBindBuffer(GL_ARRAY_BUFFER, segments.ends);
  glVertexAttribIPointer(
      0, 2, GL_UNSIGNED_INT, 0,
      reinterpret_cast<void*>(std::size_t(segments.range.first) * 2 * sizeof(std::uint32_t)));
  // Sets without their own colours read this constant for the colour attribute: the uniform wins.
  glVertexAttrib4f(1, 0.0f, 0.0f, 0.0f, 0.0f);
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(segments.range.count));
  glBindVertexArray(0);
  if (is_translucent) glDisable(GL_BLEND);
}

void Renderer::draw_lines(const LineSet& lines, const Frame& frame, const glm::vec4& color,
                          float width) const {
  draw_segments(lines.segments(), frame, color, width);
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
