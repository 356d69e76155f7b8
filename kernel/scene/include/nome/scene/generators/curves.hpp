#pragma once

#include "nome/scene/piece.hpp"

namespace nome::scene {

// Helix (JIPCAD): the open rim line of `segs` segments (vertices v0..v{segs}) on the cylinder of radius
// `radius` around z, from angle 0 (+x) to theta_max degrees, rising `rise` per radian (z = rise * angle),
// as NOME3's helix does.
Piece helix(double radius, double rise, double theta_max, int segs);

// Spiral (JIPCAD): the open rim line of `segs` segments (vertices v0..v{segs}) of the Archimedean spiral
// in z = 0 from the origin, its radius growing by `rate` per whole turn, over `angle` degrees.
Piece spiral(double rate, double angle, int segs);

}  // namespace nome::scene
