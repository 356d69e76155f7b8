// JIPCAD's `mobiusstrip NAME (radius twists cuts segs) endmobiusstrip`: radius is the band's width, cuts
// split it into parallel bands.
#include <array>
#include <cmath>
#include <numbers>

#include "nome/scene/generators/mobius_strip.hpp"
#include "scene/generators/generator_support.hpp"

namespace nome::scene {

Piece cut_mobius_strip(const MobiusStripParams& p) {
  require(p.segs >= 3 && p.cuts >= 0 && p.twists >= 0 && p.radius > 0,
          "cut_mobius_strip: needs segs >= 3, cuts >= 0, twists >= 0, radius > 0");
  Piece piece;
  const int strips = 2 * p.cuts + 1;  // bands at the even strips, gaps at the odd ones
  const int across = strips + 1;
  for (int i = 0; i < p.segs; ++i) {
    const double around = 2 * std::numbers::pi * i / p.segs;
    const double turn = std::numbers::pi * p.twists * i / p.segs;
    const Vec3 radial{std::cos(around), std::sin(around), 0};
    const Vec3 across_dir = std::cos(turn) * radial + std::sin(turn) * Vec3(0, 0, 1);
    for (int j = 0; j < across; ++j) {
      const double t = p.radius * (double(j) / strips - 0.5);
      piece.add_vertex(radial + t * across_dir, "v" + std::to_string(i) + "_" + std::to_string(j));
    }
  }
  // After a full turn the cross-section has turned by twists*180 degrees: odd twists reverse it.
  auto vertex = [&](int i, int j) {
    if (i == p.segs) {
      i = 0;
      if (p.twists % 2 == 1) j = strips - j;
    }
    return Index(i * across + j);
  };
  for (int i = 0; i < p.segs; ++i)
    for (int k = 0; k <= p.cuts; ++k) {
      const int j = 2 * k;
      const std::array<Index, 4> quad{vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j + 1)};
      piece.add_face(quad, "f" + std::to_string(i) + "_" + std::to_string(k));
    }
  return piece;
}

}  // namespace nome::scene
