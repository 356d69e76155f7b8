#pragma once

#include <glm/vec3.hpp>

#include "nome/index.hpp"

namespace nome {

using Vec3 = glm::dvec3;
using Color = glm::vec3;

// The colour of a face that has none, where faces beside it have one (parts of one soup or mesh): no colour
// (outside 0..1, so no surface can name it), shown in the viewer's front colour like an uncoloured mesh.
inline constexpr Color no_face_color{-1.0f, -1.0f, -1.0f};
// What a file that colours every face gets for a face without a colour: a light grey.
inline Color written_face_color(const Color& c) {
  return c.r < 0.0f ? Color(0.75f) : c;
}

// OpenSubdiv's infinite sharpness: a crease or corner weight from 10 up never decays.
inline constexpr float infinite_sharpness = 10.0f;

}  // namespace nome
