#pragma once

#include <algorithm>

#include <glm/geometric.hpp>

#include "nome/mesh/types.hpp"

namespace nome {

// Face f's unit normal by Newell, with the longest side in the same walk round the face; zero when the
// face is degenerate: its area small against the squared length of its longest side (a relative
// threshold), or all its vertices at one point. Shared by the one-thread and threaded normal passes so
// that both give the same bits.
inline Vec3 unit_face_normal(const Vec3* p, const Index* corners, Index begin, Index end) {
  Vec3 n(0.0);
  double extent_squared = 0.0;
  const Vec3* a = &p[corners[end - 1]];
  for (Index c = begin; c < end; ++c) {
    const Vec3& b = p[corners[c]];
    n += Vec3((a->y - b.y) * (a->z + b.z), (a->z - b.z) * (a->x + b.x), (a->x - b.x) * (a->y + b.y));
    const Vec3 side = b - *a;
    extent_squared = std::max(extent_squared, glm::dot(side, side));
    a = &b;
  }
  const double len = glm::length(n);
  if (!(len > 1e-14 * extent_squared) || extent_squared == 0.0) return Vec3(0.0);
  return n * (1.0 / len);
}

}  // namespace nome
