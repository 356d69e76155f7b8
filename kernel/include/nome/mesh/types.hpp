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

// The colour of a face that has none, where faces beside it have one (parts of one soup or mesh).
inline constexpr Color default_face_color{0.75f, 0.75f, 0.75f};

// OpenSubdiv's infinite sharpness: a crease or corner weight from 10 up never decays.
inline constexpr float infinite_sharpness = 10.0f;

}  // namespace nome
