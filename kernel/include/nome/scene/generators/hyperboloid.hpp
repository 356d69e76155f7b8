#pragma once

#include "nome/scene/piece.hpp"

namespace nome::scene {

enum class HyperboloidSheet { one, paraboloid, two };

// Hyperboloid (JIPCAD, after NOME3): around the z axis, with radius scale `a` and height scale `c`, the
// hyperbolic parameter u up to u_max in `u_segs` segments, `v_segs` around. One sheet:
// (a cosh u cos v, a cosh u sin v, c sinh u), u in [-u_max, u_max], an annulus. Paraboloid:
// (a u cos v, a u sin v, c u^2), u in [0, u_max], a disk around the pole `apex`. Two sheets:
// (a sinh u cos v, a sinh u sin v, +-c cosh u), u in [0, u_max], two disks (names `top_...`, `bottom_...`,
// poles `top_apex`, `bottom_apex`). Vertices v{i}_{j} (around i, along j), faces f{i}_{j} pointing away
// from the side the surface curves around.
struct HyperboloidParams {
  double a = 1, c = 1, u_max = 1;
  int u_segs = 8, v_segs = 16;
  HyperboloidSheet sheet = HyperboloidSheet::one;
};
Piece hyperboloid(const HyperboloidParams& p);

}  // namespace nome::scene
