#pragma once

#include "nome/scene/piece.hpp"

namespace nome::scene {

// Torus knot (JIPCAD): the curve on the torus of radii `major_radius` (around z) and `minor_radius` that
// passes `symmetry` times through the hole while it goes `turns` times around the z axis (the knot's
// rotational symmetry is |symmetry|; negative values mirror it), swept by a circle of radius
// `tube_radius`. A closed tube of `sweep_segs` x `circle_segs` quads (vertices v{i}_{j}: i along, j
// around; faces f{i}_{j} pointing outwards), closed with chi 0. A tube radius of 0 gives the curve
// alone, as a closed rim line. symmetry and turns must be coprime (otherwise the curve is a link that
// runs over itself).
struct TorusKnotParams {
  int symmetry = 3, turns = 2;
  double major_radius = 2, minor_radius = 1, tube_radius = 0.2;
  int circle_segs = 8, sweep_segs = 64;
};
Piece torus_knot(const TorusKnotParams& p);

}  // namespace nome::scene
