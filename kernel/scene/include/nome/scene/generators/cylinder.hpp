#pragma once

#include "nome/scene/piece.hpp"

namespace nome::scene {

// Cylinder and cone (JIPCAD): the mantle between the circle of radius `radius` at z = 0 and the circle of
// radius `top_radius` at z = height, from theta = 0 (+x) to theta_max degrees in `theta_segs` segments
// (vertices v{i}_0 below, v{i}_1 above; a top radius of 0 is the single vertex `apex`; faces f{i}_0
// pointing outwards). The caps close the ends (faces `botcap` pointing down, `topcap` up): over a whole
// turn each is one polygon of its circle, over a wedge a pie with a centre vertex (`bottom`, `top`). A
// whole cylinder with both caps is closed with chi 2.
struct CylinderParams {
  double radius = 1, top_radius = 1, height = 1, theta_max = 360;
  int theta_segs = 16;
  bool has_bottom_cap = false, has_top_cap = false;
};
Piece cylinder(const CylinderParams& p);

}  // namespace nome::scene
