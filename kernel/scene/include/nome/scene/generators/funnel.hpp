#pragma once

#include "nome/scene/piece.hpp"

namespace nome::scene {

// Funnel (report 6.3): the n-gon base circle of radius ro at z = 0 (vertices bc0..bc{n-1}) joined by n
// quads (f0..) to the high circle of radius ro*(1+ratio) at z = h (hc0..); vertex i at 360*i/n degrees
// from +x. Faces are oriented with their normals pointing away from the axis. The successor's files name
// the circles' vertices v1_0.. and v2_0.. (geom__Annulus0.nom's faces join them).
struct FunnelParams {
  int n = 8;
  double ro = 1, ratio = 0, h = 1;
  const char* base_names = "bc";
  const char* high_names = "hc";
};
Piece funnel(const FunnelParams& p);

}  // namespace nome::scene
