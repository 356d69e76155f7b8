#pragma once

#include "nome/scene/piece.hpp"

namespace nome::scene {

// Funnel (report 6.3): the n-gon base circle of radius ro at z = 0 (vertices bc0..bc{n-1}) joined by n
// quads (f0..) to the high circle of radius ro*(1+ratio) at z = h (hc0..); vertex i at 360*i/n degrees
// from +x. Faces are oriented with their normals pointing away from the axis.
struct FunnelParams {
  int n = 8;
  double ro = 1, ratio = 0, h = 1;
};
Piece funnel(const FunnelParams& p);

// Tunnel: two funnels sharing the base circle bc (radius ro, z = 0): the high circle hc at z = h, radius
// ro*(1+ratio) (faces hf0..), and the low circle lc at z = -h_low, radius ro*(1+ratio_low) (faces lf0..).
// The symmetric tunnel of the report has ratio_low = ratio and h_low = h.
struct TunnelParams {
  int n = 8;
  double ro = 1, ratio = 0, h = 1, ratio_low = 0, h_low = 1;
};
Piece tunnel(const TunnelParams& p);

// Circle (NOME 2.x): a closed rim line of n vertices c0.. of radius r in the plane z = 0.
Piece circle(int n, double r);

// Möbius strip: a band around the circle of the given radius in z = 0, `segs` quads around and `cuts` across
// a width of radius/2, its cross-section turning by twists*180 degrees once around (odd: single-sided).
// Vertices v{i}_{j} (ring i around, j across), faces f{i}_{j}.
struct MobiusStripParams {
  double radius = 1;
  int twists = 1, cuts = 1, segs = 24;
};
Piece mobius_strip(const MobiusStripParams& p);

}  // namespace nome::scene
