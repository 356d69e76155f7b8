#pragma once

#include "nome/scene/piece.hpp"

namespace nome::scene {

// Möbius strip: a band around the circle of the given radius in z = 0, `segs` quads around and `cuts` across
// a width of radius/2, its cross-section turning by twists*180 degrees once around (odd: single-sided).
// Vertices v{i}_{j} (ring i around, j across), faces f{i}_{j}.
struct MobiusStripParams {
  double radius = 1;
  int twists = 1, cuts = 1, segs = 24;
};
Piece mobius_strip(const MobiusStripParams& p);

}  // namespace nome::scene
