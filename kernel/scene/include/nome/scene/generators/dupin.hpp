#pragma once

#include "nome/scene/piece.hpp"

namespace nome::scene {

// Dupin cyclide (JIPCAD, after NOME3): with D(u, v) = a - c cos u cos v,
//   x = (d (c - a cos u cos v) + b^2 cos u) / D,  y = b sin u (a - d cos v) / D,
//   z = b sin v (c cos u - d) / D,
// u over [0, u_max] and v over [0, v_max] (u_max, v_max in radians here), each in `segs` segments. A whole
// turn either way shares its seam: the whole cyclide is closed with chi 0 (b^2 = a^2 - c^2 gives the
// classical ring cyclide). Vertices v{i}_{j}, faces f{i}_{j}, consistently oriented.
struct DupinParams {
  double a = 1, b = 0.98, c = 0.2, d = 0.5;
  double u_max = 6.283185307179586, v_max = 6.283185307179586;
  int segs = 24;
};
Piece dupin(const DupinParams& p);

}  // namespace nome::scene
