#pragma once

#include <span>

#include "nome/mesh/mesh.hpp"

namespace nome {

// The colour given to faces of uncoloured parts when other parts carry colours.
inline constexpr Color uncoloured_face_color{0.8f, 0.8f, 0.8f};

// The parts side by side as one soup: vertex and face ids offset part by part, names, colours and
// sharp marks kept (a part without names gets empty ones when another part has them).
PolygonSoup concatenate(std::span<const Mesh> parts);

}  // namespace nome
