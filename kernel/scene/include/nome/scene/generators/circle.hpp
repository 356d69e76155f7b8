#pragma once

#include "nome/scene/piece.hpp"

namespace nome::scene {

// Circle (NOME 2.x): a closed rim line of n vertices c0.. of radius r in the plane z = 0.
Piece circle(int n, double r);

}  // namespace nome::scene
