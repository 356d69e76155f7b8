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

// Möbius strip in JIPCAD's meaning of the same four arguments: a band around the unit circle in z = 0,
// `radius` wide, cut `cuts` times along its length into cuts + 1 bands with equal gaps between them (2 cuts
// + 1 equal strips across), the cross-section turning by twists*180 degrees once around; `segs` segments
// around. Vertices v{i}_{j} (ring i, j = 0 .. 2 cuts + 1 across), faces f{i}_{k} (band k). The seam is
// joined by position: with odd twists strip j meets strip 2 cuts - j, so the middle band is one-sided.
Piece cut_mobius_strip(const MobiusStripParams& p);

}  // namespace nome::scene
