#pragma once

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "render/scene_lights.hpp"

namespace nome::render {

// How back faces show (polyscope's BackFacePolicy): `different` is how a one-sided surface shows itself.
enum class BackFacePolicy { same, different, cull };

// `automatic` shades a subdivision surface smooth and faces as made (generators, meshes, files) flat, one
// normal per face, as JIPCAD and most modellers draw a mesh the user has not smoothed: flat caps stay
// flat and a coarse surface shows its facets rather than a hammered look.
enum class Shading { automatic, smooth, flat };

// What `automatic` means for a result that is, or is not, a subdivision surface.
inline Shading shown_shading(Shading chosen, bool is_smoothed) {
  if (chosen != Shading::automatic) return chosen;
  return is_smoothed ? Shading::smooth : Shading::flat;
}

// Everything the viewer's View menu and `nome render`'s options change; one struct so the window and
// the PNG agree for the same settings.
struct DisplaySettings {
  Shading shading = Shading::automatic;
  BackFacePolicy back_faces = BackFacePolicy::different;
  bool draws_faces = true;
  bool draws_wireframe = false;
  bool draws_mobius_edges = false;
  bool draws_borders = false;
  bool uses_face_colors = true;
  // A section: the faces on the positive side of the plane (a, b, c, d: a x + b y + c z + d > 0) are cut
  // away; all zero shows everything. On a closed solid (`fills_section`) the inside seen through the cut
  // is painted flat in section_color, so the wall reads as a band.
  glm::vec4 section_plane{0.0f};
  bool fills_section = false;
  glm::vec3 section_color{0.86f, 0.16f, 0.20f};

  glm::vec3 front_color{0.80f, 0.62f, 0.25f};  // warm gold
  glm::vec3 back_color{0.25f, 0.45f, 0.80f};   // blue: the other side
  glm::vec3 selection_color{0.95f, 0.25f, 0.20f};
  glm::vec3 sharp_color{0.10f, 0.85f, 0.95f};  // cyan: edges marked sharp
  glm::vec3 rim_color{0.05f, 0.45f, 0.55f};    // teal: polylines (rim lines) and their vertices
  glm::vec4 wire_color{0.08f, 0.08f, 0.10f, 1.0f};
  glm::vec4 mobius_color{0.85f, 0.10f, 0.55f, 1.0f};
  glm::vec4 border_color{0.05f, 0.60f, 0.30f, 1.0f};
  glm::vec4 background{1.0f, 1.0f, 1.0f, 1.0f};
  SceneLights lights;             // the file's placed lights; unused: lights fixed to the camera
  bool uses_scene_lights = true;  // the viewer's switch: off, its own lights whatever the file places

  // Widths in pixels at the reference resolution; the renderer scales them with the picture's height
  // (Renderer::Frame::pixel_scale) so a large render looks like a small one, only sharper.
  float wire_width = 1.0f;
  float highlight_width = 3.0f;
};

// JIPCAD's colours for users who compare pictures: front orange (250, 166, 25), back dark grey.
inline void use_jipcad_palette(DisplaySettings& settings) {
  settings.front_color = glm::vec3(250.0f, 166.0f, 25.0f) / 255.0f;
  settings.back_color = glm::vec3(0.3f);
  settings.back_faces = BackFacePolicy::different;
}

}  // namespace nome::render
