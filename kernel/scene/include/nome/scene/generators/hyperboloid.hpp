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

// The successor's (JIPCAD's) hyperboloid, `(segs a b c sheet theta)` as its Hyperboloid.cpp reads them:
// rows at the whole heights z = -c..c; one sheet (sheet 0) at (a s cos t, b s sin t, z) with
// s = sqrt(z^2 + 1), two sheets (any other sheet) with s = sqrt(z^2 - 1), the rows |z| >= 1 only (the
// rows at z = +-1 are the apexes `top_apex`, `bottom_apex`). Column i at t = i theta pi / segs, i < segs:
// theta 2 closes the ring, any other sweep stops a step short of theta pi, as JIPCAD's does. Faces turn
// from column i to i+1, then up: normals away from the axis.
struct SuccessorHyperboloidParams {
  int segs = 6;
  double a = 1, b = 1;
  int rows = 1;  // c, whole rows above z = 0
  bool is_two_sheets = false;
  double theta = 2;  // in units of pi
};
Piece successor_hyperboloid(const SuccessorHyperboloidParams& p);

}  // namespace nome::scene
