#pragma once

#include <cstdint>
#include <limits>

#include <glm/vec3.hpp>

namespace nome {

// 32-bit ids into contiguous arrays; `no_index` marks an absent element (a boundary edge's missing face).
using Index = std::uint32_t;
inline constexpr Index no_index = std::numeric_limits<Index>::max();

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
