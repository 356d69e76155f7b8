#pragma once

#include "nome/scene/piece.hpp"

namespace nome::scene {

// Torus (JIPCAD): the circle of radius `minor_radius`, from phi_min to phi_max degrees (0 outwards, 90 up),
// swept around the z axis at distance `major_radius` from theta = 0 (+x) to theta_max. Vertices v{i}_{j}
// (theta i, phi j), faces f{i}_{j} pointing outwards; a whole turn either way shares its seam, so the
// whole torus is closed with chi 0 and a half torus (theta_max = 180) is an annulus with two borders.
struct TorusParams {
  double major_radius = 2, minor_radius = 0.5;
  double theta_max = 360, phi_min = 0, phi_max = 360;
  int theta_segs = 16, phi_segs = 8;
};
Piece torus(const TorusParams& p);

}  // namespace nome::scene
