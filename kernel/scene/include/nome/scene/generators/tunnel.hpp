#pragma once

#include "nome/scene/piece.hpp"

namespace nome::scene {

// Tunnel: two funnels sharing the base circle bc (radius ro, z = 0): the high circle hc at z = h, radius
// ro*(1+ratio) (faces hf0..), and the low circle lc at z = -h_low, radius ro*(1+ratio_low) (faces lf0..).
// The symmetric tunnel of the report has ratio_low = ratio and h_low = h.
struct TunnelParams {
  int n = 8;
  double ro = 1, ratio = 0, h = 1, ratio_low = 0, h_low = 1;
};
Piece tunnel(const TunnelParams& p);

}  // namespace nome::scene
