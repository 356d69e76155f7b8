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

}  // namespace nome
