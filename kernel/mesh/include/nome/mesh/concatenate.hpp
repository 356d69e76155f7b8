#pragma once

#include <span>

#include "nome/mesh/mesh.hpp"

namespace nome {

// The parts side by side as one soup: vertex and face ids offset part by part, names, colours and
// sharp marks kept as append_soup keeps them.
PolygonSoup concatenate(std::span<const Mesh> parts);

}  // namespace nome
