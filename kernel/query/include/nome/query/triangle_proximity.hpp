#pragma once

#include <array>

#include "nome/mesh/types.hpp"

namespace nome {

using Triangle = std::array<Vec3, 3>;

// The segment where two triangles cross (from == to when they meet at one point).
struct CrossingSegment {
  Vec3 from{0.0}, to{0.0};
};

// Whether two triangles cross, and where: each triangle's sides are cut with the other's plane and
// the cut points kept when they lie in the other triangle (Möller 1997's interval idea, written with
// plane-side signs). Coplanar pairs count as not crossing: on a surface they are touching sheets, which
// the near-miss test measures instead.
bool triangles_cross(const Triangle& a, const Triangle& b, CrossingSegment& segment);

// The point of triangle t nearest to p (Ericson, Real-Time Collision Detection, 5.1.5).
Vec3 closest_point_on_triangle(const Vec3& p, const Triangle& t);

}  // namespace nome
