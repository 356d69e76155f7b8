#pragma once

#include <cstdint>
#include <limits>

namespace nome {

// 32-bit ids into contiguous arrays; `no_index` marks an absent element (a boundary edge's missing face).
using Index = std::uint32_t;
inline constexpr Index no_index = std::numeric_limits<Index>::max();

}  // namespace nome
